// 2D line tests (the book's chapter 5, "line intersection"): whether a segment meets a circle, a
// rectangle or an oriented rectangle, and 2D raycasts against them with a hit record.
//
// - intersects(segment, shape) (either order): closed; the segment meets the shape within the
//   tolerance (a segment that grazes a corner or runs along an edge meets it).
// - raycast(ray, shape): the first point of the shape along the ray, as RayHit2T {t, point,
//   normal, inside}, or nothing. The ray's direction must be unit length (validate(Ray2T)), so t
//   is a distance.
//   * A ray starting in the shape (within the tolerance) hits at t = 0 with point = origin,
//     inside = true and normal = -direction (there is no surface to report; the normal still
//     faces the ray).
//   * Otherwise the hit is where the ray enters, t > 0, with the outward unit normal of the
//     surface there (it faces the ray: normal . direction <= 0, = 0 for a grazing hit). A ray
//     exactly through a corner of a rectangle (both slabs entered at the same t) reports the face
//     of the x slab (local x for the oriented one).
//   * The rectangle tests are slab tests written for the hard cases: a zero direction component
//     takes no division (the ray is inside or outside that slab for all t, including an origin
//     exactly on a slab line), and the slabs are widened by kGeometry2dTolerance times the largest
//     coordinate of the rectangle relative to the origin (in its frame), so a ray along an edge,
//     which rounding puts a hair outside an oriented rectangle, still hits it. The reported t is
//     computed from the entered face itself, not the widened one. "Inside" means inside the
//     widened rectangle.
//
// Where the book's code (Geometry2D.cpp, Geometry3D.cpp) differs:
// - LineRectangle replaces the reciprocal of a zero direction component by 0, so a horizontal or
//   vertical segment that crosses a rectangle is reported as missing it unless one of its ends is
//   inside (e.g. (-1, 0.5)-(3, 0.5) against [0, 2] x [0, 1]).
// - LineCircle rejects a segment whose closest point on the infinite line lies beyond an end,
//   even when that end is inside the circle ((-3, 0)-(-0.5, 0) against the unit circle), and uses
//   `<`, so touching misses.
// - The 3D sphere raycast returns the exit point for an origin inside, and a negative t (not a
//   miss) for a sphere behind the ray.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "simdphys/geometry2d/point_tests.hpp"
#include "simdphys/geometry2d/primitives.hpp"

namespace simdphys {

template <class T>
struct RayHit2T {
  T t;             // distance along the ray (0 for an origin inside)
  Vec2<T> point;   // origin + t direction
  Vec2<T> normal;  // unit, facing the ray
  bool inside;     // the origin is in the shape
};
using RayHit2 = RayHit2T<float>;
using RayHit2d = RayHit2T<double>;

// ---- segments --------------------------------------------------------------------------------
// (shape, segment), the other order: primitives.hpp's intersects(a, b).

// The closest point of the segment to the center is within the radius, within the tolerance
// times max(radius, |center - start|, length).
template <class T>
bool intersects(const Segment2T<T>& s, const CircleT<T>& c);

// Slab test on t in [0, 1], relative to the start.
template <class T>
bool intersects(const Segment2T<T>& s, const RectT<T>& r);

// Slab test in the oriented rectangle's frame.
template <class T>
bool intersects(const Segment2T<T>& s, const OrientedRectT<T>& b);

// ---- raycasts --------------------------------------------------------------------------------

// Solves |m + t d| = r with m = origin - center from the perpendicular distance of the line to the
// center (not b^2 - c, which cancels for distant origins). A hit within the tolerance times
// (radius + |m|) of the circle counts (a grazing ray hits at its closest approach).
template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const CircleT<T>& c);

template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const RectT<T>& r);

template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const OrientedRectT<T>& b);

}  // namespace simdphys

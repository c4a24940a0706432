// 2D shape-versus-shape tests (the book's chapter 5) and 2D contact manifolds: circle-circle,
// circle-rectangle, circle-oriented rectangle, rectangle-rectangle, rectangle-oriented rectangle
// and oriented-oriented rectangle, each in both argument orders.
//
// - intersects(a, b): closed; shapes that touch intersect. Rectangle-rectangle is exact
//   (comparisons only); the others allow a gap of up to kGeometry2dTolerance * scale (stated per
//   function). Rectangle-oriented rectangle and oriented-oriented rectangle use the separating
//   axis theorem (SAT) on the four face normals, which for two rectangles are all the candidate
//   axes (parallel edges give the same axis twice, which is harmless).
// - collide(a, b): a Manifold2T. When the shapes intersect (colliding == intersects(a, b), by
//   construction) it holds the unit normal from a to b, the penetration depth (moving b by
//   depth * normal leaves the shapes touching: the minimum translation) and one or two contact
//   points, each halfway between the two surfaces along the normal (Box2D's convention).
//   Rectangle pairs get two contact points when edges overlap, by clipping the incident edge
//   against the side planes of the reference face (as Box2D's b2CollidePolygons; written anew).
// - Symmetry, by construction: intersects(b, a) == intersects(a, b), and collide(b, a) is
//   collide(a, b) with the normal negated, bit for bit. For two shapes of the same type both
//   orders compute on the lexicographically smaller shape first, so even ties resolve the same way.
//
// Inputs are not validated: they are assumed valid and within the supported range of math.hpp
// (what validate() accepts), where no computation overflows.
//
// Degenerate answers (all documented and tested):
// - Concentric circles: normal +x from the lexicographically smaller circle (so -x when that one
//   is b), depth rA + rB.
// - A circle whose center is inside a rectangle: the normal pushes the rectangle out through the
//   face nearest the center (ties: -x face, +x face, -y face, +y face, first wins), depth = radius
//   + distance from the center to that face.
// - Zero-size shapes are points and collide as such; coincident equal points: depth 0, normal +x
//   (circles and rectangles), for oriented rectangles the reference face's normal (their local +x).
// - Identical shapes (a == b field for field) give the same manifold in both orders: there the
//   normal cannot be antisymmetric.
// - Rectangle pairs whose two candidate contacts coincide (within the tolerance) report one.
//
// Where the book's code (Geometry2D.cpp) differs: its interval tests are closed too, but it
// compares projections of rotated corners exactly, so oriented rectangles that touch can be
// reported apart by a rounding (cos(pi/2) is not 0 in float); its rotations are in degrees;
// OrientedRectangleOrientedRectangle moves the second box into the first's frame and reuses the
// rectangle-oriented rectangle test (correct, but the frame change adds a rounding). It has no
// 2D manifolds.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "simdphys/geometry2d/point_tests.hpp"
#include "simdphys/geometry2d/primitives.hpp"

namespace simdphys {

template <class T>
struct Manifold2T {
  bool colliding = false;
  Vec2<T> normal = Vec2<T>::Zero();  // unit, from a to b (zero when not colliding)
  T depth = 0;                       // >= 0; moving b by depth * normal makes the shapes touch
  int count = 0;                     // contact points: 0 (not colliding), 1 or 2
  std::array<Vec2<T>, 2> contacts{Vec2<T>::Zero(), Vec2<T>::Zero()};
};
using Manifold2 = Manifold2T<float>;
using Manifold2d = Manifold2T<double>;

// The manifold seen from the other shape: normal negated, the rest unchanged.
template <class T>
Manifold2T<T> flipped(Manifold2T<T> m);

// ---- intersection tests ----------------------------------------------------------------------
// Each pair is declared in one order; the other order is primitives.hpp's intersects(a, b).

// |cb - ca| <= ra + rb within the tolerance times max(|cb - ca|, ra + rb).
template <class T>
bool intersects(const CircleT<T>& a, const CircleT<T>& b);

// Distance from the center to the rectangle <= radius, within the tolerance times max(distance,
// radius); the closest point is an exact clamp. A zero-radius circle is an exact point test.
template <class T>
bool intersects(const CircleT<T>& c, const RectT<T>& r);

// As circle-rectangle in the rectangle's frame, within the tolerance times radius + |center
// offset| + the larger half extent (the rotation into the frame rounds by 2 eps |offset|).
template <class T>
bool intersects(const CircleT<T>& c, const OrientedRectT<T>& b);

// Two rectangles: intersects(RectT, RectT) of primitives.hpp, closed interval overlap on both
// axes, exact.

// SAT in a frame centered on the oriented rectangle, within the tolerance times |offset of the
// centers| + the sum of all half extents.
template <class T>
bool intersects(const RectT<T>& r, const OrientedRectT<T>& b);

// SAT in a frame centered on the first rectangle (of the canonical order), same tolerance.
template <class T>
bool intersects(const OrientedRectT<T>& a, const OrientedRectT<T>& b);

// ---- manifolds -------------------------------------------------------------------------------
// Each pair is declared in one order (that of intersects); the other order is the manifold of
// that one, flipped (below).

// Normal along the centers (+x if they coincide), depth ra + rb - distance, one contact halfway
// between the two surfaces.
template <class T>
Manifold2T<T> collide(const CircleT<T>& a, const CircleT<T>& b);

// Normal from the center towards the closest rectangle point, or, with the center inside, out of
// the nearest face (see the header comment); one contact halfway between the surfaces.
template <class T>
Manifold2T<T> collide(const CircleT<T>& c, const RectT<T>& r);

// As circle-rectangle, in the oriented rectangle's frame.
template <class T>
Manifold2T<T> collide(const CircleT<T>& c, const OrientedRectT<T>& b);

// Exact interval arithmetic: the depth is the smallest of the four pushes (b out through +x, -x,
// +y, -y; ties in that order), the contacts are the ends of the overlap of the faces, halfway
// between them (one if that overlap is a point).
template <class T>
Manifold2T<T> collide(const RectT<T>& a, const RectT<T>& b);

// SAT with clipping, in a frame centered on the oriented rectangle.
template <class T>
Manifold2T<T> collide(const RectT<T>& r, const OrientedRectT<T>& b);

// SAT with clipping, in a frame centered on the first rectangle of the canonical order.
template <class T>
Manifold2T<T> collide(const OrientedRectT<T>& a, const OrientedRectT<T>& b);

// A pair in the other order than its collide is written in: that manifold seen from b.
template <class A, class B>
requires detail::SwappedPair<A, B>
auto collide(const A& a, const B& b) { return flipped(collide(b, a)); }

}  // namespace simdphys

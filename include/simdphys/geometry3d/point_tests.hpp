// Point tests of the book's chapter 8 and the triangle recipes of chapter 11: whether a shape
// contains a point, the point of a shape closest to a point, barycentric coordinates, and the
// closest points of two segments.
//
// Conventions (docs/geometry.md restates them):
// - Shapes are closed and solid: a sphere, box or OBB contains its inside and its surface, and the
//   closest point of a solid to a point inside it is the point itself.
// - Segments, rays, planes and triangles have no volume, so "contains" needs a tolerance: a point
//   counts as on one when its distance from it is at most kGeometryTolerance<T> * scale +
//   eps * max|p_i|. The scale bounds the magnitudes the rounding errors grow with (stated per
//   function: the shape's size and the point's offset from it; for a plane, |p| + |d|, since
//   n.p + d is computed in absolute coordinates). The second term is the rounding of p's own
//   coordinates (each is rounded by up to eps/2 of itself): a computed point, such as a closest
//   point, is only that precise, about one ulp of its largest coordinate. The solids use the same
//   rule, so contains(s, closestPoint(s, p)) holds (tested); the AABB alone is tested exactly (no
//   arithmetic, only comparisons; its closest point, a clamp, is exact too).
// - Differences are taken relative to a point of the shape before anything is multiplied, so a
//   shape of size 1e-2 at coordinates of 1e5 is handled at the precision of its size, not of its
//   position (in float an ulp of 1e5 is 0.0078). A point given at large coordinates is of course
//   only as precise as its own representation.
// - Degenerate but finite shapes have defined answers: a zero-radius sphere and a zero-size box
//   are points, a zero-length segment is a point, a triangle whose vertices are collinear (within
//   the tolerance) is the segment of its longest edge, or a point if they coincide.
// Queries do not validate; inputs are assumed valid and within the supported range of math.hpp
// (coordinates and sizes up to kMaxCoordinate = 1e18, a shape's center +- extent included: what
// validate() accepts), where no computation overflows. Outside it answers are unspecified.
//
// Where the book's code (Code/Geometry3D.cpp of the book's repository) is wrong:
// - PointInSphere and the sphere tests use `<`: a point on the surface is outside, touching
//   shapes do not intersect. Here everything is closed.
// - ClosestPoint(Sphere) normalises point - center: NaN for the center, and a point inside is
//   moved to the surface although PointInSphere calls it inside (the AABB and OBB versions leave
//   inside points alone). Here the sphere is solid like the boxes.
// - ClosestPoint(AABB) clamps y and z against min.x and max.x (a typo): the result can be
//   outside the box.
// - PointOnRay compares the cosine of the angle at the origin with 1 within FLT_EPSILON: a point
//   1000 along the ray and 0.2 off it counts as on it. PointOnLine compares the squared distance
//   with 0 within FLT_EPSILON, an absolute 3.4e-4 whatever the size.
// - ClosestPoint(Triangle) picks the closest of the three edges with strict `<` comparisons:
//   in the vertex region of b, edges ab and bc tie (both give b) and it returns the point of ca.
//   It and Barycentric divide by zero for a degenerate triangle.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/point_tests.hpp"

namespace simdphys {

// The tolerance of the point tests and intersection tests is kGeometryTolerance (math.hpp): a
// distance up to kGeometryTolerance * scale counts as zero.

// ---- containment ----------------------------------------------------------------------------

// Closed ball: |p - c| <= r, within the tolerance (scale max(|p - c|, r)).
template <class T>
bool contains(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point);

// The box's containment and the closest points of the sphere, the box and the segment are shared
// with 2D: simdphys/point_tests.hpp.

// Closed oriented box: |axes^T (p - c)| <= halfExtents on every axis, within the tolerance
// (scale |p - c| + the largest half extent).
template <class T>
bool contains(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);

// On the plane: |n.p + d| within the tolerance (scale |p| + |d|, the magnitudes n.p + d is
// computed from: its rounding error is below 2 eps (|p| + |d|) for a unit normal).
template <class T>
bool contains(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point);

// On the segment: distance to it within the tolerance (scale max(|p - start|, length)). A
// zero-length segment contains only its point.
template <class T>
bool contains(const SegmentT<T>& segment, const detail::NoDeduce<Vec3<T>>& point);

// On the ray: distance to it within the tolerance (scale |p - origin|, so the allowed distance
// grows along the ray as the rounding of its direction does; the book's angle test is much
// looser, see above).
template <class T>
bool contains(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point);

// On the triangle (closed: its edges and vertices included): distance to it within the tolerance
// (scale max(|p - a|, longest edge)). The closest point is accurate to about 8 eps (L + |p - a|)
// for p within the tolerance of the triangle, whatever the triangle's angles (closestOnTriangle),
// and 16 eps max(|p - a|, L) >= 8 eps (L + |p - a|), so a point of the triangle is never
// rejected; the eps |p| term covers the rounding of p's own coordinates. A degenerate triangle
// contains the points of its longest edge (its third vertex is within 16 eps L of that edge).
template <class T>
bool contains(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point);

// ---- closest points -------------------------------------------------------------------------

// p clamped to the box in its local frame; a point inside is returned unchanged (exactly).
template <class T>
Vec3<T> closestPoint(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);

// The orthogonal projection of p onto the plane.
template <class T>
Vec3<T> closestPoint(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point);

// origin + t direction with t = max(0, (p - origin).direction): points behind the origin give it.
template <class T>
Vec3<T> closestPoint(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point);

// Ericson's region method (5.1.5), not the book's, which can return a point of the wrong edge
// (see above), with the face point projected onto the plane: accurate to about 8 eps (L + |p - a|)
// on thin triangles too (see closestOnTriangle). A degenerate triangle gives the closest point
// of its longest edge.
template <class T>
Vec3<T> closestPoint(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point);

// ---- barycentric coordinates ----------------------------------------------------------------

// The barycentric coordinates (u, v, w) of p in the triangle: u a + v b + w c is the orthogonal
// projection of p onto the triangle's plane, u + v + w = 1 (to rounding), and p's projection is
// inside (or on the edges) when all three are >= 0 (to rounding). Each weight is a ratio of signed
// areas, n.(edge x offset) / |n|^2 with n = (b - a) x (c - a), which is accurate for thin triangles
// where the book's and the usual Gram-matrix form (d00 d11 - d01^2) lose digits to cancellation.
//
// Degenerate triangle (collinear vertices, within the tolerance of degenerateTriangle): the
// coordinates of p's projection onto the line of the longest edge, (1 - t, t) on that edge's two
// vertices and 0 on the third (unclamped: both are in [0, 1] for the points of the segment; the
// third vertex, lying between the two, gets the weights of its position on the edge, not
// (0, 0, 1)). All three vertices coinciding: (1, 0, 0).
//
// Accuracy: a weight is within about 16 eps (|opposite edge| (L + |p - a| + H L^2 / |n|) +
// |weight| s L) / |n| (H the distance of p off the plane, s the shortest edge): its condition
// number in p, the plane's tilt, and the uncertainty of |n| on a flat cap (TriangleFrame). On a
// thin triangle the weights of the two vertices at the ends of a short edge are thus less precise
// than the point they describe. Computed with the triangle scaled by a power of two
// (TriangleFrame), so that |n|^2 ~ L^4 cannot overflow (edges of 1e10 in float) or underflow.
template <class T>
Vec3<T> barycentric(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point);

// ---- closest points of two segments ---------------------------------------------------------

template <class T>
struct SegmentClosestPointsT {
  Vec3<T> first;   // on the first segment: start + s (end - start)
  Vec3<T> second;  // on the second segment: start + t (end - start)
  T s, t;          // in [0, 1]
  T distance;      // |first - second|, computed from offsets (no cancellation at large coordinates)
};
using SegmentClosestPoints = SegmentClosestPointsT<float>;

// The closest points of two segments (Ericson 5.1.9), robust for parallel and degenerate ones.
// The squared distance is a convex quadratic in (s, t) over [0, 1]^2, so its minimum is either
// the stationary point of the two lines (if it lies inside the square) or on one of the square's
// four sides, where it is the clamped closest point of one segment's endpoint on the other. All
// five candidates are evaluated and the closest kept: no case analysis that rounding can lead
// astray, and nothing to divide by zero when a segment is a point or the two are parallel.
// The stationary point is solved with cross products, s = ((P2 - P1) x d2).n / |n|^2 and
// t = ((P2 - P1) x d1).n / |n|^2 with n = d1 x d2, whose relative error is about eps / sin(angle),
// instead of the usual a e - b^2 denominator, whose error is about eps / sin^2(angle); it is
// skipped when |n| <= tolerance |d1| |d2| (parallel: the sides hold a closest pair then).
// For parallel overlapping segments, where closest pairs are not unique, the first of the
// candidates in the order (stationary, s = 0, s = 1, t = 0, t = 1) is returned.
template <class T>
SegmentClosestPointsT<T> closestPoints(const SegmentT<T>& first, const SegmentT<T>& second);

}  // namespace simdphys

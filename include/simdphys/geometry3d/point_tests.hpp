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

namespace simdphys {

// The tolerance of the point tests and intersection tests is kGeometryTolerance (math.hpp): a
// distance up to kGeometryTolerance * scale counts as zero.

namespace detail {

// The parameter in [0, 1] of the point of the segment from 0 to `d` closest to `r` (both relative
// to the segment's start); 0 for a zero-length segment (no division by zero).
template <class T>
T segmentParameter(const Vec3<T>& d, const Vec3<T>& r) {
  const T dd = d.squaredNorm();
  if (!(dd > 0)) return T(0);
  return std::clamp(r.dot(d) / dd, T(0), T(1));
}

// num / den clamped to [0, 1], and 0 when den is not positive (num >= 0 is known by the caller).
template <class T>
T unitRatio(T num, T den) {
  return den > 0 ? std::clamp(num / den, T(0), T(1)) : T(0);
}

// The tolerance of "p is on the shape" (see the header comment): the computation's rounding,
// relative to the local scale, and the rounding of p's coordinates.
template <class T>
T onShapeTolerance(T localScale, const Vec3<T>& p) {
  return kGeometryTolerance<T> * localScale +
         std::numeric_limits<T>::epsilon() * p.cwiseAbs().maxCoeff();
}

template <class T>
T longestEdgeSquared(const Vec3<T>& ab, const Vec3<T>& ac, const Vec3<T>& bc) {
  return std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
}

// A triangle is degenerate when its height over the longest edge L is at most the tolerance times
// L, |ab x ac| <= tol L^2: it is then a segment (or a point) to within the tolerance. The cross
// product is accurate to about 2 eps L^2, so an exactly collinear triangle is always degenerate.
// Compares norms, not squared norms, so that shapes of 1e-6 do not underflow in float (|n|^2
// ~ L^4 stays a normal number down to sizes of about 1e-9 in float, 1e-77 in double).
template <class T>
bool degenerateTriangle(const Vec3<T>& normal, T longestSquared) {
  return normal.norm() <= kGeometryTolerance<T> * longestSquared;
}

// The closest point of a triangle to p, as its offset from vertex a and its barycentric weights.
template <class T>
struct TriangleClosest {
  Vec3<T> offset;   // closest point - a
  Vec3<T> weights;  // (u, v, w): closest point = u a + v b + w c
};

// Degenerate triangle: the closest of the closest points of its three edges (for collinear
// vertices one of them is the longest edge, which contains the others). Ties keep the first.
template <class T>
TriangleClosest<T> closestOnDegenerateTriangle(const Vec3<T>& ab, const Vec3<T>& ac,
                                               const Vec3<T>& bc, const Vec3<T>& ap,
                                               const Vec3<T>& bp) {
  const T tab = segmentParameter(ab, ap);
  const T tac = segmentParameter(ac, ap);
  const T tbc = segmentParameter(bc, bp);
  TriangleClosest<T> best{tab * ab, Vec3<T>(1 - tab, tab, 0)};
  T bestDistance = (ap - best.offset).norm();
  const T dac = (ap - tac * ac).norm();
  if (dac < bestDistance) {
    best = {tac * ac, Vec3<T>(1 - tac, 0, tac)};
    bestDistance = dac;
  }
  if ((bp - tbc * bc).norm() < bestDistance) best = {ab + tbc * bc, Vec3<T>(0, 1 - tbc, tbc)};
  return best;
}

// Ericson, Real-Time Collision Detection 5.1.5: find the Voronoi region of p (three vertex
// regions, three edge regions, the face) from the signs of dot products, then project onto that
// feature. The region tests va, vb, vc are written as n.(edge x offset) (equal to Ericson's
// d1 d4 - d3 d2 etc. by the Binet-Cauchy identity) because products of dot products lose digits
// to cancellation on thin triangles.
template <class T>
TriangleClosest<T> closestOnTriangle(const TriangleT<T>& tri, const Vec3<T>& p) {
  const Vec3<T> ab = tri.b - tri.a, ac = tri.c - tri.a, bc = tri.c - tri.b;
  const Vec3<T> ap = p - tri.a, bp = p - tri.b;
  const Vec3<T> n = ab.cross(ac);
  if (degenerateTriangle(n, longestEdgeSquared(ab, ac, bc)))
    return closestOnDegenerateTriangle(ab, ac, bc, ap, bp);

  const T d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {Vec3<T>::Zero(), Vec3<T>(1, 0, 0)};  // vertex a
  const T d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {ab, Vec3<T>(0, 1, 0)};  // vertex b
  const Vec3<T> cp = p - tri.c;
  const T d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {ac, Vec3<T>(0, 0, 1)};  // vertex c

  const T vc = n.dot(ab.cross(ap));  // <= 0: p is beyond edge ab
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const T t = unitRatio(d1, d1 - d3);
    return {t * ab, Vec3<T>(1 - t, t, 0)};
  }
  const T vb = n.dot(ap.cross(ac));  // <= 0: beyond edge ca
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const T t = unitRatio(d2, d2 - d6);
    return {t * ac, Vec3<T>(1 - t, 0, t)};
  }
  const T va = n.dot(bc.cross(bp));  // <= 0: beyond edge bc
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const T t = unitRatio(d4 - d3, (d4 - d3) + (d5 - d6));
    return {ab + t * bc, Vec3<T>(0, 1 - t, t)};
  }
  // Face region: va, vb, vc are |n|^2 times the barycentric weights. |n|^2 is well above zero
  // here (the triangle is not degenerate).
  const T nn = n.squaredNorm();
  const T v = vb / nn, w = vc / nn;
  return {v * ab + w * ac, Vec3<T>(va / nn, v, w)};
}

}  // namespace detail

// ---- containment ----------------------------------------------------------------------------

// Closed ball: |p - c| <= r, within the tolerance (scale max(|p - c|, r)).
template <class T>
bool contains(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point) {
  const T distance = (point - sphere.center).norm();
  return distance <=
         sphere.radius + detail::onShapeTolerance(std::max(distance, sphere.radius), point);
}

// Closed box, exact: min <= p <= max on every axis (comparisons only, no rounding).
template <class T>
bool contains(const AabbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  return (box.min.array() <= point.array()).all() && (point.array() <= box.max.array()).all();
}

// Closed oriented box: |axes^T (p - c)| <= halfExtents on every axis, within the tolerance
// (scale |p - c| + the largest half extent).
template <class T>
bool contains(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> offset = point - box.center;
  const Vec3<T> local = box.axes.transpose() * offset;
  const T excess = (local.cwiseAbs() - box.halfExtents).maxCoeff();
  return excess <= detail::onShapeTolerance(offset.norm() + box.halfExtents.maxCoeff(), point);
}

// On the plane: |n.p + d| within the tolerance (scale |p| + |d|, the magnitudes n.p + d is
// computed from: its rounding error is below 2 eps (|p| + |d|) for a unit normal).
template <class T>
bool contains(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point) {
  return std::abs(plane.signedDistance(point)) <=
         detail::onShapeTolerance(point.norm() + std::abs(plane.d), point);
}

// On the segment: distance to it within the tolerance (scale max(|p - start|, length)). A
// zero-length segment contains only its point.
template <class T>
bool contains(const SegmentT<T>& segment, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> d = segment.end - segment.start;
  const Vec3<T> r = point - segment.start;
  const T t = detail::segmentParameter(d, r);
  return (r - t * d).norm() <= detail::onShapeTolerance(std::max(r.norm(), d.norm()), point);
}

// On the ray: distance to it within the tolerance (scale |p - origin|, so the allowed distance
// grows along the ray as the rounding of its direction does; the book's angle test is much
// looser, see above).
template <class T>
bool contains(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> r = point - ray.origin;
  const T t = std::max(T(0), r.dot(ray.direction));
  return (r - t * ray.direction).norm() <= detail::onShapeTolerance(r.norm(), point);
}

// On the triangle (closed: its edges and vertices included): distance to it within the tolerance
// (scale max(|p - a|, longest edge)). A degenerate triangle contains the points of its longest
// edge.
template <class T>
bool contains(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> ap = point - triangle.a;
  const detail::TriangleClosest<T> closest = detail::closestOnTriangle(triangle, point);
  const T longest = std::sqrt(detail::longestEdgeSquared<T>(
      triangle.b - triangle.a, triangle.c - triangle.a, triangle.c - triangle.b));
  return (ap - closest.offset).norm() <=
         detail::onShapeTolerance(std::max(ap.norm(), longest), point);
}

// ---- closest points -------------------------------------------------------------------------

// The point of the solid ball closest to p: p itself when inside, else the surface point towards
// p. A zero-radius sphere gives its center. Never divides by zero (outside means |p - c| > r >= 0).
template <class T>
Vec3<T> closestPoint(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> offset = point - sphere.center;
  const T distance = offset.norm();
  if (distance <= sphere.radius) return point;
  return sphere.center + offset * (sphere.radius / distance);
}

// p clamped to the box on each axis: exact.
template <class T>
Vec3<T> closestPoint(const AabbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  return point.cwiseMax(box.min).cwiseMin(box.max);
}

// p clamped to the box in its local frame; a point inside is returned unchanged (exactly).
template <class T>
Vec3<T> closestPoint(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> local = box.axes.transpose() * (point - box.center);
  const Vec3<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  if (clamped == local) return point;
  return box.center + box.axes * clamped;
}

// The orthogonal projection of p onto the plane.
template <class T>
Vec3<T> closestPoint(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point) {
  return point - plane.normal * plane.signedDistance(point);
}

// start + t (end - start) with t the clamped projection parameter; the start for a zero-length
// segment.
template <class T>
Vec3<T> closestPoint(const SegmentT<T>& segment, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> d = segment.end - segment.start;
  return segment.start + detail::segmentParameter<T>(d, point - segment.start) * d;
}

// origin + t direction with t = max(0, (p - origin).direction): points behind the origin give it.
template <class T>
Vec3<T> closestPoint(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point) {
  const T t = std::max(T(0), (point - ray.origin).dot(ray.direction));
  return ray.origin + t * ray.direction;
}

// Ericson's region method (5.1.5), not the book's, which can return a point of the wrong edge
// (see above). A degenerate triangle gives the closest point of its longest edge.
template <class T>
Vec3<T> closestPoint(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  return triangle.a + detail::closestOnTriangle(triangle, point).offset;
}

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
template <class T>
Vec3<T> barycentric(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> ab = triangle.b - triangle.a, ac = triangle.c - triangle.a;
  const Vec3<T> bc = triangle.c - triangle.b;
  const Vec3<T> ap = point - triangle.a, bp = point - triangle.b;
  const Vec3<T> n = ab.cross(ac);
  const T lab = ab.squaredNorm(), lac = ac.squaredNorm(), lbc = bc.squaredNorm();
  const T longest = std::max({lab, lac, lbc});
  if (detail::degenerateTriangle(n, longest)) {
    if (!(longest > 0)) return Vec3<T>(1, 0, 0);
    if (lab == longest) {
      const T t = ap.dot(ab) / lab;
      return Vec3<T>(1 - t, t, 0);
    }
    if (lac == longest) {
      const T t = ap.dot(ac) / lac;
      return Vec3<T>(1 - t, 0, t);
    }
    const T t = bp.dot(bc) / lbc;
    return Vec3<T>(0, 1 - t, t);
  }
  const T nn = n.squaredNorm();
  return Vec3<T>(n.dot(bc.cross(bp)) / nn, n.dot(ap.cross(ac)) / nn, n.dot(ab.cross(ap)) / nn);
}

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
SegmentClosestPointsT<T> closestPoints(const SegmentT<T>& first, const SegmentT<T>& second) {
  const Vec3<T> d1 = first.end - first.start, d2 = second.end - second.start;
  const Vec3<T> r = second.start - first.start;
  T bestS = 0, bestT = 0;
  T best = std::numeric_limits<T>::infinity();
  // The offset first(s) - second(t), taken from the starts so that it has no cancellation.
  const auto consider = [&](T s, T t) {
    const T distance = (s * d1 - t * d2 - r).norm();
    if (distance < best) {
      best = distance;
      bestS = s;
      bestT = t;
    }
  };
  // s and t are ratios of degree-4 products (|n|^2 ~ L^4 overflows float from L ~ 4e9): they are
  // computed on the offsets scaled exactly by a power of two that brings the longer segment to
  // about 1 (same bits where nothing overflows). Where r scaled overflows (|r| > 1e38 L), the
  // stationary point is skipped: the side candidates are then within L of it, far below the
  // rounding of r's coordinates.
  const T scale =
      detail::inversePowerOfTwo(std::max(d1.cwiseAbs().maxCoeff(), d2.cwiseAbs().maxCoeff()));
  const Vec3<T> u1 = d1 * scale, u2 = d2 * scale, ur = r * scale;
  const Vec3<T> n = u1.cross(u2);
  const T nn = n.squaredNorm();
  if (n.norm() > kGeometryTolerance<T> * u1.norm() * u2.norm()) {
    const T s = ur.cross(u2).dot(n) / nn, t = ur.cross(u1).dot(n) / nn;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) consider(s, t);
  }
  consider(T(0), detail::segmentParameter<T>(d2, first.start - second.start));
  consider(T(1), detail::segmentParameter<T>(d2, first.end - second.start));
  consider(detail::segmentParameter<T>(d1, r), T(0));
  consider(detail::segmentParameter<T>(d1, second.end - first.start), T(1));
  return {first.start + bestS * d1, second.start + bestT * d2, bestS, bestT, best};
}

}  // namespace simdphys

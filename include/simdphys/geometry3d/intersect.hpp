// Shape-versus-shape tests of the book's chapter 9 and the triangle tests of chapter 11:
// `intersects(a, b)` for every pair of sphere, AABB, OBB, plane and triangle the book has, in both
// argument orders.
//
// Conventions (docs/geometry.md restates them):
// - Closed: touching shapes intersect. Like the point tests (point_tests.hpp), a computed
//   distance or gap up to kGeometryTolerance<T> * scale counts as zero, where scale bounds the
//   magnitudes the rounding error grows with (the sizes of the shapes and the offset between them;
//   for planes also |d| and the shape's distance from the origin, since n.p + d is absolute). So
//   shapes that touch in exact arithmetic always intersect, and shapes closer than that count as
//   touching. AABB-AABB needs no tolerance: it is exact.
// - Solid: a sphere or box inside another shape intersects it.
// - Symmetric by construction: intersects(b, a) forwards to intersects(a, b) for mixed pairs.
//   OBB-OBB is written so that both orders give the same bits (see its comment): a batch of one
//   box against many can then mirror it lane by lane. For plane-plane and triangle-triangle, whose
//   arithmetic is not symmetric, the two shapes are put in a canonical order first, so both orders
//   run the same operations and agree bit for bit.
// - Positions are taken relative to one shape before anything is multiplied (see point_tests.hpp),
//   so shapes of size 1e-2 at coordinates of 1e5 are tested at the precision of their size.
//   Plane tests are the exception: a plane n.p + d = 0 is only as precise as d.
// - Inputs are not validated: they are assumed valid and within the supported range of math.hpp
//   (what validate() accepts), where no computation overflows (squared lengths of offsets stay
//   below 1.2e37 in float) and shapes at opposite corners of the range are told apart.
// - Degenerate input: a zero-radius sphere is a point, a zero-size box a point (or a segment or
//   rectangle if only some extents are zero), a triangle with collinear vertices its longest edge
//   (a point if they coincide); each test then answers for that point, segment or rectangle.
//
// Separating-axis tests (AABB-OBB, OBB-OBB, triangle-AABB, triangle-OBB, triangle-triangle), and
// the book's "Robustness of the Separating Axis Theorem":
// - Axes are never normalised (no NaN from a zero axis, no division). The gap between the two
//   intervals on an axis L is compared with kGeometryTolerance * scale * |L|: projections of
//   points at distance up to `scale` from the reference point onto L are accurate to a few eps *
//   scale * |L|, whatever the length of L.
// - An edge-edge axis e1 x e2 is skipped when |e1 x e2| <= kGeometryTolerance |e1| |e2| (the edges
//   are parallel to 16 eps, below the 64 eps to which validated OBB axes are orthonormal). This
//   is correct because the candidate axes of two convex polyhedra come from the faces of their
//   Minkowski difference: face normals of either shape, and crosses of pairs of *non-parallel*
//   edges (two parallel edges sum to a segment, never to a face), so a parallel pair has no axis
//   to contribute that the face axes do not cover. A pair at a small angle theta skipped as
//   parallel can hide a separation of the order of theta times the shapes' size, within the
//   tolerance. Between that threshold and about sqrt(eps) the computed cross product's direction is
//   uncertain by about eps / sin(theta); a projection on the computed axis is still a true
//   projection, so this never turns an intersection into a miss, but a separation of up to about
//   sqrt(eps) times the shapes' size (3.5e-4 in float, 1.5e-8 in double) can go unseen there.
// - The book's cure for a zero cross product (its SatCrossEdge: try e1 x (e1 x (p2 - p1))) is
//   needed only where the Minkowski difference is flat, which for boxes never happens (their
//   face axes exist whatever the extents). Two triangles are flat: coplanar triangles (or a
//   triangle and a coplanar segment) are separated only by in-plane axes, which none of the
//   3D candidates give unless two edges happen to be parallel, so the book's TriangleTriangle and
//   even its robust version report coplanar disjoint triangles with no parallel edges as
//   intersecting. Here the in-plane axes n x e (for both normals and all six edges) are tested
//   always, which covers coplanar and nearly coplanar pairs; a triangle whose normal vanishes
//   (degenerate) contributes no normal, and two degenerate triangles are tested as two segments
//   by their closest points.
//
// Where the book's code (Code/Geometry3D.cpp) is wrong, beyond the strict `<` of its sphere tests:
// - AABBOBB and OBBOBB fill the nine edge axes with Cross(test[i], test[j]) for i, j in 0..2, the
//   first box's axes crossed with themselves (zero or its own face axes) instead of with the
//   second box's: boxes separated only by an edge-edge axis are reported as intersecting.
// - OverlapOnAxis(OBB, OBB) takes both intervals from the first box, so OBBOBB is always true.
// - PlanePlane returns false for parallel planes even when they coincide.
// - TriangleTriangle (and TriangleTriangleRobust) miss coplanar separations, as above.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>

#include "simdphys/geometry3d/point_tests.hpp"
#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys {

namespace detail {

// ---- symmetric order ----

template <class T, std::size_t N>
bool lexicographicallyLess(const std::array<T, N>& a, const std::array<T, N>& b) {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
}
template <class T>
std::array<T, 9> numbers(const TriangleT<T>& t) {
  return {t.a.x(), t.a.y(), t.a.z(), t.b.x(), t.b.y(), t.b.z(), t.c.x(), t.c.y(), t.c.z()};
}
template <class T>
std::array<T, 4> numbers(const PlaneT<T>& p) {
  return {p.normal.x(), p.normal.y(), p.normal.z(), p.d};
}
// True when (b, a) is the canonical order of the pair.
template <class S>
bool swapToCanonical(const S& a, const S& b) {
  return lexicographicallyLess(numbers(b), numbers(a));
}

// ---- separating axes ----

// A box relative to the test's reference point: center, half extents, axes (columns).
template <class T>
struct SatBox {
  Vec3<T> center, half;
  Mat3<T> axes;
};

template <class T>
struct Interval {
  T min, max;
};

template <class T>
Interval<T> projectOnto(const SatBox<T>& box, const Vec3<T>& axis) {
  const T c = box.center.dot(axis);
  const T r = box.half[0] * std::abs(box.axes.col(0).dot(axis)) +
              box.half[1] * std::abs(box.axes.col(1).dot(axis)) +
              box.half[2] * std::abs(box.axes.col(2).dot(axis));
  return {c - r, c + r};
}

template <class T>
Interval<T> projectOnto(const std::array<Vec3<T>, 3>& v, const Vec3<T>& axis) {
  const T p0 = v[0].dot(axis), p1 = v[1].dot(axis), p2 = v[2].dot(axis);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}

// True when the two intervals on `axis` are apart by more than the tolerance; the axis is not
// normalised, so the tolerance is scaled by its length (see the header comment). The gap is
// max(b.min - a.max, a.min - b.max), compared side by side so that swapping a and b changes
// nothing even for a NaN (std::max is not symmetric there).
template <class T>
bool separatedOn(const Interval<T>& a, const Interval<T>& b, const Vec3<T>& axis, T scale) {
  const T tolerance = kGeometryTolerance<T> * scale * axis.norm();
  return b.min - a.max > tolerance || a.min - b.max > tolerance;
}

// Whether an edge-edge axis is long enough to test (see the header comment on parallel edges).
// |e1| |e2| is one product, so swapping e1 and e2 gives the same threshold bits.
template <class T>
bool crossAxis(const Vec3<T>& e1, const Vec3<T>& e2, Vec3<T>& axis) {
  axis = e1.cross(e2);
  return axis.norm() > kGeometryTolerance<T> * (e1.norm() * e2.norm());
}

// Box-box SAT: the 3 + 3 face axes and the 9 crosses of non-parallel axis pairs. Symmetric in a
// and b to the last bit (see intersects(Obb, Obb)); the scale adds each box's part first for that.
template <class T>
bool boxesIntersect(const SatBox<T>& a, const SatBox<T>& b) {
  const T scale = (a.center.norm() + a.half.sum()) + (b.center.norm() + b.half.sum());
  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(a, axis), projectOnto(b, axis), axis, scale);
  };
  for (int i = 0; i < 3; ++i)
    if (separated(a.axes.col(i)) || separated(b.axes.col(i))) return false;
  Vec3<T> axis;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis<T>(a.axes.col(i), b.axes.col(j), axis) && separated(axis)) return false;
  return true;
}

// The three edges b - a, c - b, a - c of a triangle.
template <class T>
std::array<Vec3<T>, 3> edgesOf(const std::array<Vec3<T>, 3>& v) {
  return {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
}

// The triangle's normal, or false if it is degenerate (see degenerateTriangle).
template <class T>
bool properNormal(const std::array<Vec3<T>, 3>& e, Vec3<T>& normal) {
  normal = e[0].cross(e[1]);
  const T longest = std::max({e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()});
  return !degenerateTriangle(normal, longest);
}

// Scales the vertices v and the other vectors (all relative to the test's reference point) by one
// power of two so that every component is below 1. Exact (no rounding, barring underflow far
// below the tolerance), so the test's answer is that of the unscaled offsets; but the edge
// crosses (L^2), their norms (L^4 before the root) and projections on them (L^3) stay finite for
// shapes anywhere in the supported range: offsets of 2e18 would give 1e73 and report shapes at
// opposite ends of the range as intersecting (an infinite tolerance).
template <class T>
void toUnitScale(std::array<Vec3<T>, 3>& v, std::initializer_list<Vec3<T>*> others) {
  T m = 0;
  for (const Vec3<T>& x : v) m = std::max(m, x.cwiseAbs().maxCoeff());
  for (const Vec3<T>* x : others) m = std::max(m, x->cwiseAbs().maxCoeff());
  const T inverse = inversePowerOfTwo(m);
  for (Vec3<T>& x : v) x *= inverse;
  for (Vec3<T>* x : others) *x *= inverse;
}

// Triangle-box SAT: the box's 3 face axes, the triangle's normal, the 9 crosses of box axes with
// triangle edges. Complete also for a degenerate triangle (a segment: its Minkowski difference
// with the box has only box faces and edge crosses; a point: only box faces) and for flat boxes
// (the box's axes exist whatever its extents; when box and triangle are coplanar, the in-plane
// normal n x e of a triangle edge is, on the flat difference, equivalent to any u x e that is not
// parallel to n, and one of the three box axes gives such an axis).
template <class T>
bool triangleBoxIntersect(std::array<Vec3<T>, 3> v, SatBox<T> box) {
  toUnitScale(v, {&box.center, &box.half});
  const T scale =
      box.center.norm() + box.half.sum() + std::max({v[0].norm(), v[1].norm(), v[2].norm()});
  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(v, axis), projectOnto(box, axis), axis, scale);
  };
  for (int i = 0; i < 3; ++i)
    if (separated(box.axes.col(i))) return false;
  const std::array<Vec3<T>, 3> e = edgesOf(v);
  Vec3<T> axis;
  if (properNormal(e, axis) && separated(axis)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis<T>(box.axes.col(i), e[j], axis) && separated(axis)) return false;
  return true;
}

// The longest edge of a degenerate triangle, the segment it stands for.
template <class T>
SegmentT<T> longestEdge(const std::array<Vec3<T>, 3>& v) {
  const std::array<Vec3<T>, 3> e = edgesOf(v);
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (e[i].squaredNorm() > e[k].squaredNorm()) k = i;
  return {v[k], v[(k + 1) % 3]};
}

// Triangle-triangle SAT, both triangles relative to the reference point. Axes: each proper
// triangle's normal, the crosses of non-parallel edge pairs, and the in-plane axes n x e of each
// proper normal with all six edges (for coplanar and nearly coplanar pairs, see the header).
// Two degenerate triangles are two segments: they intersect when their closest points are within
// twice the tolerance (once for the rounding, once for the up to tolerance * L by which a
// degenerate triangle may stand off its longest edge).
template <class T>
bool trianglesIntersect(std::array<Vec3<T>, 3> v1, std::array<Vec3<T>, 3> v2) {
  toUnitScale(v1, {&v2[0], &v2[1], &v2[2]});
  T scale = 0;
  for (int i = 0; i < 3; ++i) scale = std::max({scale, v1[i].norm(), v2[i].norm()});
  scale *= 2;  // also bounds the edge lengths
  const std::array<Vec3<T>, 3> e1 = edgesOf(v1), e2 = edgesOf(v2);
  Vec3<T> n1, n2;
  const bool proper1 = properNormal(e1, n1), proper2 = properNormal(e2, n2);
  if (!proper1 && !proper2)
    return closestPoints(longestEdge(v1), longestEdge(v2)).distance <=
           2 * kGeometryTolerance<T> * scale;

  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(v1, axis), projectOnto(v2, axis), axis, scale);
  };
  if ((proper1 && separated(n1)) || (proper2 && separated(n2))) return false;
  Vec3<T> axis;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis(e1[i], e2[j], axis) && separated(axis)) return false;
  const auto separatedInPlane = [&](const Vec3<T>& n) {
    for (const std::array<Vec3<T>, 3>* e : {&e1, &e2})
      for (int i = 0; i < 3; ++i)
        if (crossAxis(n, (*e)[i], axis) && separated(axis)) return true;
    return false;
  };
  return !((proper1 && separatedInPlane(n1)) || (proper2 && separatedInPlane(n2)));
}

template <class T>
std::array<Vec3<T>, 3> relative(const TriangleT<T>& t, const Vec3<T>& origin) {
  return {t.a - origin, t.b - origin, t.c - origin};
}

// An AABB as a SatBox relative to its own min corner (differences of nearby coordinates are exact,
// its center (min + max) / 2 at large coordinates would not be).
template <class T>
SatBox<T> boxFromMin(const AabbT<T>& box) {
  const Vec3<T> half = (box.max - box.min) / T(2);
  return {half, half, Mat3<T>::Identity()};
}

// |s| <= r within the tolerance: a shape of radius r along the normal, at signed distance s.
template <class T>
bool withinPlaneReach(T s, T r, T scale) {
  return std::abs(s) <= r + kGeometryTolerance<T> * scale;
}

}  // namespace detail

// ---- sphere ---------------------------------------------------------------------------------

// |c1 - c2| <= r1 + r2. Scale |c1 - c2| + r1 + r2.
template <class T>
bool intersects(const SphereT<T>& a, const SphereT<T>& b) {
  const T distance = (b.center - a.center).norm();
  const T reach = a.radius + b.radius;
  return distance <= reach + kGeometryTolerance<T> * (distance + reach);
}

// The distance from the center to its clamp into the box (exact) is at most r. Scale: that
// distance + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const AabbT<T>& box) {
  const T distance = (sphere.center - closestPoint(box, sphere.center)).norm();
  return distance <= sphere.radius + kGeometryTolerance<T> * (distance + sphere.radius);
}
template <class T>
bool intersects(const AabbT<T>& box, const SphereT<T>& sphere) {
  return intersects(sphere, box);
}

// The same in the box's frame: the distance is that of the local center from its clamp. Scale:
// |c - center| + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const ObbT<T>& box) {
  const Vec3<T> offset = sphere.center - box.center;
  const Vec3<T> local = box.axes.transpose() * offset;
  const Vec3<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  return (local - clamped).norm() <=
         sphere.radius + kGeometryTolerance<T> * (offset.norm() + sphere.radius);
}
template <class T>
bool intersects(const ObbT<T>& box, const SphereT<T>& sphere) {
  return intersects(sphere, box);
}

// |n.c + d| <= r. Scale |c| + |d| + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const PlaneT<T>& plane) {
  return detail::withinPlaneReach(plane.signedDistance(sphere.center), sphere.radius,
                                  sphere.center.norm() + std::abs(plane.d) + sphere.radius);
}
template <class T>
bool intersects(const PlaneT<T>& plane, const SphereT<T>& sphere) {
  return intersects(sphere, plane);
}

// ---- AABB -----------------------------------------------------------------------------------

// Overlap on all three axes, closed and exact (primitives.hpp's overlaps).
template <class T>
bool intersects(const AabbT<T>& a, const AabbT<T>& b) {
  return overlaps(a, b);
}

// Box-box SAT relative to the AABB's min corner.
template <class T>
bool intersects(const AabbT<T>& a, const ObbT<T>& b) {
  return detail::boxesIntersect(detail::boxFromMin(a),
                                detail::SatBox<T>{b.center - a.min, b.halfExtents, b.axes});
}
template <class T>
bool intersects(const ObbT<T>& b, const AabbT<T>& a) {
  return intersects(a, b);
}

// |n.center + d| <= sum of half |n_i|. Scale |center| + |d| + that sum.
template <class T>
bool intersects(const AabbT<T>& box, const PlaneT<T>& plane) {
  const Vec3<T> center = box.center(), half = box.halfExtents();
  const T reach = half.dot(plane.normal.cwiseAbs());
  return detail::withinPlaneReach(plane.signedDistance(center), reach,
                                  center.norm() + std::abs(plane.d) + reach);
}
template <class T>
bool intersects(const PlaneT<T>& plane, const AabbT<T>& box) {
  return intersects(box, plane);
}

// ---- OBB ------------------------------------------------------------------------------------

// Box-box SAT relative to the midpoint m of the two centres. intersects(a, b) and intersects(b, a)
// give identical bits with no reordering (batch.hpp's overlapping(Obb, ObbStream) relies on it):
// - m = a/2 + b/2 is the same in both orders (+ commutes; halving is exact but for subnormals;
//   unlike (a + b) / 2 it cannot overflow), so each box gets the same relative centre and the
//   same scale, whose two halves are added in either order.
// - A face axis gives the same intervals in both orders, only the roles are swapped, and
//   separatedOn compares the same two differences, b.min - a.max and a.min - b.max.
// - The edge axis b_j x a_i is exactly -(a_i x b_j): each component is a difference of products
//   that commute, and x - y = -(y - x) in IEEE arithmetic (no fused multiply-add: the project
//   builds with -ffp-contract=off). Its norm and crossAxis's threshold are unchanged, projections
//   onto -L are the exact negations of those onto L (the radius, a sum of |dots|, is unchanged),
//   so the intervals are negated and swapped, and separatedOn compares the same two values.
// - "Separated" is an OR over the axes, so the order in which they are tried does not matter.
// Precision: where the boxes are close, a.center - m and b.center - m are exact (Sterbenz), and
// in general within eps |b - a| of exact, as good as the offset from one centre.
template <class T>
bool intersects(const ObbT<T>& a, const ObbT<T>& b) {
  const Vec3<T> m = a.center * T(0.5) + b.center * T(0.5);
  return detail::boxesIntersect(detail::SatBox<T>{a.center - m, a.halfExtents, a.axes},
                                detail::SatBox<T>{b.center - m, b.halfExtents, b.axes});
}

// |n.center + d| <= sum of half_i |n.axis_i|. Scale |center| + |d| + that sum.
template <class T>
bool intersects(const ObbT<T>& box, const PlaneT<T>& plane) {
  const T reach = box.halfExtents.dot((box.axes.transpose() * plane.normal).cwiseAbs());
  return detail::withinPlaneReach(plane.signedDistance(box.center), reach,
                                  box.center.norm() + std::abs(plane.d) + reach);
}
template <class T>
bool intersects(const PlaneT<T>& plane, const ObbT<T>& box) {
  return intersects(box, plane);
}

// ---- plane ----------------------------------------------------------------------------------

// Planes intersect unless parallel and distinct. Parallel: |n1 x n2| <= tolerance (the normals
// agree to 16 eps, below the precision validate() asks of a unit normal); such planes coincide
// when their offsets agree (d1 = d2 for equal normals, d1 = -d2 for opposite ones) within the
// tolerance times |d1| + |d2|. Nearly parallel planes beyond that do meet, far away.
template <class T>
bool intersects(const PlaneT<T>& a, const PlaneT<T>& b) {
  if (detail::swapToCanonical(a, b)) return intersects(b, a);
  if (a.normal.cross(b.normal).norm() > kGeometryTolerance<T>) return true;
  const T offset = a.normal.dot(b.normal) > 0 ? a.d - b.d : a.d + b.d;
  return std::abs(offset) <= kGeometryTolerance<T> * (std::abs(a.d) + std::abs(b.d));
}

// ---- triangle -------------------------------------------------------------------------------

// The triangle's closest point to the center (Ericson's regions) is within r. Scale:
// max(|c - a|, longest edge) + r. A degenerate triangle answers for its longest edge.
template <class T>
bool intersects(const TriangleT<T>& triangle, const SphereT<T>& sphere) {
  const Vec3<T> ac = sphere.center - triangle.a;
  const T distance = (ac - detail::closestOnTriangle(triangle, sphere.center)).norm();
  const T longest = std::sqrt(detail::longestEdgeSquared<T>(
      triangle.b - triangle.a, triangle.c - triangle.a, triangle.c - triangle.b));
  return distance <=
         sphere.radius + kGeometryTolerance<T> * (std::max(ac.norm(), longest) + sphere.radius);
}
template <class T>
bool intersects(const SphereT<T>& sphere, const TriangleT<T>& triangle) {
  return intersects(triangle, sphere);
}

// Triangle-box SAT relative to the AABB's min corner.
template <class T>
bool intersects(const TriangleT<T>& triangle, const AabbT<T>& box) {
  return detail::triangleBoxIntersect(detail::relative(triangle, box.min), detail::boxFromMin(box));
}
template <class T>
bool intersects(const AabbT<T>& box, const TriangleT<T>& triangle) {
  return intersects(triangle, box);
}

// Triangle-box SAT relative to the OBB's center.
template <class T>
bool intersects(const TriangleT<T>& triangle, const ObbT<T>& box) {
  return detail::triangleBoxIntersect(
      detail::relative(triangle, box.center),
      detail::SatBox<T>{Vec3<T>::Zero(), box.halfExtents, box.axes});
}
template <class T>
bool intersects(const ObbT<T>& box, const TriangleT<T>& triangle) {
  return intersects(triangle, box);
}

// Not all three vertices strictly on one side: min(s) <= 0 <= max(s) for the signed distances s
// of the vertices, within the tolerance times max |vertex| + |d|. A triangle lying in the plane
// intersects it.
template <class T>
bool intersects(const TriangleT<T>& triangle, const PlaneT<T>& plane) {
  const T sa = plane.signedDistance(triangle.a), sb = plane.signedDistance(triangle.b),
          sc = plane.signedDistance(triangle.c);
  const T scale =
      std::max({triangle.a.norm(), triangle.b.norm(), triangle.c.norm()}) + std::abs(plane.d);
  const T tolerance = kGeometryTolerance<T> * scale;
  return std::min({sa, sb, sc}) <= tolerance && std::max({sa, sb, sc}) >= -tolerance;
}
template <class T>
bool intersects(const PlaneT<T>& plane, const TriangleT<T>& triangle) {
  return intersects(triangle, plane);
}

// Triangle-triangle SAT relative to the first triangle's vertex a, in canonical order.
template <class T>
bool intersects(const TriangleT<T>& a, const TriangleT<T>& b) {
  if (detail::swapToCanonical(a, b)) return intersects(b, a);
  return detail::trianglesIntersect(detail::relative(a, a.a), detail::relative(b, a.a));
}

}  // namespace simdphys

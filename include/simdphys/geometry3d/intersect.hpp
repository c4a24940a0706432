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

// ---- separating axes ----

// A box relative to the test's reference point: center, half extents, axes (columns).
template <class T>
struct SatBox {
  Vec3<T> center, half;
  Mat3<T> axes;
};

// Box-box SAT: the 3 + 3 face axes and the 9 crosses of non-parallel axis pairs. Symmetric in a
// and b to the last bit (see intersects(Obb, Obb)); the scale adds each box's part first for that.
template <class T>
bool boxesIntersect(const SatBox<T>& a, const SatBox<T>& b);

// Triangle-triangle SAT, both triangles relative to the reference point. Axes: each proper
// triangle's normal, the crosses of non-parallel edge pairs, and the in-plane axes n x e of each
// proper normal with all six edges (for coplanar and nearly coplanar pairs, see the header).
// Two degenerate triangles are two segments: they intersect when their closest points are within
// twice the tolerance (once for the rounding, once for the up to tolerance * L by which a
// degenerate triangle may stand off its longest edge).
template <class T>
bool trianglesIntersect(std::array<Vec3<T>, 3> v1, std::array<Vec3<T>, 3> v2);

template <class T>
std::array<Vec3<T>, 3> relative(const TriangleT<T>& t, const Vec3<T>& origin);

}  // namespace detail

// Each pair is declared in one order; the other order is primitives.hpp's intersects(a, b).

// ---- sphere ---------------------------------------------------------------------------------

// |c1 - c2| <= r1 + r2. Scale |c1 - c2| + r1 + r2.
template <class T>
bool intersects(const SphereT<T>& a, const SphereT<T>& b);

// The distance from the center to its clamp into the box (exact) is at most r. Scale: that
// distance + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const AabbT<T>& box);

// The same in the box's frame: the distance is that of the local center from its clamp. Scale:
// |c - center| + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const ObbT<T>& box);

// |n.c + d| <= r. Scale |c| + |d| + r.
template <class T>
bool intersects(const SphereT<T>& sphere, const PlaneT<T>& plane);

// ---- AABB -----------------------------------------------------------------------------------

// Two AABBs: intersects(AabbT, AabbT) of primitives.hpp, overlap on all three axes, closed and
// exact.

// Box-box SAT relative to the AABB's min corner.
template <class T>
bool intersects(const AabbT<T>& a, const ObbT<T>& b);

// |n.center + d| <= sum of half |n_i|. Scale |center| + |d| + that sum.
template <class T>
bool intersects(const AabbT<T>& box, const PlaneT<T>& plane);

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
bool intersects(const ObbT<T>& a, const ObbT<T>& b);

// |n.center + d| <= sum of half_i |n.axis_i|. Scale |center| + |d| + that sum.
template <class T>
bool intersects(const ObbT<T>& box, const PlaneT<T>& plane);

// ---- plane ----------------------------------------------------------------------------------

// Planes intersect unless parallel and distinct. Parallel: |n1 x n2| <= tolerance (the normals
// agree to 16 eps, below the precision validate() asks of a unit normal); such planes coincide
// when their offsets agree (d1 = d2 for equal normals, d1 = -d2 for opposite ones) within the
// tolerance times |d1| + |d2|. Nearly parallel planes beyond that do meet, far away.
template <class T>
bool intersects(const PlaneT<T>& a, const PlaneT<T>& b);

// ---- triangle -------------------------------------------------------------------------------

// The triangle's closest point to the center (Ericson's regions) is within r. Scale:
// max(|c - a|, longest edge) + r. A degenerate triangle answers for its longest edge.
template <class T>
bool intersects(const TriangleT<T>& triangle, const SphereT<T>& sphere);

// Triangle-box SAT relative to the AABB's min corner.
template <class T>
bool intersects(const TriangleT<T>& triangle, const AabbT<T>& box);

// Triangle-box SAT relative to the OBB's center.
template <class T>
bool intersects(const TriangleT<T>& triangle, const ObbT<T>& box);

// Not all three vertices strictly on one side: min(s) <= 0 <= max(s) for the signed distances s
// of the vertices, within the tolerance times max |vertex| + |d|. A triangle lying in the plane
// intersects it.
template <class T>
bool intersects(const TriangleT<T>& triangle, const PlaneT<T>& plane);

// Triangle-triangle SAT relative to the first triangle's vertex a, in canonical order.
template <class T>
bool intersects(const TriangleT<T>& a, const TriangleT<T>& b);

}  // namespace simdphys

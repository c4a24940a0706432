// Tests of include/simdphys/geometry3d/intersect.hpp on hand-worked cases and named hard cases
// (parallel and nearly parallel OBB edges, touching shapes, 1e5 coordinates with 1e-2 sizes,
// 1e-6 shapes, degenerate triangles, zero-size boxes), in float and in double. Every expected
// value is derived in the comment beside it; tolerances as in geometry3d_point_test.cpp.
#include "geometry3d_cases.hpp"

namespace simdphys {
namespace {

using namespace test;

// =============================================================================================
// Intersections: hand-worked cases
// =============================================================================================

TYPED_TEST(Intersects, SphereSphere) {
  using T = TypeParam;
  const SphereT<T> a{v3<T>(0, 0, 0), 1};
  EXPECT_INTERSECTS(a, (SphereT<T>{v3<T>(3, 0, 0), 2}), true);  // touching: 3 = 1 + 2 (book: <)
  EXPECT_INTERSECTS(a, (SphereT<T>{v3<T>(3.001, 0, 0), 2}), false);
  EXPECT_INTERSECTS(a, (SphereT<T>{v3<T>(0.5, 0, 0), 0.1}), true);  // inside
  // Zero radii: points.
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(1, 1, 1), 0}), (SphereT<T>{v3<T>(1, 1, 1), 0}), true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(1, 1, 1), 0}), (SphereT<T>{v3<T>(1, 1, 1.001), 0}), false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, 0, 2), 0}), (SphereT<T>{v3<T>(0, 0, 0), 2}), true);
}

TYPED_TEST(Intersects, SphereAabb) {
  using T = TypeParam;
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  // Face: center (2,0,0) clamps to (1,0,0), distance 1.
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 0, 0), 1}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 0, 0), 0.999}), box, false);
  // Edge: (2,2,0) clamps to (1,1,0), distance sqrt 2; corner: (2,2,2) to (1,1,1), sqrt 3. The
  // radii round in T, within tol.
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 2, 0), std::sqrt(T(2))}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 2, 0), T(0.999) * std::sqrt(T(2))}), box, false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 2, 2), std::sqrt(T(3))}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2, 2, 2), T(0.999) * std::sqrt(T(3))}), box, false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, 0, 0), 0.1}), box, true);  // inside the solid box
}

TYPED_TEST(Intersects, SphereObb) {
  using T = TypeParam;
  const ObbT<T> box{v3<T>(1, 1, 0), v3<T>(2, 1, 0.5), quarterTurnZ<T>()};
  // Center (1,5,0): local (4,0,0), clamped (2,0,0): distance 2.
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(1, 5, 0), 2}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(1, 5, 0), 1.999}), box, false);
  // Center (-3,7,0.5): offset (-4,6,0.5), local (u0.d, u1.d, u2.d) = (6, 4, 0.5), clamped
  // (2, 1, 0.5) (a corner): the difference (4, 3, 0) has length 5.
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(-3, 7, 0.5), 5}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(-3, 7, 0.5), 4.999}), box, false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(1, 1, 0), 0.01}), box, true);  // inside
}

TYPED_TEST(Intersects, SpherePlane) {
  using T = TypeParam;
  const PlaneT<T> plane{v3<T>(0, 1, 0), -1};                         // y = 1
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(5, 3, -3), 2}), plane, true);  // signed distance 2
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(5, 3, -3), 1.999}), plane, false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, -1, 0), 0.5}), plane, false);  // behind, -2
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, -1, 0), 2}), plane, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(4, 1, 4), 0}), plane, true);  // a point on the plane
}

TYPED_TEST(Intersects, AabbAabb) {
  using T = TypeParam;
  const AabbT<T> a{v3<T>(0, 0, 0), v3<T>(1, 1, 1)};
  EXPECT_INTERSECTS(a, (AabbT<T>{v3<T>(1, 0, 0), v3<T>(2, 1, 1)}), true);  // face
  EXPECT_INTERSECTS(a, (AabbT<T>{v3<T>(1, 1, 0), v3<T>(2, 2, 1)}), true);  // edge
  EXPECT_INTERSECTS(a, (AabbT<T>{v3<T>(1, 1, 1), v3<T>(2, 2, 2)}), true);  // corner
  EXPECT_INTERSECTS(a, (AabbT<T>{v3<T>(1.001, 0, 0), v3<T>(2, 1, 1)}), false);
  EXPECT_INTERSECTS(a, (AabbT<T>{v3<T>(0.2, 0.2, 0.2), v3<T>(0.3, 0.3, 0.3)}), true);  // inside
}

// Separated only by the edge-edge axis z x u0 (see ridgeBox). The book's AABBOBB fills its nine
// edge axes with the AABB's axes crossed with themselves, so it never tests z x u0 and reports
// the g = 0.5 pair as intersecting.
TYPED_TEST(Intersects, AabbObbAcrossAnEdgeEdgeAxis) {
  using T = TypeParam;
  const AabbT<T> cube{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  EXPECT_INTERSECTS(cube, ridgeBox<T>(0.5), false);  // book: true
  // The gap 0.01 is far beyond the tolerance (16 eps * scale, scale ~ 10: 2e-5 in float).
  EXPECT_INTERSECTS(cube, ridgeBox<T>(0.01), false);
  EXPECT_INTERSECTS(cube, ridgeBox<T>(0), true);  // the edges touch at (1,1,0)
  EXPECT_INTERSECTS(cube, ridgeBox<T>(-0.1), true);
  // Face against face: a box turned 30 degrees about x keeps its x faces; x in [1, 2] touches.
  const ObbT<T> turned{v3<T>(1.5, 0, 0), v3<T>(0.5, 1, 1), rotationX(T(0.5235987755982988))};
  EXPECT_INTERSECTS(cube, turned, true);
  const ObbT<T> apart{v3<T>(1.501, 0, 0), v3<T>(0.5, 1, 1), rotationX(T(0.5235987755982988))};
  EXPECT_INTERSECTS(cube, apart, false);
}

TYPED_TEST(Intersects, AabbPlane) {
  using T = TypeParam;
  // Box center (5,0,0), half 1; n = (0.6, 0.8, 0): reach 0.6 + 0.8 = 1.4, signed distance 3 + d.
  const AabbT<T> box{v3<T>(4, -1, -1), v3<T>(6, 1, 1)};
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0.8, 0), -1.6}), true);   // 1.4: touching
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0.8, 0), -1.5}), false);  // 1.5
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0.8, 0), -3}), true);     // 0: through the center
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0.8, 0), -4.4}), true);   // -1.4: touching
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0.8, 0), -4.5}), false);  // -1.5
}

TYPED_TEST(Intersects, ObbObb) {
  using T = TypeParam;
  const ObbT<T> cube = cubeObb<T>(Vec3<T>::Zero(), 1);
  EXPECT_INTERSECTS(cube, ridgeBox<T>(0.5), false);
  EXPECT_INTERSECTS(cube, ridgeBox<T>(0), true);
  EXPECT_INTERSECTS(cube, ridgeBox<T>(-0.1), true);
  // The book's OverlapOnAxis(OBB, OBB) takes both intervals from the first box, so its OBBOBB
  // is true for any pair, e.g. these unit cubes 5 apart.
  EXPECT_INTERSECTS(cube, cubeObb<T>(v3<T>(5, 0, 0), 1, rotation345<T>()), false);  // book: true
  // A corner against a face: B is turned so that its local (1,1,1) corner points along -x
  // (rotation about (0,-1,1) by acos(-1/sqrt3)); that corner is c - sqrt3 x. With
  // c = (1 + sqrt3 + g, 0.2, 0.3) it lies at x = 1 + g, inside the face x = 1 for g = 0.
  const T sqrt3 = std::sqrt(T(3));
  const Mat3<T> r = axisAngle(v3<T>(0, -1, 1), std::acos(T(-1) / sqrt3));
  EXPECT_INTERSECTS(cube, cubeObb<T>(Vec3<T>(1 + sqrt3, T(0.2), T(0.3)), 1, r), true);
  EXPECT_INTERSECTS(cube, cubeObb<T>(Vec3<T>(T(1.01) + sqrt3, T(0.2), T(0.3)), 1, r), false);
  EXPECT_INTERSECTS(cube, cubeObb<T>(Vec3<T>(T(0.99) + sqrt3, T(0.2), T(0.3)), 1, r), true);
}

TYPED_TEST(Intersects, ObbPlane) {
  using T = TypeParam;
  // Center (0,0,5), half (1,2,3), quarter turn about z (u0 = y, u1 = -x, u2 = z).
  const ObbT<T> box{v3<T>(0, 0, 5), v3<T>(1, 2, 3), quarterTurnZ<T>()};
  // z = 2: reach 3 |n.u2| = 3, signed distance 5 - 2 = 3: touching.
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0, 0, 1), -2}), true);
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0, 0, 1), -1.9}), false);
  // n = (0.6, 0, 0.8): reach 1 |n.y| + 2 |n.(-x)| + 3 |n.z| = 0 + 1.2 + 2.4 = 3.6; signed
  // distance 0.8 * 5 + d = 4 + d.
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0, 0.8), -0.4}), true);   // 3.6
  EXPECT_INTERSECTS(box, (PlaneT<T>{v3<T>(0.6, 0, 0.8), -0.3}), false);  // 3.7
}

TYPED_TEST(Intersects, PlanePlane) {
  using T = TypeParam;
  const PlaneT<T> z0{v3<T>(0, 0, 1), 0}, z1{v3<T>(0, 0, 1), -1};
  EXPECT_INTERSECTS(z0, z1, false);  // parallel, 1 apart
  EXPECT_INTERSECTS(z1, z1, true);   // the same plane (book: false, it only checks the normals)
  // (0,0,-1).p + 1 = 0 is z = 1 again; (0,0,-1).p - 1 = 0 is z = -1.
  EXPECT_INTERSECTS(z1, (PlaneT<T>{v3<T>(0, 0, -1), 1}), true);
  EXPECT_INTERSECTS(z1, (PlaneT<T>{v3<T>(0, 0, -1), -1}), false);
  EXPECT_INTERSECTS(z0, (PlaneT<T>{v3<T>(1, 0, 0), -5}), true);
  // Turned by 1e-3 rad: not parallel (|n1 x n2| = 1e-3 >> tol), they meet about 1000 away.
  const T a = T(1e-3);
  EXPECT_INTERSECTS(z1, (PlaneT<T>{Vec3<T>(std::sin(a), 0, std::cos(a)), 0}), true);
}

TYPED_TEST(Intersects, TriangleSphere) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(1, 1, 2), 2}), true);  // the face, 2 below
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(1, 1, 2), 1.999}), false);
  // Vertex b's region: (6,-1,0) is sqrt 5 from b. The book's ClosestPoint returns a, sqrt 37
  // away, so its TriangleSphere misses this sphere.
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(6, -1, 0), std::sqrt(T(5))}), true);  // book: false
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(6, -1, 0), T(0.999) * std::sqrt(T(5))}), false);
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(2, 2, 0), 0}), true);  // a point on edge bc
}

TYPED_TEST(Intersects, TriangleAabb) {
  using T = TypeParam;
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  // The plane x + y + z = k through (k,0,0), (0,k,0), (0,0,k). The box's corner (1,1,1) has
  // x + y + z = 3 and is the triangle's centroid for k = 3: touching. Every box axis overlaps
  // ([0, k] against [-1, 1]); for k = 3.01 only the normal separates, by 0.01/sqrt3.
  const auto slab = [](double k) {
    return TriangleT<T>{v3<T>(k, 0, 0), v3<T>(0, k, 0), v3<T>(0, 0, k)};
  };
  EXPECT_INTERSECTS(slab(3), box, true);
  EXPECT_INTERSECTS(slab(3.01), box, false);
  EXPECT_INTERSECTS(slab(2), box, true);
  // In the plane z = 0, beyond the corner edge (1,1,z): edge v0 v1 lies on x + y = 2 + g.
  // x, y, z and the normal z overlap; z x (v1 - v0) is along (1,1,0), where the triangle starts
  // at 2 + g and the box ends at 2: separated by g alone.
  const auto beyond = [](double g) {
    return TriangleT<T>{v3<T>(4 + g, -2, 0), v3<T>(-2, 4 + g, 0), v3<T>(5, 5, 0)};
  };
  EXPECT_INTERSECTS(beyond(0), box, true);
  EXPECT_INTERSECTS(beyond(0.01), box, false);
  EXPECT_INTERSECTS((TriangleT<T>{v3<T>(-2, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 0, 2)}), box, true);
  EXPECT_INTERSECTS((TriangleT<T>{v3<T>(-0.5, 0, 0), v3<T>(0.5, 0, 0), v3<T>(0, 0.5, 0)}), box,
                    true);  // inside the solid box
}

// The same two configurations turned by the 3-4-5 rotation and moved to (10, 0, 0): an OBB and
// the triangles' vertices mapped by p -> R p + (10,0,0) (rounded: well within tol).
TYPED_TEST(Intersects, TriangleObb) {
  using T = TypeParam;
  const Mat3<T> r = rotation345<T>();
  const Vec3<T> at = v3<T>(10, 0, 0);
  const ObbT<T> box = cubeObb<T>(at, 1, r);
  const auto moved = [&](const TriangleT<T>& t) {
    return TriangleT<T>{r * t.a + at, r * t.b + at, r * t.c + at};
  };
  const auto slab = [&](double k) {
    return moved(TriangleT<T>{v3<T>(k, 0, 0), v3<T>(0, k, 0), v3<T>(0, 0, k)});
  };
  const auto beyond = [&](double g) {
    return moved(TriangleT<T>{v3<T>(4 + g, -2, 0), v3<T>(-2, 4 + g, 0), v3<T>(5, 5, 0)});
  };
  EXPECT_INTERSECTS(slab(3), box, true);
  EXPECT_INTERSECTS(slab(3.01), box, false);
  EXPECT_INTERSECTS(beyond(0), box, true);
  EXPECT_INTERSECTS(beyond(0.01), box, false);
}

TYPED_TEST(Intersects, TrianglePlane) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  EXPECT_INTERSECTS(tri, (PlaneT<T>{v3<T>(0, 0, 1), 0}), true);    // lies in it
  EXPECT_INTERSECTS(tri, (PlaneT<T>{v3<T>(0, 0, 1), -1}), false);  // z = 1
  EXPECT_INTERSECTS(tri, (PlaneT<T>{v3<T>(1, 0, 0), -4}), true);   // x = 4: touches b
  EXPECT_INTERSECTS(tri, (PlaneT<T>{v3<T>(1, 0, 0), -4.001}), false);
  EXPECT_INTERSECTS(tri, (PlaneT<T>{v3<T>(1, 0, 0), -2}), true);  // crosses
}

TYPED_TEST(Intersects, TriangleTriangle) {
  using T = TypeParam;
  const TriangleT<T> t1{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  // Crossing: t2's edge from (0.2,0.2,-1) to (0.2,0.2,1) pierces t1 at (0.2,0.2,0).
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.2, 0.2, -1), v3<T>(0.2, 0.2, 1), v3<T>(3, 3, 0)}),
                    true);
  // t1 moved up by 1: separated by the normal.
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0, 0, 1), v3<T>(1, 0, 1), v3<T>(0, 1, 1)}), false);
  // Two "ridges": s1 hangs below its edge (-1,0,0)-(1,0,0) in the plane y = z, s2 stands above
  // its edge (0,-1,g)-(0,1,g) in the plane x = z - g. On s1's normal (0,1,-1) s1 is 0 and s2
  // spans [-1-g, 1-g]; on s2's normal (1,0,-1) s2 is -g and s1 spans [-1, 1]: both overlap. On
  // the edge-edge axis x x y = z, s1 spans [-1, 0] and s2 [g, 1+g]: a gap of g. The edges cross
  // at the origin for g = 0; for g = -0.01 s2's edge passes through s1 at (0, -0.01, -0.01).
  const TriangleT<T> s1{v3<T>(-1, 0, 0), v3<T>(1, 0, 0), v3<T>(0, -1, -1)};
  const auto s2 = [](double g) {
    return TriangleT<T>{v3<T>(0, -1, g), v3<T>(0, 1, g), v3<T>(1, 0, 1 + g)};
  };
  EXPECT_INTERSECTS(s1, s2(0.01), false);
  EXPECT_INTERSECTS(s1, s2(0), true);
  EXPECT_INTERSECTS(s1, s2(-0.01), true);
}

// Coplanar triangles, in z = 0. t2 = (2,0,0), (4,1,0), (3,3,0) has no edge parallel to one of
// t1 = (0,0,0), (1,0,0), (0,1,0), and t1's x range [0,1] is apart from t2's [2,4]. Both normals
// are z, where both triangles project to 0, and every edge-edge cross product of two edges in
// the plane is along z too: none of the book's 11 axes separates, and its SatCrossEdge fallback
// only acts on parallel edges, so the book's TriangleTriangle and TriangleTriangleRobust report
// an intersection. The in-plane axes z x edge find the gap.
TYPED_TEST(Intersects, CoplanarTriangles) {
  using T = TypeParam;
  const TriangleT<T> t1{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(2, 0, 0), v3<T>(4, 1, 0), v3<T>(3, 3, 0)}),
                    false);  // book: true
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.2, 0.2, 0), v3<T>(2, 0.2, 0), v3<T>(0.2, 2, 0)}),
                    true);  // overlapping
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1, 0, 0), v3<T>(2, 0, 0), v3<T>(2, 1, 0)}),
                    true);  // sharing vertex (1,0,0)
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(1, 1, 0)}),
                    true);  // sharing the edge x + y = 1
  // Just beyond that edge: x + y >= 1.01 against x + y <= 1.
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1.01, 0, 0), v3<T>(0, 1.01, 0), v3<T>(1, 1, 0)}),
                    false);
  // t1 contains t2.
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.1, 0.1, 0), v3<T>(0.2, 0.1, 0), v3<T>(0.1, 0.2, 0)}),
                    true);
}

// =============================================================================================
// Named hard cases
// =============================================================================================

// Exactly parallel edges: both boxes have z as an axis, so z x z is exactly zero (skipped: the
// face axes cover it, see intersect.hpp). B is turned 45 degrees about z, so its vertical edge
// (corner (-sqrt2, 0) in its xy section) faces A's face x = 1 at c.x - sqrt2 = 1 + g.
TYPED_TEST(HardCases, ObbExactlyParallelEdges) {
  using T = TypeParam;
  const ObbT<T> a = cubeObb<T>(Vec3<T>::Zero(), 1);
  const Mat3<T> turn = rotationZ(T(0.7853981633974483));
  const T s2 = std::sqrt(T(2));
  const auto b = [&](double g) { return cubeObb<T>(Vec3<T>(1 + s2 + T(g), 0, 0), 1, turn); };
  EXPECT_INTERSECTS(a, b(0), true);  // the edge lies on the face (within the rounding of sqrt2)
  EXPECT_INTERSECTS(a, b(0.01), false);
  EXPECT_INTERSECTS(a, b(-0.01), true);
  // Identical axes: all nine edge pairs parallel, only face axes are tested.
  EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(2, 2, 2), 1), true);  // corner to corner
  EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(2, 2, 2.01), 1), false);
  EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(0.5, 0.25, -0.5), 1), true);
  EXPECT_INTERSECTS(a, a, true);  // a box against itself
}

// Nearly parallel edges: B = the 45-degree box above tilted about x by e = 1e-2 ... 1e-8 rad.
// Tilting about x leaves every x coordinate of B unchanged, so B's x range is still
// [c.x - sqrt2, c.x + sqrt2]: with c.x = 1 + sqrt2 + g the pair is separated on A's x axis by g
// for g > 0, and for g < 0 B's left edge point (1 + g, ~0, ~0) is inside A. The edge pairs (z, u2)
// are at angle e: for e = 1e-8 the cross product is below float's parallel threshold and is
// skipped, for the larger ones it is a short axis (|L| = e) that must neither produce a NaN nor a
// false separation. A second pair: B = A turned by e about a general axis, centered at
// (0.5, 0.3, 0.2) (overlapping deeply), and at (2.1, 0, 0) (separated by 0.1 - O(e) on x).
TYPED_TEST(HardCases, ObbNearlyParallelEdges) {
  using T = TypeParam;
  const ObbT<T> a = cubeObb<T>(Vec3<T>::Zero(), 1);
  const T s2 = std::sqrt(T(2));
  for (const double e : {1e-2, 1e-4, 1e-6, 1e-8}) {
    SCOPED_TRACE(e);
    const Mat3<T> tilt = rotationX(T(e)) * rotationZ(T(0.7853981633974483));
    const auto b = [&](double g) { return cubeObb<T>(Vec3<T>(1 + s2 + T(g), 0, 0), 1, tilt); };
    EXPECT_INTERSECTS(a, b(0.01), false);
    EXPECT_INTERSECTS(a, b(-0.01), true);
    EXPECT_INTERSECTS(a, b(0), true);
    const Mat3<T> turn = axisAngle(v3<T>(0.3, -0.5, 0.8), T(e));
    EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(0.5, 0.3, 0.2), 1, turn), true);
    EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(2.1, 0, 0), 1, turn), false);
    EXPECT_INTERSECTS(a, cubeObb<T>(v3<T>(1.9, 0, 0), 1, turn), true);
  }
}

// Distance exactly zero (in exact arithmetic) for faces, edges and corners of every solid pair;
// the inputs are exact binary numbers wherever the geometry allows, so most of these touch
// exactly; the rest (sqrt, rotations) touch within the rounding, which the tolerance absorbs.
TYPED_TEST(HardCases, TouchingShapes) {
  using T = TypeParam;
  const AabbT<T> box{v3<T>(0, 0, 0), v3<T>(1, 1, 1)};
  const ObbT<T> obb = cubeObb<T>(v3<T>(0.5, 0.5, 0.5), 0.5);  // the same cube as an OBB
  for (const Vec3<T>& o : {v3<T>(1, 0, 0), v3<T>(1, 1, 0), v3<T>(1, 1, 1), v3<T>(-1, 0, 0),
                           v3<T>(0, -1, -1), v3<T>(-1, -1, -1)}) {
    SCOPED_TRACE(::testing::Message() << "offset " << o.transpose());
    // Boxes moved by a face, edge or corner offset touch; 1/64 further they do not.
    const AabbT<T> moved{box.min + o, box.max + o};
    const AabbT<T> apart{box.min + o * T(1.015625), box.max + o * T(1.015625)};
    EXPECT_INTERSECTS(box, moved, true);
    EXPECT_INTERSECTS(box, apart, false);
    const ObbT<T> movedObb = cubeObb<T>(obb.center + o, 0.5);
    EXPECT_INTERSECTS(box, movedObb, true);
    EXPECT_INTERSECTS(obb, movedObb, true);
    EXPECT_INTERSECTS(obb, cubeObb<T>(obb.center + o * T(1.015625), 0.5), false);
    // Triangles through the touching feature: the face, edge or corner point of `moved`.
    const Vec3<T> p = closestPoint(box, box.center() + o);  // a point of box on the feature
    const TriangleT<T> touching{p, p + o + v3<T>(0, 0.25, 0.5), p + o + v3<T>(0.5, 0, 0.25)};
    EXPECT_INTERSECTS(touching, box, true);
    EXPECT_INTERSECTS(touching, obb, true);
    const TriangleT<T> away{p + o / 64, touching.b + o / 64, touching.c + o / 64};
    EXPECT_INTERSECTS(away, box, false);
    EXPECT_INTERSECTS(away, obb, false);
    // Spheres touching at that point, centered outward along o (|o| = 1, sqrt2 or sqrt3).
    const SphereT<T> sphere{p + o, o.norm()};
    EXPECT_INTERSECTS(sphere, box, true);
    EXPECT_INTERSECTS(sphere, obb, true);
    EXPECT_INTERSECTS(sphere, (SphereT<T>{p - o, o.norm()}), true);
    EXPECT_INTERSECTS(sphere, touching, true);
  }
  // Triangles touching at a vertex and along an edge (coplanar and not).
  const TriangleT<T> t1{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1, 0, 0), v3<T>(2, 0, 1), v3<T>(2, 1, 1)}), true);
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(1, 1, 1)}), true);
  // A vertex on the other's face.
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.25, 0.25, 0), v3<T>(1, 1, 1), v3<T>(-1, 1, 1)}),
                    true);
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.25, 0.25, 0.01), v3<T>(1, 1, 1), v3<T>(-1, 1, 1)}),
                    false);
}

// Shapes of size ~1e-2 at coordinates of 1e5. In float an ulp of 1e5 is 2^-7 = 0.0078, so every
// input here is a multiple of 2^-7 near 1e5 (exact), sizes are 2^-6 = 0.0156 and gaps 2^-7:
// a computation in absolute coordinates would round away the whole configuration, while the
// tests work on offsets from one shape (exact here by Sterbenz's lemma) and get every case right.
// The random part compares float with double on the same (float) shapes: they agree wherever the
// double answer is clear of the touching band, whose width is stated there.
TYPED_TEST(HardCases, LargeCoordinatesSmallShapes) {
  using T = TypeParam;
  const double base = 1e5, s = 1.0 / 64, u = 1.0 / 128;
  const auto at = [&](double x, double y, double z) { return v3<T>(base + x, base + y, base + z); };
  const AabbT<T> box{at(0, 0, 0), at(s, s, s)};
  EXPECT_INTERSECTS(box, (AabbT<T>{at(s, 0, 0), at(2 * s, s, s)}), true);
  EXPECT_INTERSECTS(box, (AabbT<T>{at(s + u, 0, 0), at(2 * s, s, s)}), false);
  EXPECT_INTERSECTS((SphereT<T>{at(0, 0, 0), T(s)}), (SphereT<T>{at(2 * s, 0, 0), T(s)}), true);
  EXPECT_INTERSECTS((SphereT<T>{at(0, 0, 0), T(s)}), (SphereT<T>{at(2 * s + u, 0, 0), T(s)}),
                    false);
  EXPECT_INTERSECTS((SphereT<T>{at(2 * s, s / 2, s / 2), T(s)}), box, true);  // face touch
  EXPECT_INTERSECTS((SphereT<T>{at(2 * s + u, s / 2, s / 2), T(s)}), box, false);
  // An OBB turned a quarter about z touching the box's face x = base + s, and one 2^-7 further.
  const ObbT<T> obb{at(s + s / 2, s / 2, s / 2), Vec3<T>::Constant(T(s / 2)), quarterTurnZ<T>()};
  const ObbT<T> obbApart{at(s + s / 2 + u, s / 2, s / 2), Vec3<T>::Constant(T(s / 2)),
                         quarterTurnZ<T>()};
  EXPECT_INTERSECTS(box, obb, true);
  EXPECT_INTERSECTS(box, obbApart, false);
  EXPECT_INTERSECTS(cubeObb<T>(at(s / 2, s / 2, s / 2), T(s / 2)), obbApart, false);
  const TriangleT<T> tri{at(s, 0, 0), at(2 * s, s, 0), at(2 * s, 0, s)};  // touches at a corner
  const TriangleT<T> triApart{at(s + u, 0, 0), at(2 * s, s, 0), at(2 * s, 0, s)};
  EXPECT_INTERSECTS(tri, box, true);
  EXPECT_INTERSECTS(triApart, box, false);
  EXPECT_INTERSECTS(tri, obb, true);
  EXPECT_INTERSECTS(triApart, cubeObb<T>(at(s / 2, s / 2, s / 2), T(s / 2)), false);
  EXPECT_INTERSECTS(tri, (TriangleT<T>{at(s, 0, 0), at(0, s, 0), at(0, 0, s)}), true);
  EXPECT_INTERSECTS(triApart, (TriangleT<T>{at(s, 0, 0), at(0, s, 0), at(0, 0, s)}), false);
  // Closest points: the offset to the closest point is exact (multiples of 2^-7 near 1e5).
  EXPECT_EQ(closestPoint(tri, at(0, 0, 0)), at(s, 0, 0));
  EXPECT_EQ(closestPoint(obb, at(0, s / 2, s / 2)), at(s, s / 2, s / 2));
  EXPECT_TRUE(contains(obb, at(s, s / 2, s / 2)));
  // 2^-7 outside is within the rounding allowance of a point at 1e5 (eps * 1e5 = 0.012 in float,
  // see point_tests.hpp); 2^-6 outside is not.
  EXPECT_FALSE(contains(obb, at(s - 2 * u, s / 2, s / 2)));
  EXPECT_TRUE(contains(seg(at(0, 0, 0), at(s, s, 0)), at(s / 2, s / 2, 0)));
  EXPECT_FALSE(contains(seg(at(0, 0, 0), at(s, s, 0)), at(s / 2, s / 2, 2 * u)));
}

// Shapes of size 1e-6 near the origin: every tolerance is relative, so gaps of 1e-8 (1% of the
// size) separate and touching still intersects.
TYPED_TEST(HardCases, TinyShapes) {
  using T = TypeParam;
  const double k = 1e-6, g = 1e-8;
  const AabbT<T> box{v3<T>(0, 0, 0), v3<T>(k, k, k)};
  EXPECT_INTERSECTS(box, (AabbT<T>{v3<T>(k, 0, 0), v3<T>(2 * k, k, k)}), true);
  EXPECT_INTERSECTS(box, (AabbT<T>{v3<T>(k + g, 0, 0), v3<T>(2 * k, k, k)}), false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, 0, 0), T(k)}), (SphereT<T>{v3<T>(2 * k, 0, 0), T(k)}),
                    true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(0, 0, 0), T(k)}), (SphereT<T>{v3<T>(2 * k + g, 0, 0), T(k)}),
                    false);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2 * k, k / 2, k / 2), T(k)}), box, true);
  EXPECT_INTERSECTS((SphereT<T>{v3<T>(2 * k + g, k / 2, k / 2), T(k)}), box, false);
  // The ridge configuration scaled by 1e-6 (cube of half 1e-6 at the origin).
  const auto scaled = [&](ObbT<T> b) {
    b.center *= T(k);
    b.halfExtents *= T(k);
    return b;
  };
  const ObbT<T> cube = scaled(cubeObb<T>(Vec3<T>::Zero(), 1));
  EXPECT_INTERSECTS(cube, scaled(ridgeBox<T>(0.01)), false);
  EXPECT_INTERSECTS(cube, scaled(ridgeBox<T>(0)), true);
  EXPECT_INTERSECTS(cube, scaled(ridgeBox<T>(-0.01)), true);
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(k, 0, 0), v3<T>(0, k, 0)};
  EXPECT_INTERSECTS(tri, (TriangleT<T>{v3<T>(k, 0, 0), v3<T>(2 * k, 0, k), v3<T>(2 * k, k, k)}),
                    true);
  EXPECT_INTERSECTS(tri, (TriangleT<T>{v3<T>(k + g, 0, 0), v3<T>(2 * k, 0, k), v3<T>(2 * k, k, k)}),
                    false);
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(k / 4, k / 4, k), T(k)}), true);
  EXPECT_INTERSECTS(tri, (SphereT<T>{v3<T>(k / 4, k / 4, k + g), T(k)}), false);
  EXPECT_INTERSECTS(tri, box, true);
  EXPECT_TRUE(contains(tri, v3<T>(k / 4, k / 4, 0)));
  EXPECT_FALSE(contains(tri, v3<T>(k / 4, k / 4, g)));
  EXPECT_TRUE(
      closeTo(closestPoint(tri, v3<T>(k, k, k)), v3<double>(k / 2, k / 2, 0), 4 * kEps<T> * k));
  EXPECT_FALSE(contains(seg(v3<T>(0, 0, 0), v3<T>(k, 0, 0)), v3<T>(k / 2, g, 0)));
}

// Degenerate triangles (collinear or coincident vertices) against every shape.
TYPED_TEST(HardCases, DegenerateTriangles) {
  using T = TypeParam;
  // The segment x + y = 2, z = 0 from (2,0,0) to (0,2,0) (third vertex in the middle) touches
  // the cube [-1,1]^3 at its edge point (1,1,0); moved out by 0.01 along x it does not.
  const auto diagonal = [](double g) {
    return TriangleT<T>{v3<T>(2 + g, 0, 0), v3<T>(g, 2, 0), v3<T>(1 + g, 1, 0)};
  };
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  EXPECT_INTERSECTS(diagonal(0), box, true);
  EXPECT_INTERSECTS(diagonal(0.01), box, false);
  EXPECT_INTERSECTS(diagonal(0), cubeObb<T>(Vec3<T>::Zero(), 1, rotationZ(T(0.0))), true);
  EXPECT_INTERSECTS(diagonal(0.01), cubeObb<T>(Vec3<T>::Zero(), 1), false);
  EXPECT_INTERSECTS(diagonal(0), (SphereT<T>{v3<T>(0, 0, 0), std::sqrt(T(2))}), true);
  EXPECT_INTERSECTS(diagonal(0), (SphereT<T>{v3<T>(0, 0, 0), T(1.41)}), false);
  EXPECT_INTERSECTS(diagonal(0), (PlaneT<T>{v3<T>(1, 0, 0), -2}), true);
  EXPECT_INTERSECTS(diagonal(0), (PlaneT<T>{v3<T>(1, 0, 0), -2.01}), false);
  // Against a proper triangle: t1 = x + y <= 1 in z = 0. The coplanar segment x + y = 1 touches
  // it along its edge; x + y = 1.01 is apart (found by the in-plane axes n1 x e).
  const TriangleT<T> t1{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(0.5, 0.5, 0)}), true);
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(1.01, 0, 0), v3<T>(0, 1.01, 0), v3<T>(0.5, 0.51, 0)}),
                    false);
  // A segment through t1's interior, and the same segment moved outside.
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(0.2, 0.2, -1), v3<T>(0.2, 0.2, 1), v3<T>(0.2, 0.2, 0)}),
                    true);
  EXPECT_INTERSECTS(t1, (TriangleT<T>{v3<T>(2, 2, -1), v3<T>(2, 2, 1), v3<T>(2, 2, 0)}), false);
  // A point inside t1, and outside.
  const auto point = [](double x, double y, double z) {
    return TriangleT<T>{v3<T>(x, y, z), v3<T>(x, y, z), v3<T>(x, y, z)};
  };
  EXPECT_INTERSECTS(t1, point(0.25, 0.25, 0), true);
  EXPECT_INTERSECTS(t1, point(1, 1, 0), false);
  EXPECT_INTERSECTS(box, point(1, 1, 1), true);
  EXPECT_INTERSECTS(box, point(1, 1, 1.01), false);
  // Two degenerate triangles: crossing segments, the same 0.01 apart, collinear segments apart
  // (only the axis along the line separates these) and touching, points.
  const TriangleT<T> xs{v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(1, 0, 0)};
  EXPECT_INTERSECTS(xs, (TriangleT<T>{v3<T>(1, -1, 0), v3<T>(1, 1, 0), v3<T>(1, 0, 0)}), true);
  EXPECT_INTERSECTS(xs, (TriangleT<T>{v3<T>(1, -1, 0.01), v3<T>(1, 1, 0.01), v3<T>(1, 0, 0.01)}),
                    false);
  EXPECT_INTERSECTS(xs, (TriangleT<T>{v3<T>(3, 0, 0), v3<T>(4, 0, 0), v3<T>(3.5, 0, 0)}), false);
  EXPECT_INTERSECTS(xs, (TriangleT<T>{v3<T>(2, 0, 0), v3<T>(4, 0, 0), v3<T>(3, 0, 0)}), true);
  EXPECT_INTERSECTS(point(1, 2, 3), point(1, 2, 3), true);
  EXPECT_INTERSECTS(point(1, 2, 3), point(1, 2, 3.01), false);
  EXPECT_INTERSECTS(xs, point(1.5, 0, 0), true);
}

// Zero-size boxes are points, flat ones rectangles.
TYPED_TEST(HardCases, ZeroSizeBoxes) {
  using T = TypeParam;
  const AabbT<T> point{v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  EXPECT_INTERSECTS(point, point, true);
  EXPECT_INTERSECTS(point, (AabbT<T>{v3<T>(0, 0, 0), v3<T>(1, 1, 1)}), true);
  EXPECT_INTERSECTS(point, (AabbT<T>{v3<T>(0, 0, 0), v3<T>(1, 1, 0.99)}), false);
  EXPECT_INTERSECTS(point, (SphereT<T>{v3<T>(1, 1, 3), 2}), true);
  EXPECT_INTERSECTS(point, (SphereT<T>{v3<T>(1, 1, 3), 1.99}), false);
  // Turned by the 3-4-5 rotation about z and centered at (2.5,1,1): the point's local
  // coordinates are R^T (-1.5, 0, 0) = (-0.9, 1.2, 0), outside (1.2 > 1); at (2,1,1) they are
  // (-0.6, 0.8, 0), inside.
  EXPECT_INTERSECTS(point, cubeObb<T>(v3<T>(2.5, 1, 1), 1, rotation345<T>()), false);
  EXPECT_INTERSECTS(point, cubeObb<T>(v3<T>(2, 1, 1), 1, rotation345<T>()), true);
  EXPECT_INTERSECTS(point, cubeObb<T>(v3<T>(2, 1, 1), 1), true);  // on its face x = 1
  EXPECT_INTERSECTS(point, (PlaneT<T>{v3<T>(0, 0, 1), -1}), true);
  EXPECT_INTERSECTS(point, (PlaneT<T>{v3<T>(0, 0, 1), -1.01}), false);
  EXPECT_INTERSECTS(point, (TriangleT<T>{v3<T>(0, 0, 1), v3<T>(4, 0, 1), v3<T>(0, 4, 1)}), true);
  EXPECT_INTERSECTS(point, (TriangleT<T>{v3<T>(0, 0, 1), v3<T>(1.9, 0, 1), v3<T>(0, 1.9, 1)}),
                    false);
  // A zero-size OBB against a cube: touching at x = 1, apart at 1.001.
  const ObbT<T> cube = cubeObb<T>(Vec3<T>::Zero(), 1);
  EXPECT_INTERSECTS(cube, (ObbT<T>{v3<T>(1, 0, 0), Vec3<T>::Zero(), rotation345<T>()}), true);
  EXPECT_INTERSECTS(cube, (ObbT<T>{v3<T>(1.001, 0, 0), Vec3<T>::Zero(), rotation345<T>()}), false);
  // A flat box [0,1]^2 x {0} and a coplanar triangle in x + y >= 2 touching its corner (1,1,0),
  // then moved 0.01 out: separated only in the plane (by z x edge, see intersect.hpp).
  const AabbT<T> flat{v3<T>(0, 0, 0), v3<T>(1, 1, 0)};
  EXPECT_INTERSECTS(flat, (TriangleT<T>{v3<T>(2, 0, 0), v3<T>(0, 2, 0), v3<T>(2, 2, 0)}), true);
  EXPECT_INTERSECTS(
      flat, (TriangleT<T>{v3<T>(2.01, 0.01, 0), v3<T>(0.01, 2.01, 0), v3<T>(2, 2, 0)}), false);
  const ObbT<T> flatObb{v3<T>(0.5, 0.5, 0), v3<T>(0.5, 0.5, 0), Mat3<T>::Identity()};
  EXPECT_INTERSECTS(flatObb, (TriangleT<T>{v3<T>(2, 0, 0), v3<T>(0, 2, 0), v3<T>(2, 2, 0)}), true);
  EXPECT_INTERSECTS(
      flatObb, (TriangleT<T>{v3<T>(2.01, 0.01, 0), v3<T>(0.01, 2.01, 0), v3<T>(2, 2, 0)}), false);
  EXPECT_INTERSECTS(flatObb, (AabbT<T>{v3<T>(1, 1, 0), v3<T>(2, 2, 0)}), true);
}

}  // namespace
}  // namespace simdphys

// Tests of include/simdphys/geometry3d/point_tests.hpp (containment, closest points, barycentric
// coordinates, closest points of segments) and intersect.hpp (shape-versus-shape tests), in float
// and in double.
//
// - Hand-worked cases: every expected value is derived in the comment beside it, never taken
//   from a run. Where the book's code (Code/Geometry3D.cpp) gives a different answer, the comment
//   says so ("book: ...").
// - Properties on random inputs from fixed seeds: closest points against dense sampling of the
//   shape; intersections against double-precision oracles written here (a separating-axis gap
//   over normalised axes for boxes, closest-point distances for spheres and triangles, corner
//   signs for planes) and against point sampling; every intersects() in both orders.
// - Named hard cases: parallel and nearly parallel OBB edges, touching shapes, 1e5 coordinates
//   with 1e-2 sizes, 1e-6 shapes, degenerate triangles, zero-size boxes.
//
// Tolerances. eps is the machine epsilon of the scalar type (1.19e-7 float, 2.22e-16 double);
// tol = kGeometryTolerance = 16 eps is the library's touching tolerance. A value that is exact in
// binary and computed exactly is compared with EXPECT_EQ; otherwise the tolerance is stated
// beside the assertion.
#include "geometry3d_cases.hpp"

namespace simdphys {
namespace {

using namespace test;

// =============================================================================================
// Point tests: containment and closest point
// =============================================================================================

TYPED_TEST(PointTests, SphereContainsAndClosestPoint) {
  using T = TypeParam;
  const SphereT<T> s{v3<T>(1, 2, 3), 2};
  // (1,2,5) is 2 from the center: on the surface, contained (book: PointInSphere uses <, false).
  EXPECT_TRUE(contains(s, v3<T>(1, 2, 5)));
  // 2.001 from the center: outside by 1e-3, far beyond tol * 2 (3.8e-6 in float).
  EXPECT_FALSE(contains(s, v3<T>(1, 2, 5.001)));
  EXPECT_TRUE(contains(s, s.center));
  // (2.2, 3.6, 3) - c = (1.2, 1.6, 0), length 2: on the surface (decimals round: within tol).
  EXPECT_TRUE(contains(s, v3<T>(2.2, 3.6, 3)));

  // Outside: p - c = (3, 4, 0), |.| = 5, so the closest point is c + (3,4,0) * 2/5 = (2.2, 3.6, 3).
  // Tolerance: a few roundings of values up to 4: 8 eps * 4.
  EXPECT_TRUE(closeTo(closestPoint(s, v3<T>(4, 6, 3)), v3<double>(2.2, 3.6, 3), 32 * kEps<T>));
  // Inside points are their own closest point (solid ball), exactly. The book projects them to
  // the surface, and for the center normalises a zero vector (NaN).
  EXPECT_EQ(closestPoint(s, v3<T>(1.5, 2, 3)), v3<T>(1.5, 2, 3));
  EXPECT_EQ(closestPoint(s, s.center), s.center);

  // Zero radius: the sphere is its center.
  const SphereT<T> point{v3<T>(1, 2, 3), 0};
  EXPECT_TRUE(contains(point, v3<T>(1, 2, 3)));
  EXPECT_FALSE(contains(point, v3<T>(1, 2, 3.001)));
  EXPECT_EQ(closestPoint(point, v3<T>(5, 5, 5)), v3<T>(1, 2, 3));  // c + d * 0 = c exactly
}

TYPED_TEST(PointTests, AabbContainsAndClosestPoint) {
  using T = TypeParam;
  const AabbT<T> box{v3<T>(-1, 0, 2), v3<T>(3, 1, 4)};
  EXPECT_TRUE(contains(box, v3<T>(3, 1, 4)));       // corner: closed
  EXPECT_TRUE(contains(box, v3<T>(-1, 0.5, 3)));    // on the face x = -1
  EXPECT_FALSE(contains(box, v3<T>(3, 1, 4.001)));  // exact test: any excess is outside
  EXPECT_FALSE(contains(box, v3<T>(-1.001, 0.5, 3)));
  // Closest points clamp each coordinate into [min, max]: exact.
  EXPECT_EQ(closestPoint(box, v3<T>(5, -2, 3)), v3<T>(3, 0, 3));
  EXPECT_EQ(closestPoint(box, v3<T>(-7, 9, 10)), v3<T>(-1, 1, 4));
  EXPECT_EQ(closestPoint(box, v3<T>(0, 0.5, 3)), v3<T>(0, 0.5, 3));  // inside: itself

  // Zero-size box: a point.
  const AabbT<T> point{v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  EXPECT_TRUE(contains(point, v3<T>(1, 1, 1)));
  EXPECT_FALSE(contains(point, v3<T>(1, 1, 1.0001)));
  EXPECT_EQ(closestPoint(point, v3<T>(0, 0, 0)), v3<T>(1, 1, 1));
}

// The book's ClosestPoint(AABB) clamps y and z against min.x and max.x. For this box
// (min.x = -1, max.x = 3): y = 2 is neither < -1 nor > 3, so the book keeps y = 2, outside the
// box's y range [0, 1]; z = 1 likewise stays 1, below min.z = 2.
TYPED_TEST(PointTests, AabbClosestPointClampsEachAxisToItsOwnBounds) {
  using T = TypeParam;
  const AabbT<T> box{v3<T>(-1, 0, 2), v3<T>(3, 1, 4)};
  EXPECT_EQ(closestPoint(box, v3<T>(0, 2, 3)), v3<T>(0, 1, 3));      // book: (0, 2, 3)
  EXPECT_EQ(closestPoint(box, v3<T>(0, 0.5, 1)), v3<T>(0, 0.5, 2));  // book: (0, 0.5, 1)
}

TYPED_TEST(PointTests, ObbContainsAndClosestPoint) {
  using T = TypeParam;
  // A quarter turn about z: local x is world +y, local y is world -x.
  const ObbT<T> box{v3<T>(1, 1, 0), v3<T>(2, 1, 0.5), quarterTurnZ<T>()};
  // p = (1,4,0): p - c = (0,3,0), local (3, 0, 0): outside (3 > 2); clamped local (2, 0, 0) is
  // c + 2 (0,1,0) = (1, 3, 0). All entries are small integers: exact.
  EXPECT_FALSE(contains(box, v3<T>(1, 4, 0)));
  EXPECT_EQ(closestPoint(box, v3<T>(1, 4, 0)), v3<T>(1, 3, 0));
  EXPECT_TRUE(contains(box, v3<T>(1, 3, 0)));  // on the face local x = 2
  // The corner local (2, 1, 0.5) is c + 2 (0,1,0) + (-1,0,0) + 0.5 z = (0, 3, 0.5).
  EXPECT_TRUE(contains(box, v3<T>(0, 3, 0.5)));
  EXPECT_FALSE(contains(box, v3<T>(0, 3, 0.51)));
  // p = (3,1,0): local (0, -2, 0), clamped (0, -1, 0): c - (-1,0,0) = (2, 1, 0).
  EXPECT_FALSE(contains(box, v3<T>(3, 1, 0)));
  EXPECT_EQ(closestPoint(box, v3<T>(3, 1, 0)), v3<T>(2, 1, 0));
  EXPECT_EQ(closestPoint(box, v3<T>(1.5, 1.5, 0.25)), v3<T>(1.5, 1.5, 0.25));  // inside

  // The 3-4-5 rotation, unit cube at the origin: p = (3,4,0) has local (0.6*3 + 0.8*4,
  // -0.8*3 + 0.6*4, 0) = (5, 0, 0); clamped (1, 0, 0) is the first axis (0.6, 0.8, 0).
  // Tolerance: 0.6 and 0.8 round, and the local coordinates are sums of products of size 5:
  // 16 eps * 5.
  const ObbT<T> turned = cubeObb<T>(Vec3<T>::Zero(), 1, rotation345<T>());
  EXPECT_TRUE(closeTo(closestPoint(turned, v3<T>(3, 4, 0)), v3<double>(0.6, 0.8, 0), 80 * kEps<T>));
  EXPECT_TRUE(contains(turned, v3<T>(0.6, 0.8, 0)));                   // on a face, within tol
  EXPECT_FALSE(contains(turned, v3<T>(0.6 * 1.001, 0.8 * 1.001, 0)));  // 1e-3 out
}

TYPED_TEST(PointTests, PlaneContainsAndClosestPoint) {
  using T = TypeParam;
  // 0.6 x + 0.8 z = 2.
  const PlaneT<T> plane{v3<T>(0.6, 0, 0.8), -2};
  // (2, 5, 1): 1.2 + 0.8 - 2 = 0, on the plane (0.6, 0.8 round: error ~ eps (|p| + |d|) << tol).
  EXPECT_TRUE(contains(plane, v3<T>(2, 5, 1)));
  // 1e-3 along the normal: off the plane by 1e-3 >> tol * (|p| + |d|) = 16 eps * 7.5.
  EXPECT_FALSE(contains(plane, v3<T>(2 + 0.6e-3, 5, 1 + 0.8e-3)));
  // The origin has signed distance -2; its projection is 0 + 2 n = (1.2, 0, 1.6). Tolerance:
  // rounding of 0.6, 0.8 and of the products: 4 eps * 2.
  EXPECT_TRUE(closeTo(closestPoint(plane, v3<T>(0, 0, 0)), v3<double>(1.2, 0, 1.6), 8 * kEps<T>));
  // A point on the plane projects onto itself (signed distance 0 exactly for (5, -1, 0) and n = x,
  // d = -5).
  const PlaneT<T> xPlane{v3<T>(1, 0, 0), -5};
  EXPECT_EQ(closestPoint(xPlane, v3<T>(5, -1, 7)), v3<T>(5, -1, 7));
  EXPECT_EQ(closestPoint(xPlane, v3<T>(9, -1, 7)), v3<T>(5, -1, 7));
}

TYPED_TEST(PointTests, SegmentContainsAndClosestPoint) {
  using T = TypeParam;
  const SegmentT<T> s{v3<T>(0, 0, 0), v3<T>(4, 0, 0)};
  // t = (p - start).d / |d|^2: (2*4)/16 = 0.5 -> (2,0,0); -4/16 -> clamped 0; 24/16 -> 1. Exact.
  EXPECT_EQ(closestPoint(s, v3<T>(2, 3, 0)), v3<T>(2, 0, 0));
  EXPECT_EQ(closestPoint(s, v3<T>(-1, 1, 0)), v3<T>(0, 0, 0));
  EXPECT_EQ(closestPoint(s, v3<T>(6, 0, 1)), v3<T>(4, 0, 0));
  EXPECT_TRUE(contains(s, v3<T>(2, 0, 0)));
  EXPECT_TRUE(contains(s, v3<T>(4, 0, 0)));
  EXPECT_FALSE(contains(s, v3<T>(2, 1e-3, 0)));  // 1e-3 off >> tol * 4 (7.6e-6 in float)
  EXPECT_FALSE(contains(s, v3<T>(4.001, 0, 0)));
  // A zero-length segment is its point; no division by zero.
  const SegmentT<T> point{v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  EXPECT_EQ(closestPoint(point, v3<T>(7, -3, 2)), v3<T>(1, 1, 1));
  EXPECT_TRUE(contains(point, v3<T>(1, 1, 1)));
  EXPECT_FALSE(contains(point, v3<T>(1, 1, 1.001)));
}

// The book's PointOnLine compares the squared distance with 0 within FLT_EPSILON: an absolute
// distance of 3.4e-4, whatever the segment's size. A segment of length 1e-6 and a point 1e-4
// off it (a hundred times its length) would be "on" it; here the tolerance is relative.
TYPED_TEST(PointTests, SegmentContainsIsRelativeToItsSize) {
  using T = TypeParam;
  const SegmentT<T> tiny{v3<T>(0, 0, 0), v3<T>(1e-6, 0, 0)};
  EXPECT_FALSE(contains(tiny, v3<T>(0.5e-6, 1e-4, 0)));  // book: true
  EXPECT_FALSE(contains(tiny, v3<T>(0.5e-6, 1e-8, 0)));  // 1e-8 >> tol * 1e-6
  EXPECT_TRUE(contains(tiny, v3<T>(0.5e-6, 0, 0)));
}

TYPED_TEST(PointTests, RayContainsAndClosestPoint) {
  using T = TypeParam;
  const RayT<T> ray{v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_EQ(closestPoint(ray, v3<T>(1, -5, 0)), v3<T>(1, 0, 0));  // behind: the origin
  EXPECT_EQ(closestPoint(ray, v3<T>(3, 4, 0)), v3<T>(1, 4, 0));   // t = 4
  EXPECT_EQ(closestPoint(ray, v3<T>(1, 4, 7)), v3<T>(1, 4, 0));
  EXPECT_TRUE(contains(ray, v3<T>(1, 0, 0)));
  EXPECT_TRUE(contains(ray, v3<T>(1, 100, 0)));
  EXPECT_FALSE(contains(ray, v3<T>(1, -0.001, 0)));  // behind the origin
}

// The book's PointOnRay compares the cosine of the angle between p - origin and the direction
// with 1 within FLT_EPSILON. For p 1000 along the ray and 0.2 off it the cosine is
// 1000 / sqrt(1000^2 + 0.04) = 1 - 2e-8, within FLT_EPSILON of 1: "on the ray". Here the allowed
// distance is tol * |p - origin| = 1.9e-3 in float at 1000, 3.6e-12 in double.
TYPED_TEST(PointTests, RayContainsIsADistanceNotAnAngle) {
  using T = TypeParam;
  const RayT<T> ray{v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_FALSE(contains(ray, v3<T>(1.2, 1000, 0)));  // book: true
  EXPECT_TRUE(contains(ray, v3<T>(1, 1000, 0)));
}

// Triangle (0,0,0), (4,0,0), (0,4,0) in the plane z = 0; one point in each of Ericson's seven
// regions, each projected by hand.
TYPED_TEST(PointTests, TriangleClosestPointInEachRegion) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  // Vertex a: (p - a).(b - a) = -4 <= 0 and (p - a).(c - a) = -4 <= 0.
  EXPECT_EQ(closestPoint(tri, v3<T>(-1, -1, 2)), v3<T>(0, 0, 0));
  // Vertex c: (p - c).(c - a) = 8 >= 0, (p - c).(b - c) = -4 - 8 < 0.
  EXPECT_EQ(closestPoint(tri, v3<T>(-1, 6, -3)), v3<T>(0, 4, 0));
  // Edge ab: the foot (2, 0, 0) of (2,-3,1) lies inside ab, and p is below the line y = 0.
  EXPECT_EQ(closestPoint(tri, v3<T>(2, -3, 1)), v3<T>(2, 0, 0));
  // Edge ca: foot (0, 1, 0).
  EXPECT_EQ(closestPoint(tri, v3<T>(-2, 1, 0)), v3<T>(0, 1, 0));
  // Edge bc (x + y = 4): (3,3,5) - (2,2,0) = (1,1,5) is perpendicular to bc = (-4,4,0); the
  // parameter is (d4 - d3) / ((d4 - d3) + (d5 - d6)) = 16 / 32 = 0.5: b + 0.5 (c - b).
  EXPECT_EQ(closestPoint(tri, v3<T>(3, 3, 5)), v3<T>(2, 2, 0));
  // Face: straight down. Weights v = w = 64/256 = 0.25, offset 0.25 (4,0,0) + 0.25 (0,4,0).
  EXPECT_EQ(closestPoint(tri, v3<T>(1, 1, 7)), v3<T>(1, 1, 0));
}

// The book's ClosestPoint(Triangle) takes the closest point of each edge and returns c1 if its
// distance is strictly smallest, else c2 if strictly smallest, else c3 (edge ca). For p = (6,-1,0)
// in the vertex region of b, edges ab and bc both give b at squared distance 5 and ca gives a at
// 37: neither strict test holds and the book returns a = (0,0,0). The closest point is b.
TYPED_TEST(PointTests, TriangleClosestPointInTheVertexRegionOfB) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  EXPECT_EQ(closestPoint(tri, v3<T>(6, -1, 0)), v3<T>(4, 0, 0));  // book: (0, 0, 0)
  // The same tie happens off the plane: (6, -1, 3) projects to (6, -1, 0).
  EXPECT_EQ(closestPoint(tri, v3<T>(6, -1, 3)), v3<T>(4, 0, 0));
}

TYPED_TEST(PointTests, TriangleContains) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  EXPECT_TRUE(contains(tri, v3<T>(1, 1, 0)));    // inside
  EXPECT_TRUE(contains(tri, v3<T>(4, 0, 0)));    // vertex
  EXPECT_TRUE(contains(tri, v3<T>(2, 2, 0)));    // on edge bc
  EXPECT_TRUE(contains(tri, v3<T>(0, 2.5, 0)));  // on edge ca
  // 0.01 beyond edge bc, 1e-3 above the plane: both >> tol * 4.
  EXPECT_FALSE(contains(tri, v3<T>(2.01, 2, 0)));
  EXPECT_FALSE(contains(tri, v3<T>(1, 1, 0.001)));
  EXPECT_FALSE(contains(tri, v3<T>(-0.001, 1, 0)));
}

// Collinear and coincident vertices: the triangle is the segment of its longest edge or a point.
TYPED_TEST(PointTests, DegenerateTriangleClosestPointAndContains) {
  using T = TypeParam;
  // (0,0,0), (2,0,0), (1,0,0): the segment [0, 2] on the x axis.
  const TriangleT<T> line{v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(1, 0, 0)};
  EXPECT_EQ(closestPoint(line, v3<T>(1.5, 1, 0)), v3<T>(1.5, 0, 0));  // on ab at t = 0.75
  EXPECT_EQ(closestPoint(line, v3<T>(3, 1, 0)), v3<T>(2, 0, 0));
  EXPECT_EQ(closestPoint(line, v3<T>(-1, 0, 5)), v3<T>(0, 0, 0));
  EXPECT_TRUE(contains(line, v3<T>(0.5, 0, 0)));
  EXPECT_TRUE(contains(line, v3<T>(1, 0, 0)));
  EXPECT_FALSE(contains(line, v3<T>(0.5, 0.01, 0)));
  EXPECT_FALSE(contains(line, v3<T>(2.01, 0, 0)));
  // All three vertices at (1,2,3): a point.
  const TriangleT<T> point{v3<T>(1, 2, 3), v3<T>(1, 2, 3), v3<T>(1, 2, 3)};
  EXPECT_EQ(closestPoint(point, v3<T>(4, 4, 4)), v3<T>(1, 2, 3));
  EXPECT_TRUE(contains(point, v3<T>(1, 2, 3)));
  EXPECT_FALSE(contains(point, v3<T>(1, 2, 3.001)));
  // Two coincident vertices: the segment (0,0,0)-(0,0,2).
  const TriangleT<T> twice{v3<T>(0, 0, 0), v3<T>(0, 0, 0), v3<T>(0, 0, 2)};
  EXPECT_EQ(closestPoint(twice, v3<T>(3, 0, 1)), v3<T>(0, 0, 1));
  for (const Vec3<T>& q :
       {closestPoint(line, v3<T>(0.3, 7, -2)), closestPoint(twice, v3<T>(1, 1, 9))})
    EXPECT_TRUE(q.allFinite());
}

// =============================================================================================
// Barycentric coordinates
// =============================================================================================

TYPED_TEST(PointTests, Barycentric) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(0, 4, 0)};
  // In this triangle v = x/4, w = y/4, u = 1 - v - w; the signed-area ratios are exact here
  // (n = (0,0,16), |n|^2 = 256, every cross product has small integer entries).
  EXPECT_EQ(barycentric(tri, v3<T>(1, 2, 0)), v3<T>(0.25, 0.25, 0.5));
  EXPECT_EQ(barycentric(tri, v3<T>(1, 2, 5)), v3<T>(0.25, 0.25, 0.5));   // off the plane: projected
  EXPECT_EQ(barycentric(tri, v3<T>(5, 1, 0)), v3<T>(-0.5, 1.25, 0.25));  // outside: u < 0
  EXPECT_EQ(barycentric(tri, tri.a), v3<T>(1, 0, 0));
  EXPECT_EQ(barycentric(tri, tri.b), v3<T>(0, 1, 0));
  EXPECT_EQ(barycentric(tri, tri.c), v3<T>(0, 0, 1));
  // A triangle not in a coordinate plane: its centroid has weights 1/3 (tolerance: a few
  // roundings of values of order 1: 8 eps).
  const TriangleT<T> slanted{v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(0, 0, 1)};
  EXPECT_TRUE(closeTo(barycentric(slanted, v3<T>(1.0 / 3, 1.0 / 3, 1.0 / 3)),
                      v3<double>(1.0 / 3, 1.0 / 3, 1.0 / 3), 8 * kEps<T>));
}

// A thin triangle a = (0,0,0), b = (1,0,0), c = (0.5, h, 0) with h = 1e-4, and p = (0.5, h/2, 0):
// p = u a + v b + w c gives h w = h/2 and v + 0.5 w = 0.5, so (u, v, w) = (0.25, 0.25, 0.5).
// The usual Gram form divides by d00 d11 - d01^2 = 1 * (0.25 + h^2) - 0.5^2 = h^2 = 1e-8, which
// in float is lost: 0.25 + 1e-8 rounds to 0.25 (ulp 3e-8), the determinant is 0 and the book's
// BarycentricOptimized returns (0,0,0). The signed areas keep full relative precision: tolerance
// 8 eps.
TYPED_TEST(PointTests, BarycentricOfAThinTriangle) {
  using T = TypeParam;
  const T h = T(1e-4);
  const TriangleT<T> thin{v3<T>(0, 0, 0), v3<T>(1, 0, 0), Vec3<T>(T(0.5), h, 0)};
  EXPECT_TRUE(closeTo(barycentric(thin, Vec3<T>(T(0.5), h / 2, 0)), v3<double>(0.25, 0.25, 0.5),
                      8 * kEps<T>));
}

// Degenerate triangles: the coordinates along the longest edge, 0 on the third vertex; a point
// gives (1, 0, 0).
TYPED_TEST(PointTests, BarycentricOfDegenerateTriangles) {
  using T = TypeParam;
  // Longest edge ab = [0, 4] on x: t = p.x / 4.
  const TriangleT<T> ab{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(1, 0, 0)};
  EXPECT_EQ(barycentric(ab, v3<T>(1, 0, 0)), v3<T>(0.75, 0.25, 0));  // c itself, by position
  EXPECT_EQ(barycentric(ab, v3<T>(6, 3, 0)), v3<T>(-0.5, 1.5, 0));   // unclamped, projected
  // Longest edge bc: a = (1,0,0), b = (0,0,0), c = (4,0,0); p = (2,0,0) is halfway along bc.
  const TriangleT<T> bc{v3<T>(1, 0, 0), v3<T>(0, 0, 0), v3<T>(4, 0, 0)};
  EXPECT_EQ(barycentric(bc, v3<T>(2, 0, 0)), v3<T>(0, 0.5, 0.5));
  // Longest edge ca: a = (0,0,0), b = (1,0,0), c = (4,0,0); p = (2,5,0) projects to x = 2.
  const TriangleT<T> ca{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(4, 0, 0)};
  EXPECT_EQ(barycentric(ca, v3<T>(2, 5, 0)), v3<T>(0.5, 0, 0.5));
  const TriangleT<T> point{v3<T>(1, 2, 3), v3<T>(1, 2, 3), v3<T>(1, 2, 3)};
  EXPECT_EQ(barycentric(point, v3<T>(7, 7, 7)), v3<T>(1, 0, 0));
}

// =============================================================================================
// Closest points of two segments
// =============================================================================================

TYPED_TEST(SegmentPairs, SkewSegments) {
  using T = TypeParam;
  // x axis [0,2] and the line x = 1, z = 1 along y: closest (1,0,0) and (1,0,1), s = t = 0.5.
  // With n = d1 x d2 = (0,0,4): s = (r x d2).n / 16 = 8/16, t = (r x d1).n / 16 = 8/16. Exact.
  auto c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(2, 0, 0)), seg(v3<T>(1, -1, 1), v3<T>(1, 1, 1)));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(1, 0, 1));
  EXPECT_EQ(c.s, T(0.5));
  EXPECT_EQ(c.t, T(0.5));
  EXPECT_EQ(c.distance, T(1));
  // Moved so the lines' closest point is beyond the first segment's end (s = 2 on the lines):
  // the closest pair is the end (1,0,0) and (2,0,1), distance sqrt 2.
  c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(1, 0, 0)), seg(v3<T>(2, -1, 1), v3<T>(2, 1, 1)));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(2, 0, 1));
  EXPECT_EQ(c.s, T(1));
  EXPECT_EQ(c.t, T(0.5));
  EXPECT_TRUE(closeTo(c.distance, std::sqrt(2.0), 2 * kEps<T>));
  // An endpoint against an interior point: (1,0,0) and (2,0,0).
  c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(1, 0, 0)), seg(v3<T>(2, -1, 0), v3<T>(2, 1, 0)));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(2, 0, 0));
  EXPECT_EQ(c.distance, T(1));
}

TYPED_TEST(SegmentPairs, ParallelSegments) {
  using T = TypeParam;
  // Overlapping: x in [0,4] at y = 0 and x in [1,3] at y = 2. Every pair with equal x in [1,3]
  // is closest (distance 2). Candidates, in order: s = 0 -> (0,0,0)-(1,2,0), sqrt 5; s = 1 ->
  // (4,0,0)-(3,2,0), sqrt 5; t = 0 -> (1,0,0)-(1,2,0), 2 (kept); t = 1 -> (3,0,0)-(3,2,0), 2
  // (a tie keeps the first).
  auto c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(4, 0, 0)), seg(v3<T>(1, 2, 0), v3<T>(3, 2, 0)));
  EXPECT_EQ(c.distance, T(2));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(1, 2, 0));
  EXPECT_EQ(c.s, T(0.25));
  EXPECT_EQ(c.t, T(0));
  // Disjoint: [0,1] at y = 0 and [3,5] at y = 1: (1,0,0) to (3,1,0), sqrt 5.
  c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(1, 0, 0)), seg(v3<T>(3, 1, 0), v3<T>(5, 1, 0)));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(3, 1, 0));
  EXPECT_TRUE(closeTo(c.distance, std::sqrt(5.0), 4 * kEps<T>));
  // Collinear and disjoint, the second reversed: [0,1] and 3 -> 2. Closest (1,0,0) and the second
  // segment's end (2,0,0): s = 1, t = 1.
  c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(1, 0, 0)), seg(v3<T>(3, 0, 0), v3<T>(2, 0, 0)));
  EXPECT_EQ(c.first, v3<T>(1, 0, 0));
  EXPECT_EQ(c.second, v3<T>(2, 0, 0));
  EXPECT_EQ(c.s, T(1));
  EXPECT_EQ(c.t, T(1));
  EXPECT_EQ(c.distance, T(1));
}

TYPED_TEST(SegmentPairs, DegenerateSegments) {
  using T = TypeParam;
  // A point against a segment: (1,1,0) onto x in [0,2]: (1,0,0), t = 0.5.
  auto c = closestPoints(seg(v3<T>(1, 1, 0), v3<T>(1, 1, 0)), seg(v3<T>(0, 0, 0), v3<T>(2, 0, 0)));
  EXPECT_EQ(c.first, v3<T>(1, 1, 0));
  EXPECT_EQ(c.second, v3<T>(1, 0, 0));
  EXPECT_EQ(c.t, T(0.5));
  EXPECT_EQ(c.distance, T(1));
  // Two points (1,2,3) and (4,6,3): distance 5.
  c = closestPoints(seg(v3<T>(1, 2, 3), v3<T>(1, 2, 3)), seg(v3<T>(4, 6, 3), v3<T>(4, 6, 3)));
  EXPECT_EQ(c.first, v3<T>(1, 2, 3));
  EXPECT_EQ(c.second, v3<T>(4, 6, 3));
  EXPECT_EQ(c.distance, T(5));
}

// Nearly parallel segments crossing (in projection) at x = 1: the first along x in [0, 2], the
// second from (0, h, 0.5) to (2, -h, 0.5) with h = 1e-3. By hand (n = d1 x d2 = (0,0,-4h)):
// s = (r x d2).n / |n|^2 = 8h^2 / 16h^2 = 0.5 and t = 0.5, the closest points (1,0,0) and
// (1,0,0.5), distance 0.5. With the cross-product form the parameters are accurate to about
// eps / sin(angle) = 1e3 eps (tolerance 1e4 eps on the points, whose error is 2 * that); the
// usual (a e - b^2) denominator would lose eps / sin^2 = 1e6 eps, a tenth of the value in float.
TYPED_TEST(SegmentPairs, NearlyParallelSegments) {
  using T = TypeParam;
  const T h = T(1e-3);
  const auto c = closestPoints(seg(v3<T>(0, 0, 0), v3<T>(2, 0, 0)),
                               seg(Vec3<T>(0, h, T(0.5)), Vec3<T>(2, -h, T(0.5))));
  EXPECT_TRUE(closeTo(c.first, v3<double>(1, 0, 0), 1e4 * kEps<T>));
  EXPECT_TRUE(closeTo(c.second, v3<double>(1, 0, 0.5), 1e4 * kEps<T>));
  // The distance is 0.5 to first order in the parameter error (the offset's xy part is
  // h * 2 * (error in s - t) ~ 1e-3 * 1e3 eps): tolerance 4 eps.
  EXPECT_TRUE(closeTo(c.distance, 0.5, 4 * kEps<T>));
}

}  // namespace
}  // namespace simdphys

// ---- validation of the primitives ----------------------------------------------------------

namespace simdphys {
namespace {

TEST(PrimitiveValidation, RejectsWhatItMustAndSaysWhere) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  using test::expectError;
  Obb obb{{0, 0, 0}, {1, 1, 1}, Mat3f::Identity()};
  EXPECT_NO_THROW(validate(obb, "obb"));
  obb.axes(1, 2) = nan;
  expectError([&] { validate(obb, "obb"); }, "obb: axes.col(2).y is nan");
  obb.axes = Mat3f::Identity() * 1.01f;  // 1% off unit length: far beyond 64 eps
  expectError([&] { validate(obb, "obb"); }, "not orthonormal");
  obb.axes = -Mat3f::Identity();  // orthonormal but left-handed
  expectError([&] { validate(obb, "obb"); }, "right-handed");
  expectError([&] { validate(Plane{{0, 0, 2}, 1}, "plane"); }, "normal is not unit length");
  expectError([&] { validate(Segment{{0, 0, 0}, {nan, 0, 0}}, "seg"); }, "seg: end.x is nan");
  expectError([&] { validate(Triangle{{0, 0, 0}, {1, 0, 0}, {0, nan, 0}}, "tri"); }, "tri: c.y");
  expectError([&] { validate(Ray{{0, 0, 0}, {0, 0, 0.5f}}, "ray"); }, "direction is not unit");
  expectError([&] { (void)Ray::fromTo({1, 2, 3}, {1, 2, 3}); }, "coincide");
  expectError([&] { (void)Plane::fromPointNormal({1, 2, 3}, {0, 0, 0}); }, "normal is zero");
  // The constructors normalise what they are given: 3-4-5 gives an exact unit direction.
  const Ray r = Ray::fromTo({0, 0, 0}, {3, 4, 0});
  EXPECT_EQ(r.direction, Vec3f(0.6f, 0.8f, 0));
  const Plane p = Plane::fromPointNormal({0, 0, 5}, {0, 0, 2});
  EXPECT_EQ(p.normal, Vec3f(0, 0, 1));
  EXPECT_EQ(p.d, -5.0f);  // n.p + d = 0 at z = 5
}

}  // namespace
}  // namespace simdphys

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
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "expect_error.hpp"
#include "scenes/workloads.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "typed.hpp"

namespace simdphys {
namespace {

template <class T>
constexpr double kEps = std::numeric_limits<T>::epsilon();
template <class T>
constexpr double kTol = double(kGeometryTolerance<T>);

using test::closeTo;
using test::ScalarName;
using test::Scalars;
using test::v3;

template <class T>
class PointTests : public ::testing::Test {};
template <class T>
class SegmentPairs : public ::testing::Test {};
template <class T>
class Intersects : public ::testing::Test {};
template <class T>
class HardCases : public ::testing::Test {};
template <class T>
class Properties : public ::testing::Test {};
TYPED_TEST_SUITE(PointTests, Scalars, ScalarName);
TYPED_TEST_SUITE(SegmentPairs, Scalars, ScalarName);
TYPED_TEST_SUITE(Intersects, Scalars, ScalarName);
TYPED_TEST_SUITE(HardCases, Scalars, ScalarName);
TYPED_TEST_SUITE(Properties, Scalars, ScalarName);

// Both argument orders give `expected` (and so agree with each other).
#define EXPECT_INTERSECTS(a, b, expected)                                      \
  do {                                                                         \
    EXPECT_EQ(intersects((a), (b)), expected) << "intersects(" #a ", " #b ")"; \
    EXPECT_EQ(intersects((b), (a)), expected) << "intersects(" #b ", " #a ")"; \
  } while (0)

// Rotation matrices with exact entries: a quarter turn about z (columns (0,1,0), (-1,0,0), z)
// and the 3-4-5 rotation about z (columns (0.6,0.8,0), (-0.8,0.6,0), z; 0.6 and 0.8 round).
template <class T>
Mat3<T> quarterTurnZ() {
  Mat3<T> m;
  m << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return m;
}
template <class T>
Mat3<T> rotation345() {
  Mat3<T> m;
  m << T(0.6), T(-0.8), 0, T(0.8), T(0.6), 0, 0, 0, 1;
  return m;
}

template <class T>
ObbT<T> cubeObb(const Vec3<T>& center, T half, const Mat3<T>& axes = Mat3<T>::Identity()) {
  return {center, Vec3<T>::Constant(half), axes};
}

// The unit cube [-1, 1]^3 and a cube of half size 1 standing on one of its edges so that this
// "ridge" edge, along u0 = (1,-1,0)/sqrt2, faces the cube's z edge through (1,1,0) across a gap
// g along w = (1,1,0)/sqrt2. Its other axes are u1 = (w + z)/sqrt2 = (1/2, 1/2, 1/sqrt2) and
// u2 = (z - w)/sqrt2 = (-1/2, -1/2, 1/sqrt2) (u0 x u1 = u2: right-handed). The ridge is the edge
// of support in direction -w: c - (u1 - u2) = c - sqrt2 w, so with c = (2 sqrt2 + g) w =
// (2 + g/sqrt2, 2 + g/sqrt2, 0) it lies on the plane w.p = sqrt2 + g, and the cube's z edge on
// w.p = sqrt2: the gap on the edge-edge axis z x u0 = w is g. Every other axis overlaps for
// g <= 1: on x, the ridge box spans 2 + g/sqrt2 -+ (1/sqrt2 + 1/2 + 1/2), min 1 + (g - 1)/sqrt2
// <= 1; on u1, the cube spans +-(1 + 1/sqrt2) and the ridge box 2 + g/sqrt2 -+ 1, min
// 1 + g/sqrt2 <= 1 + 1/sqrt2; u2 likewise; u0 and z contain both centers. So for 0 < g <= 1 the
// pair is separated by the edge-edge axis alone, touches for g = 0 (the ridge passes through
// (1,1,0)) and overlaps for g < 0.
template <class T>
ObbT<T> ridgeBox(double g) {
  const T r = T(1) / std::sqrt(T(2));
  Mat3<T> axes;
  axes.col(0) = Vec3<T>(r, -r, 0);
  axes.col(1) = Vec3<T>(T(0.5), T(0.5), r);
  axes.col(2) = Vec3<T>(T(-0.5), T(-0.5), r);
  const T c = T(2) + T(g) * r;
  return {Vec3<T>(c, c, 0), Vec3<T>::Constant(1), axes};
}

template <class T>
SegmentT<T> seg(const Vec3<T>& a, const Vec3<T>& b) {
  return {a, b};
}

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

// =============================================================================================
// Random inputs and oracles
// =============================================================================================

// Draws from scenes::Random (fixed seeds), in float; the same draws feed both scalar types.
struct Draw {
  scenes::Random r;
  explicit Draw(std::uint64_t seed) : r(seed) {}
  double uniform(double a, double b) { return r.uniform(float(a), float(b)); }
  template <class T>
  Vec3<T> vec(double a, double b) {
    return v3<T>(uniform(a, b), uniform(a, b), uniform(a, b));
  }
  template <class T>
  Mat3<T> rotation() {
    const Vec3f axis = r.unitDirection();
    return axisAngle(axis.template cast<T>(), T(uniform(0, 3.14159)));
  }
  // Log-uniform in [a, b].
  double logUniform(double a, double b) { return a * std::pow(b / a, uniform(0, 1)); }
};

template <class T>
SphereT<T> randomSphere(Draw& d) {
  return {d.vec<T>(-2, 2), T(d.uniform(0.05, 1.5))};
}
template <class T>
AabbT<T> randomAabb(Draw& d) {
  const Vec3<T> c = d.vec<T>(-2, 2), h = d.vec<T>(0.05, 1.5);
  return {c - h, c + h};
}
template <class T>
ObbT<T> randomObb(Draw& d) {
  return {d.vec<T>(-2, 2), d.vec<T>(0.05, 1.5), d.rotation<T>()};
}
template <class T>
TriangleT<T> randomTriangle(Draw& d) {
  const Vec3<T> c = d.vec<T>(-2, 2);
  return {c + d.vec<T>(-1.5, 1.5), c + d.vec<T>(-1.5, 1.5), c + d.vec<T>(-1.5, 1.5)};
}
template <class T>
PlaneT<T> randomPlane(Draw& d) {
  // Normalised in T, so that the double normal is unit to double precision.
  const Vec3<T> n = d.r.unitDirection().template cast<T>().normalized();
  return {n, T(d.uniform(-3, 3))};
}

// ---- double-precision oracles (independent formulations, normalised axes, no tolerances) ----

struct OracleBox {
  Vec3d c, h;
  Mat3d u;
};
template <class T>
OracleBox oracle(const AabbT<T>& b) {
  const Vec3d lo = b.min.template cast<double>(), hi = b.max.template cast<double>();
  return {(lo + hi) / 2, (hi - lo) / 2, Mat3d::Identity()};
}
template <class T>
OracleBox oracle(const ObbT<T>& b) {
  return {b.center.template cast<double>(), b.halfExtents.template cast<double>(),
          b.axes.template cast<double>()};
}
template <class T>
std::array<Vec3d, 3> oracle(const TriangleT<T>& t) {
  return {t.a.template cast<double>(), t.b.template cast<double>(), t.c.template cast<double>()};
}

// The signed gap of two intervals on a unit axis: > 0 apart by that much, <= 0 overlapping.
double gapOf(double minA, double maxA, double minB, double maxB) {
  return std::max(minB - maxA, minA - maxB);
}
std::pair<double, double> projection(const OracleBox& b, const Vec3d& axis) {
  const double c = b.c.dot(axis);
  double r = 0;
  for (int i = 0; i < 3; ++i) r += b.h[i] * std::abs(b.u.col(i).dot(axis));
  return {c - r, c + r};
}
std::pair<double, double> projection(const std::array<Vec3d, 3>& v, const Vec3d& axis) {
  const double p0 = v[0].dot(axis), p1 = v[1].dot(axis), p2 = v[2].dot(axis);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}
// The face normals of a box as a parallelepiped: the cross products of pairs of its axes (for
// orthonormal axes, the axes themselves).
std::array<Vec3d, 3> faceNormals(const OracleBox& b) {
  return {b.u.col(1).cross(b.u.col(2)).normalized(), b.u.col(2).cross(b.u.col(0)).normalized(),
          b.u.col(0).cross(b.u.col(1)).normalized()};
}

// The largest gap over a list of candidate directions (normalised here; shorter than 1e-12 of
// their factors' lengths skipped as parallel).
template <class A, class B>
double maxGap(const A& a, const B& b, const std::vector<Vec3d>& axes) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec3d& axis : axes) {
    const auto [minA, maxA] = projection(a, axis);
    const auto [minB, maxB] = projection(b, axis);
    best = std::max(best, gapOf(minA, maxA, minB, maxB));
  }
  return best;
}
void addAxis(std::vector<Vec3d>& axes, const Vec3d& axis, double length) {
  if (axis.norm() > 1e-12 * length) axes.push_back(axis.normalized());
}

// Box-box separating-axis gap: > 0 means separated by at least that distance; <= 0 means they
// intersect (the 15 axes are complete for two boxes).
double boxGap(const OracleBox& a, const OracleBox& b) {
  std::vector<Vec3d> axes;
  for (const auto& n : faceNormals(a)) axes.push_back(n);
  for (const auto& n : faceNormals(b)) axes.push_back(n);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) addAxis(axes, a.u.col(i).cross(b.u.col(j)), 1);
  return maxGap(a, b, axes);
}

// Triangle-box gap: box faces, triangle normal, box axis x edge, and the in-plane normals.
double triangleBoxGap(const std::array<Vec3d, 3>& v, const OracleBox& b) {
  std::vector<Vec3d> axes;
  for (const auto& n : faceNormals(b)) axes.push_back(n);
  const std::array<Vec3d, 3> e{v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  const Vec3d n = e[0].cross(e[1]);
  addAxis(axes, n, e[0].norm() * e[1].norm());
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) addAxis(axes, b.u.col(i).cross(e[j]), e[j].norm());
    addAxis(axes, n.cross(e[j]), n.norm() * e[j].norm());
  }
  return maxGap(v, b, axes);
}

// Distance from a segment to a triangle: the minimum over the segment's endpoints against the
// triangle, the segment against the triangle's edges, and the point where it crosses the plane.
// (The distance is convex along the segment; its minimum is at an endpoint, where the segment
// meets the plane, or where the closest triangle point is on an edge.) Built on closestPoint and
// closestPoints in double, which the properties below check against dense sampling.
// When the segment pierces the triangle (crosses its plane at a point whose barycentric weights
// are all positive) the result is negative instead, minus the smallest weight times the longest
// edge: a certificate of intersection that does not rely on a distance of ~1e-17 being "zero".
double segmentTriangleDistance(const Vec3d& p, const Vec3d& q, const std::array<Vec3d, 3>& v) {
  const TriangleT<double> t{v[0], v[1], v[2]};
  double best = std::min((p - closestPoint(t, p)).norm(), (q - closestPoint(t, q)).norm());
  for (int i = 0; i < 3; ++i)
    best = std::min(best, closestPoints(SegmentT<double>{p, q}, {v[i], v[(i + 1) % 3]}).distance);
  const Vec3d n = (v[1] - v[0]).cross(v[2] - v[0]);
  const double sp = n.dot(p - v[0]), sq = n.dot(q - v[0]);
  if ((sp <= 0 && sq >= 0) || (sp >= 0 && sq <= 0)) {
    if (sp != sq) {
      const Vec3d x = p + (q - p) * (sp / (sp - sq));
      const Vec3d w = barycentric(t, x);
      if (sp != 0 && sq != 0 && w.minCoeff() > 0)
        return -w.minCoeff() * std::max({(v[1] - v[0]).norm(), (v[2] - v[0]).norm()});
      best = std::min(best, (x - closestPoint(t, x)).norm());
    }
  }
  return best;
}
// Two triangles intersect exactly when an edge of one meets the other; negative when an edge
// pierces the other triangle.
double triangleDistance(const std::array<Vec3d, 3>& a, const std::array<Vec3d, 3>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, segmentTriangleDistance(a[i], a[(i + 1) % 3], b));
    best = std::min(best, segmentTriangleDistance(b[i], b[(i + 1) % 3], a));
  }
  return best;
}

// The separation the oracles report for a pair, > 0 apart (a lower bound on the distance for the
// separating-axis oracles, the distance for the others), <= 0 intersecting.
template <class T>
double separation(const SphereT<T>& s, const SphereT<T>& o) {
  return (s.center.template cast<double>() - o.center.template cast<double>()).norm() -
         double(s.radius) - double(o.radius);
}
template <class T, class Shape>
double sphereSeparation(const SphereT<T>& s, const Shape& shape) {
  const Vec3d c = s.center.template cast<double>();
  return (c - closestPoint(cast<double>(shape), c)).norm() - double(s.radius);
}
template <class T>
double separation(const SphereT<T>& s, const AabbT<T>& b) {
  return sphereSeparation(s, b);
}
template <class T>
double separation(const SphereT<T>& s, const ObbT<T>& b) {
  return sphereSeparation(s, b);
}
template <class T>
double separation(const SphereT<T>& s, const TriangleT<T>& t) {
  return sphereSeparation(s, t);
}
template <class T>
double separation(const SphereT<T>& s, const PlaneT<T>& p) {
  return std::abs(cast<double>(p).signedDistance(s.center.template cast<double>())) -
         double(s.radius);
}
// Boxes and triangles against a plane: the signed distances of the corners; apart by the
// smallest |distance| when all have one sign.
template <class T>
double planeSeparation(const std::vector<Vec3d>& points, const PlaneT<T>& p) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3d& x : points) {
    const double s = cast<double>(p).signedDistance(x);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return std::max(lo, -hi);
}
std::vector<Vec3d> corners(const OracleBox& b) {
  std::vector<Vec3d> out;
  for (int k = 0; k < 8; ++k)
    out.push_back(b.c + b.u * Vec3d(k & 1 ? b.h[0] : -b.h[0], k & 2 ? b.h[1] : -b.h[1],
                                    k & 4 ? b.h[2] : -b.h[2]));
  return out;
}
template <class T>
double separation(const AabbT<T>& b, const PlaneT<T>& p) {
  return planeSeparation(corners(oracle(b)), p);
}
template <class T>
double separation(const ObbT<T>& b, const PlaneT<T>& p) {
  return planeSeparation(corners(oracle(b)), p);
}
template <class T>
double separation(const TriangleT<T>& t, const PlaneT<T>& p) {
  const auto v = oracle(t);
  return planeSeparation({v[0], v[1], v[2]}, p);
}
template <class T>
double separation(const AabbT<T>& a, const AabbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const AabbT<T>& a, const ObbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const ObbT<T>& a, const ObbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& t, const AabbT<T>& b) {
  return triangleBoxGap(oracle(t), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& t, const ObbT<T>& b) {
  return triangleBoxGap(oracle(t), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& a, const TriangleT<T>& b) {
  return triangleDistance(oracle(a), oracle(b));
}

// Moving a shape: translate by an offset.
template <class T>
SphereT<T> moved(SphereT<T> s, const Vec3<T>& o) {
  s.center += o;
  return s;
}
template <class T>
AabbT<T> moved(AabbT<T> b, const Vec3<T>& o) {
  return {b.min + o, b.max + o};
}
template <class T>
ObbT<T> moved(ObbT<T> b, const Vec3<T>& o) {
  b.center += o;
  return b;
}
template <class T>
TriangleT<T> moved(TriangleT<T> t, const Vec3<T>& o) {
  return {t.a + o, t.b + o, t.c + o};
}
template <class T>
PlaneT<T> moved(PlaneT<T> p, const Vec3<T>& o) {
  p.d -= p.normal.dot(o);
  return p;
}

// A point of each shape, used to aim the near-touching search.
template <class T>
Vec3d anchor(const SphereT<T>& s) {
  return s.center.template cast<double>();
}
template <class T>
Vec3d anchor(const AabbT<T>& b) {
  return oracle(b).c;
}
template <class T>
Vec3d anchor(const ObbT<T>& b) {
  return b.center.template cast<double>();
}
template <class T>
Vec3d anchor(const TriangleT<T>& t) {
  return (t.a + t.b + t.c).template cast<double>() / 3;
}
template <class T>
Vec3d anchor(const PlaneT<T>& p) {
  return -double(p.d) * p.normal.template cast<double>();
}

// The size that scales the tolerances of a pair: the largest distance of the pair's defining
// points from the origin, 1 or more for the random scenes here.
double sizeOf(double x) { return std::max(1.0, x); }

// The band around touching where either answer is accepted, relative to the scene's size. The
// separating-axis tests can miss separations of up to about sqrt(eps) times the size where edges
// are nearly parallel (intersect.hpp); 1e-3 in float and 1e-7 in double are three and seven
// times that. The other tests are within their tolerance, 16 eps, well inside these bands.
template <class T>
constexpr double kBand = std::is_same_v<T, float> ? 1e-3 : 1e-7;

struct Tally {
  int mustIntersect = 0, mustNotIntersect = 0, inBand = 0;
};

// The scene size of a pair.
template <class A, class B>
double pairSize(const A& a, const B& b) {
  return sizeOf(anchor(a).norm() + anchor(b).norm());
}

// Checks one pair against the oracle: an intersecting or touching pair must be reported (the
// tolerance only ever adds touching pairs, never drops one), a pair separated by more than the
// band must not, and both argument orders must agree. "Touching" is a separation up to a quarter
// of the smallest tolerance any of the tests can use here, tol * 0.05 / 4: each test's scale is
// at least the size of one of its shapes, and 0.05 is the smallest size drawn. (The distance
// oracles never go below 0 and return ~1e-17 for intersecting pairs; a separating-axis
// implementation testing the oracle's axes finds no gap larger than the oracle's plus its
// rounding, below another quarter of its tolerance.)
// AABB-AABB has no tolerance (it is exact), so only separation <= 0 counts as touching there.
template <class T, class A, class B>
double contact() {
  return std::is_same_v<A, AabbT<T>> && std::is_same_v<B, AabbT<T>> ? 0 : kTol<T> * 0.05 / 4;
}

template <class T, class A, class B>
void checkPair(const A& a, const B& b, Tally& tally) {
  const double sep = separation(a, b);
  const bool ab = intersects(a, b), ba = intersects(b, a);
  ASSERT_EQ(ab, ba) << "not symmetric, separation " << sep;
  const double size = pairSize(a, b);
  if (sep <= contact<T, A, B>()) {
    ++tally.mustIntersect;
    EXPECT_TRUE(ab) << "separation " << sep;
  } else if (sep > kBand<T> * size) {
    ++tally.mustNotIntersect;
    EXPECT_FALSE(ab) << "separation " << sep;
  } else {
    ++tally.inBand;
  }
}

// Random pairs, and the same pairs slid along the line through their anchors (along the plane's
// normal for planes) to the touching position found by bisection on the oracle, then moved by
// +-delta with delta log-uniform in [1e-9, 1e-1]: many pairs on both sides of touching, a few
// inside the band.
template <class T, class A, class B, class MakeA, class MakeB>
Tally checkRandomPairs(std::uint64_t seed, int count, MakeA makeA, MakeB makeB) {
  Draw d(seed);
  Tally tally;
  for (int n = 0; n < count; ++n) {
    const A a = makeA(d);
    const B b = makeB(d);
    checkPair<T>(a, b, tally);
    Vec3d dir = anchor(b) - anchor(a);
    if constexpr (std::is_same_v<A, PlaneT<T>>) dir = a.normal.template cast<double>();
    if constexpr (std::is_same_v<B, PlaneT<T>>) dir = b.normal.template cast<double>();
    if (!(dir.norm() > 1e-6)) dir = Vec3d(1, 0, 0);
    dir.normalize();
    // b with its anchor at anchor(a) + t dir.
    const Vec3d from = anchor(b);
    const auto place = [&](double t) {
      return moved(b, Vec3<T>((anchor(a) + t * dir - from).template cast<T>()));
    };
    // Intersecting at 0 (a shared anchor point), apart at 20 (sizes <= ~5); "apart" is a
    // separation above the oracles' own rounding, 1e-13 of the size.
    const auto apart = [&](double t) { return separation(a, place(t)) > 1e-13 * pairSize(a, b); };
    double lo = 0, hi = 20;
    if (apart(lo) || !apart(hi)) continue;
    for (int i = 0; i < 60; ++i) {
      const double mid = (lo + hi) / 2;
      (apart(mid) ? hi : lo) = mid;
    }
    const double delta = (n % 8 == 0) ? 0 : d.logUniform(1e-9, 1e-1) * (n % 2 ? 1 : -1);
    checkPair<T>(a, place(hi + delta), tally);
  }
  // Not vacuous: both sides are well represented.
  EXPECT_GT(tally.mustIntersect, count / 4);
  EXPECT_GT(tally.mustNotIntersect, count / 4);
  return tally;
}

#define PAIR_PROPERTY(Name, A, B, makeA, makeB, seed)                                          \
  TYPED_TEST(Properties, Name) {                                                               \
    using T = TypeParam;                                                                       \
    const Tally t = checkRandomPairs<T, A<T>, B<T>>(                                           \
        seed, 1500, [](Draw& d) { return makeA<T>(d); }, [](Draw& d) { return makeB<T>(d); }); \
    this->RecordProperty("in_band", t.inBand);                                                 \
  }

PAIR_PROPERTY(SphereSphereAgreesWithTheOracle, SphereT, SphereT, randomSphere, randomSphere, 101)
PAIR_PROPERTY(SphereAabbAgreesWithTheOracle, SphereT, AabbT, randomSphere, randomAabb, 102)
PAIR_PROPERTY(SphereObbAgreesWithTheOracle, SphereT, ObbT, randomSphere, randomObb, 103)
PAIR_PROPERTY(SpherePlaneAgreesWithTheOracle, SphereT, PlaneT, randomSphere, randomPlane, 104)
PAIR_PROPERTY(AabbAabbAgreesWithTheOracle, AabbT, AabbT, randomAabb, randomAabb, 105)
PAIR_PROPERTY(AabbObbAgreesWithTheOracle, AabbT, ObbT, randomAabb, randomObb, 106)
PAIR_PROPERTY(AabbPlaneAgreesWithTheOracle, AabbT, PlaneT, randomAabb, randomPlane, 107)
PAIR_PROPERTY(ObbObbAgreesWithTheOracle, ObbT, ObbT, randomObb, randomObb, 108)
PAIR_PROPERTY(ObbPlaneAgreesWithTheOracle, ObbT, PlaneT, randomObb, randomPlane, 109)
PAIR_PROPERTY(SphereTriangleAgreesWithTheOracle, SphereT, TriangleT, randomSphere, randomTriangle,
              110)
PAIR_PROPERTY(TriangleAabbAgreesWithTheOracle, TriangleT, AabbT, randomTriangle, randomAabb, 111)
PAIR_PROPERTY(TriangleObbAgreesWithTheOracle, TriangleT, ObbT, randomTriangle, randomObb, 112)
PAIR_PROPERTY(TrianglePlaneAgreesWithTheOracle, TriangleT, PlaneT, randomTriangle, randomPlane, 113)
PAIR_PROPERTY(TriangleTriangleAgreesWithTheOracle, TriangleT, TriangleT, randomTriangle,
              randomTriangle, 114)

// Planes: random pairs are almost never parallel, so parallel ones are made on purpose (the same
// normal or its opposite, offsets from a small set so that some coincide). Symmetric always.
TYPED_TEST(Properties, PlanePlaneAgreesWithParallelism) {
  using T = TypeParam;
  Draw d(115);
  int parallel = 0, coincident = 0;
  for (int n = 0; n < 1000; ++n) {
    const PlaneT<T> a = randomPlane<T>(d);
    PlaneT<T> b = randomPlane<T>(d);
    if (n % 2) {
      const double sign = n % 4 == 1 ? 1 : -1;
      b = {a.normal * T(sign), T(sign * double(a.d) + (n % 3 == 0 ? 0 : d.uniform(-1, 1)))};
      ++parallel;
      // A distinct parallel plane (|offset| >= ~1e-7 here, above tol * (|d1| + |d2|) in double;
      // in float, offsets below 16 eps * 6 = 1.1e-5 count as coincident).
      const double offset = std::abs(double(a.d) - sign * double(b.d));
      const bool same = offset <= kTol<T> * (std::abs(double(a.d)) + std::abs(double(b.d)));
      coincident += same;
      EXPECT_EQ(intersects(a, b), same) << "offset " << offset;
    } else {
      EXPECT_TRUE(intersects(a, b));  // not parallel (random unit normals)
    }
    EXPECT_EQ(intersects(a, b), intersects(b, a));
  }
  EXPECT_GT(parallel, 400);
  EXPECT_GT(coincident, 100);
}

// Every closest point is contained by its shape (within the stated tolerances), and no point
// of a dense sample of the shape is closer to the query point, up to the rounding of the
// computed point: slack tol * (|p| + the shape's size), computed in double.
template <class T, class Shape, class Make, class Sample>
void checkClosestPoints(std::uint64_t seed, Make make, Sample sample) {
  Draw d(seed);
  for (int n = 0; n < 150; ++n) {
    const Shape shape = make(d);
    const Vec3<T> p = d.vec<T>(-5, 5);
    const Vec3<T> q = closestPoint(shape, p);
    ASSERT_TRUE(q.allFinite());
    EXPECT_TRUE(contains(shape, q)) << "closest point " << q.transpose() << " of " << p.transpose();
    const Vec3d pd = p.template cast<double>(), qd = q.template cast<double>();
    const std::vector<Vec3d> samples = sample(cast<double>(shape), d);
    double nearest = std::numeric_limits<double>::infinity(), size = 0;
    for (const Vec3d& s : samples) {
      nearest = std::min(nearest, (pd - s).norm());
      size = std::max(size, s.norm());
    }
    EXPECT_LE((pd - qd).norm(), nearest + kTol<T> * (pd.norm() + size))
        << "a sampled point is closer than " << q.transpose();
    // Idempotent: the closest point of a closest point is itself (to rounding).
    EXPECT_TRUE(closeTo(closestPoint(shape, q), q, kTol<T> * (pd.norm() + size)));
  }
}

std::vector<Vec3d> sampleBox(const OracleBox& b, Draw& d) {
  std::vector<Vec3d> out;
  for (int i = 0; i < 3000; ++i) {
    Vec3d local(d.uniform(-1, 1), d.uniform(-1, 1), d.uniform(-1, 1));
    if (i % 2) local[i % 3] = (i % 4 == 1) ? 1 : -1;  // half on the faces
    out.push_back(b.c + b.u * local.cwiseProduct(b.h));
  }
  return out;
}

TYPED_TEST(Properties, ClosestPointOfSphere) {
  using T = TypeParam;
  checkClosestPoints<T, SphereT<T>>(201, randomSphere<T>, [](const SphereT<double>& s, Draw& d) {
    std::vector<Vec3d> out;
    for (int i = 0; i < 3000; ++i) {
      const Vec3d dir = d.r.unitDirection().cast<double>();
      out.push_back(s.center + dir * s.radius * (i % 2 ? 1.0 : std::cbrt(d.uniform(0, 1))));
    }
    return out;
  });
}
TYPED_TEST(Properties, ClosestPointOfAabb) {
  using T = TypeParam;
  checkClosestPoints<T, AabbT<T>>(
      202, randomAabb<T>, [](const AabbT<double>& b, Draw& d) { return sampleBox(oracle(b), d); });
}
TYPED_TEST(Properties, ClosestPointOfObb) {
  using T = TypeParam;
  checkClosestPoints<T, ObbT<T>>(
      203, randomObb<T>, [](const ObbT<double>& b, Draw& d) { return sampleBox(oracle(b), d); });
}
TYPED_TEST(Properties, ClosestPointOfPlane) {
  using T = TypeParam;
  checkClosestPoints<T, PlaneT<T>>(204, randomPlane<T>, [](const PlaneT<double>& p, Draw& d) {
    // Points of the plane within 8 of its foot point from the origin, in a random in-plane frame.
    const Vec3d t1 = p.normal.unitOrthogonal(), t2 = p.normal.cross(t1);
    const Vec3d foot = -p.d * p.normal;
    std::vector<Vec3d> out;
    for (int i = 0; i < 3000; ++i)
      out.push_back(foot + d.uniform(-8, 8) * t1 + d.uniform(-8, 8) * t2);
    return out;
  });
}
TYPED_TEST(Properties, ClosestPointOfSegment) {
  using T = TypeParam;
  checkClosestPoints<T, SegmentT<T>>(
      205,
      [](Draw& d) {
        const Vec3<T> a = d.vec<T>(-3, 3);
        // Every fourth one degenerate (a point).
        return SegmentT<T>{a, d.r.uniform(0, 1) < 0.25f ? a : Vec3<T>(d.vec<T>(-3, 3))};
      },
      [](const SegmentT<double>& s, Draw&) {
        std::vector<Vec3d> out;
        for (int i = 0; i <= 2000; ++i) out.push_back(s.start + (i / 2000.0) * (s.end - s.start));
        return out;
      });
}
TYPED_TEST(Properties, ClosestPointOfRay) {
  using T = TypeParam;
  checkClosestPoints<T, RayT<T>>(
      206,
      [](Draw& d) {
        return RayT<T>{d.vec<T>(-3, 3), d.r.unitDirection().template cast<T>().normalized()};
      },
      [](const RayT<double>& r, Draw&) {
        std::vector<Vec3d> out;
        for (int i = 0; i <= 4000; ++i) out.push_back(r.origin + (i / 200.0) * r.direction);
        return out;
      });
}
TYPED_TEST(Properties, ClosestPointOfTriangle) {
  using T = TypeParam;
  checkClosestPoints<T, TriangleT<T>>(
      207,
      [](Draw& d) {
        TriangleT<T> t = randomTriangle<T>(d);
        // Every fifth one degenerate: c on the line through a and b.
        if (d.r.uniform(0, 1) < 0.2f) t.c = t.a + T(d.uniform(-1, 2)) * (t.b - t.a);
        return t;
      },
      [](const TriangleT<double>& t, Draw& d) {
        std::vector<Vec3d> out;
        const int k = 60;  // a barycentric grid with edges and vertices, plus random points
        for (int i = 0; i <= k; ++i)
          for (int j = 0; i + j <= k; ++j)
            out.push_back(t.a + (double(i) / k) * (t.b - t.a) + (double(j) / k) * (t.c - t.a));
        for (int i = 0; i < 1000; ++i) {
          double u = d.uniform(0, 1), v = d.uniform(0, 1);
          if (u + v > 1) u = 1 - u, v = 1 - v;
          out.push_back(t.a + u * (t.b - t.a) + v * (t.c - t.a));
        }
        return out;
      });
}

// Barycentric coordinates rebuild the projection of p onto the plane, and sum to 1. Their error
// grows as the triangle thins: tolerance 16 eps * scale * L^2 / |n| (L the longest edge, |n| twice
// the area), the condition of the 2x2 system they solve.
TYPED_TEST(Properties, BarycentricRebuildsTheProjection) {
  using T = TypeParam;
  Draw d(208);
  for (int n = 0; n < 2000; ++n) {
    const TriangleT<T> t = randomTriangle<T>(d);
    const Vec3<T> p = d.vec<T>(-5, 5);
    const Vec3d w = barycentric(t, p).template cast<double>();
    const auto v = oracle(t);
    const Vec3d normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const double longest =
        std::max({(v[1] - v[0]).norm(), (v[2] - v[0]).norm(), (v[2] - v[1]).norm()});
    const Vec3d pd = p.template cast<double>();
    const Vec3d projection = pd - normal * (normal.dot(pd - v[0]) / normal.squaredNorm());
    const double scale = pd.norm() + longest;
    const double condition = longest * longest / normal.norm();
    EXPECT_TRUE(closeTo(w[0] * v[0] + w[1] * v[1] + w[2] * v[2], projection,
                        16 * kEps<T> * scale * condition));
    EXPECT_TRUE(closeTo(w.sum(), 1.0, 16 * kEps<T> * condition * scale / longest));
  }
}

// closestPoints of two segments: on the segments, at the reported distance, and no pair of a
// 101 x 101 parameter grid is closer. A third of the pairs are parallel (the second a translate
// of the first), a tenth nearly parallel (1e-4 rad), some degenerate.
TYPED_TEST(SegmentPairs, ClosestPointsAgreeWithAGrid) {
  using T = TypeParam;
  Draw d(209);
  for (int n = 0; n < 400; ++n) {
    SegmentT<T> a{d.vec<T>(-2, 2), d.vec<T>(-2, 2)};
    SegmentT<T> b{d.vec<T>(-2, 2), d.vec<T>(-2, 2)};
    if (n % 3 == 0) {
      const Vec3<T> o = d.vec<T>(-1, 1);
      b = {a.start + o, a.end + o};
      if (n % 2) std::swap(b.start, b.end);
    } else if (n % 10 == 1) {
      const Vec3<T> o = d.vec<T>(-1, 1);
      const Mat3<T> tilt = axisAngle(d.r.unitDirection().template cast<T>(), T(1e-4));
      b = {a.start + o, a.start + o + tilt * (a.end - a.start) * T(d.uniform(0.2, 2))};
    } else if (n % 10 == 2) {
      b.end = b.start;  // a point
    } else if (n % 10 == 5) {
      a.end = a.start;  // both points
      b.end = b.start;
    }
    const auto c = closestPoints(a, b);
    ASSERT_TRUE(c.first.allFinite() && c.second.allFinite());
    ASSERT_GE(c.s, T(0));
    ASSERT_LE(c.s, T(1));
    ASSERT_GE(c.t, T(0));
    ASSERT_LE(c.t, T(1));
    const SegmentT<double> ad = cast<double>(a), bd = cast<double>(b);
    const double scale = 8;  // the coordinates are within [-3, 3]
    // The reported points are the reported parameters' points, and distance their distance (to
    // a few roundings of the scale).
    EXPECT_TRUE(
        closeTo(c.first, ad.start + double(c.s) * (ad.end - ad.start), 4 * kEps<T> * scale));
    EXPECT_TRUE(
        closeTo(c.second, bd.start + double(c.t) * (bd.end - bd.start), 4 * kEps<T> * scale));
    const double distance =
        (c.first.template cast<double>() - c.second.template cast<double>()).norm();
    EXPECT_TRUE(closeTo(double(c.distance), distance, 16 * kEps<T> * scale));
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; j <= 100; ++j) {
        const Vec3d p = ad.start + (i / 100.0) * (ad.end - ad.start);
        const Vec3d q = bd.start + (j / 100.0) * (bd.end - bd.start);
        nearest = std::min(nearest, (p - q).norm());
      }
    EXPECT_LE(double(c.distance), nearest + kTol<T> * scale) << "pair " << n;
  }
}

// Scaling every input by 2^-20 (about 1e-6) scales every product and sum exactly (no underflow in
// either type at these sizes), and every tolerance is relative: each answer is unchanged and each
// closest point is the scaled one, bit for bit.
TYPED_TEST(HardCases, TinyShapesAnswerAsTheirScaledUpCopies) {
  using T = TypeParam;
  const T k = std::ldexp(T(1), -20);
  Draw d(210);
  const auto sc = [&](auto shape) {
    using S = decltype(shape);
    if constexpr (std::is_same_v<S, SphereT<T>>) return S{shape.center * k, shape.radius * k};
    if constexpr (std::is_same_v<S, AabbT<T>>) return S{shape.min * k, shape.max * k};
    if constexpr (std::is_same_v<S, ObbT<T>>)
      return S{shape.center * k, shape.halfExtents * k, shape.axes};
    if constexpr (std::is_same_v<S, PlaneT<T>>) return S{shape.normal, shape.d * k};
    if constexpr (std::is_same_v<S, TriangleT<T>>) return S{shape.a * k, shape.b * k, shape.c * k};
  };
  for (int n = 0; n < 500; ++n) {
    const SphereT<T> s = randomSphere<T>(d);
    const AabbT<T> a = randomAabb<T>(d);
    const ObbT<T> o = randomObb<T>(d), o2 = randomObb<T>(d);
    const PlaneT<T> p = randomPlane<T>(d);
    const TriangleT<T> t = randomTriangle<T>(d), t2 = randomTriangle<T>(d);
    EXPECT_EQ(intersects(s, a), intersects(sc(s), sc(a)));
    EXPECT_EQ(intersects(s, o), intersects(sc(s), sc(o)));
    EXPECT_EQ(intersects(a, o), intersects(sc(a), sc(o)));
    EXPECT_EQ(intersects(o, o2), intersects(sc(o), sc(o2)));
    EXPECT_EQ(intersects(o, p), intersects(sc(o), sc(p)));
    EXPECT_EQ(intersects(t, s), intersects(sc(t), sc(s)));
    EXPECT_EQ(intersects(t, a), intersects(sc(t), sc(a)));
    EXPECT_EQ(intersects(t, o), intersects(sc(t), sc(o)));
    EXPECT_EQ(intersects(t, t2), intersects(sc(t), sc(t2)));
    const Vec3<T> q = d.vec<T>(-3, 3);
    EXPECT_EQ(closestPoint(t, q) * k, closestPoint(sc(t), Vec3<T>(q * k)));
    EXPECT_EQ(closestPoint(o, q) * k, closestPoint(sc(o), Vec3<T>(q * k)));
    EXPECT_EQ(closestPoint(s, q) * k, closestPoint(sc(s), Vec3<T>(q * k)));
    EXPECT_EQ(contains(t, closestPoint(t, q)), contains(sc(t), Vec3<T>(closestPoint(t, q) * k)));
  }
}

// Symmetry where it is not automatic: computed relative to A's center and relative to B's, the
// box-box test rounds differently, so right at the touching tolerance the two orders of the raw
// computation can disagree. Such pairs are found by bisecting the offset of B along a random
// direction down to adjacent floating-point positions and comparing the two raw orders there;
// intersects() works from the two centres' midpoint (boxes) or orders the pair canonically first
// (triangles), so both its orders must still agree. The same for triangles (relative to either
// triangle's first vertex). Needs at least 3 such pairs of each
// kind, so that the test can fail.
TYPED_TEST(HardCases, SymmetricWhereTheTwoOrdersRoundDifferently) {
  using T = TypeParam;
  Draw d(212);
  const auto boxes = [](const ObbT<T>& a, const ObbT<T>& b) {
    return detail::boxesIntersect(detail::SatBox<T>{Vec3<T>::Zero(), a.halfExtents, a.axes},
                                  detail::SatBox<T>{b.center - a.center, b.halfExtents, b.axes});
  };
  const auto triangles = [](const TriangleT<T>& a, const TriangleT<T>& b) {
    return detail::trianglesIntersect(detail::relative(a, a.a), detail::relative(b, a.a));
  };
  int boxPairs = 0, trianglePairs = 0;
  for (int n = 0; n < 400 && (boxPairs < 3 || trianglePairs < 3); ++n) {
    const Vec3<T> dir = d.r.unitDirection().template cast<T>().normalized();
    const auto search = [&](const auto& a, auto b, const auto& raw, int& found) {
      const auto place = [&](T t) {
        return moved(b, Vec3<T>(t * dir - Vec3<T>(anchor(b).template cast<T>()) +
                                Vec3<T>(anchor(a).template cast<T>())));
      };
      T lo = 0, hi = 20;
      if (!raw(a, place(lo)) || raw(a, place(hi))) return;
      for (;;) {
        const T mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        (raw(a, place(mid)) ? lo : hi) = mid;
      }
      for (const T t : {lo, hi}) {
        const auto c = place(t);
        if (raw(a, c) == raw(c, a)) continue;
        ++found;
        EXPECT_EQ(intersects(a, c), intersects(c, a)) << "offset " << t;
      }
    };
    search(randomObb<T>(d), randomObb<T>(d), boxes, boxPairs);
    search(randomTriangle<T>(d), randomTriangle<T>(d), triangles, trianglePairs);
  }
  EXPECT_GE(boxPairs, 3);
  EXPECT_GE(trianglePairs, 3);
}

// Float against double near 1e5 with sizes of about 1e-2: random pairs within 0.05 of
// (1e5, 1e5, 1e5), drawn in float; the double oracle runs on the same (cast) shapes. Because the
// tests work on offsets from one shape, the float answers agree with the double oracle except
// within a band of 1e-3 of the local scale 0.05 (the separating-axis bound above): 5e-5, while an
// ulp of 1e5 is 7.8e-3. Planes are the exception: n.p + d at 1e5 is only accurate to about
// 2 eps (|p| + |d|) = 0.08 in float, and the plane tests' tolerance is 16 eps (|p| + |d| + size)
// = 0.66: their band is the sum of the two.
TEST(LargeCoordinates, FloatAgreesWithDoubleAwayFromTouching) {
  using T = float;
  Draw d(211);
  const double base = 1e5;
  const auto near = [&](double spread) {
    return v3<T>(base + d.uniform(-spread, spread), base + d.uniform(-spread, spread),
                 base + d.uniform(-spread, spread));
  };
  const auto size = [&] { return T(d.uniform(0.002, 0.02)); };
  const auto axes = [&] { return d.rotation<T>(); };
  int decided[2] = {}, undecided[2] = {};  // [0] solids and triangles, [1] planes
  const auto check = [&](bool got, double sep, double band, int kind = 0) {
    if (sep <= 0) {
      EXPECT_TRUE(got) << "separation " << sep;
      ++decided[kind];
    } else if (sep > band) {
      EXPECT_FALSE(got) << "separation " << sep;
      ++decided[kind];
    } else {
      ++undecided[kind];
    }
  };
  const double band = 1e-3 * 0.05;
  for (int n = 0; n < 3000; ++n) {
    const SphereT<T> s{near(0.03), size()};
    const Vec3<T> c = near(0.03), h = Vec3<T>(size(), size(), size());
    const AabbT<T> a{c - h, c + h};
    const ObbT<T> o{near(0.03), Vec3<T>(size(), size(), size()), axes()};
    const ObbT<T> o2{near(0.03), Vec3<T>(size(), size(), size()), axes()};
    const Vec3<T> tc = near(0.03);
    const TriangleT<T> t{tc + d.vec<T>(-0.02, 0.02), tc + d.vec<T>(-0.02, 0.02),
                         tc + d.vec<T>(-0.02, 0.02)};
    const Vec3<T> uc = near(0.03);
    const TriangleT<T> t2{uc + d.vec<T>(-0.02, 0.02), uc + d.vec<T>(-0.02, 0.02),
                          uc + d.vec<T>(-0.02, 0.02)};
    check(intersects(s, a), separation(s, a), band);
    check(intersects(s, o), separation(s, o), band);
    check(intersects(a, o), separation(a, o), band);
    check(intersects(o, o2), separation(o, o2), band);
    check(intersects(t, s), separation(s, t), band);
    check(intersects(t, a), separation(t, a), band);
    check(intersects(t, o), separation(t, o), band);
    check(intersects(t, t2), separation(t, t2), band);
    // A plane through a point within 10 of the shapes. Its band is the plane tests' own
    // tolerance, 16 eps (|c| + |d| + size), plus the rounding error of n.c + d in float, up to
    // 2 eps (|c| + |d|) (n.c + d is absolute): up to 18 eps * 3.5e5 = 0.75 here.
    const Vec3<T> normal = d.r.unitDirection().normalized();
    const PlaneT<T> p{normal, -normal.dot(near(10))};
    const double planeBand =
        (kTol<T> + 2 * kEps<T>)*(std::sqrt(3.0) * base + std::abs(double(p.d)) + 0.1);
    check(intersects(s, p), separation(s, p), planeBand, 1);
    check(intersects(o, p), separation(o, p), planeBand, 1);
    // Closest points: the float point is the double one rounded to the float grid near 1e5
    // (half an ulp, 2^-8, per component) plus the computation's error (tol * 0.1).
    const Vec3<T> q = near(0.05);
    const Vec3d qd = q.cast<double>();
    const double bound = std::ldexp(1.0, -8) + kTol<T> * 0.1;
    EXPECT_TRUE(closeTo(closestPoint(o, q), closestPoint(cast<double>(o), qd), bound));
    EXPECT_TRUE(closeTo(closestPoint(t, q), closestPoint(cast<double>(t), qd), bound));
    EXPECT_TRUE(closeTo(closestPoint(s, q), closestPoint(cast<double>(s), qd), bound));
  }
  EXPECT_GT(decided[0], 20000);
  EXPECT_LT(undecided[0], decided[0] / 20);
  EXPECT_GT(decided[1], 4000);
  EXPECT_LT(undecided[1], decided[1] / 4);
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

// Tests of include/simdphys/geometry2d.hpp (the scalar reference), in float and in double.
// Hand-worked cases give their derivation in the comment beside them; random cases (fixed seeds)
// are checked against a double-precision oracle written here from first principles: signed
// distance functions, dense sampling of boundaries and of segments and rays, brute force over
// point pairs and triples. Every tolerance says why it is what it is. "eps" is the machine
// epsilon of the scalar type: 1.19e-7 (float), 2.22e-16 (double). The quadtree has its own file.
#include "simdphys/geometry2d.hpp"

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "workloads.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace simdphys {
namespace {

using test::expectError;

template <class T>
constexpr T kEps = std::numeric_limits<T>::epsilon();
constexpr double kPi = std::numbers::pi;
const double kSqrt2 = std::sqrt(2.0);
const double kHalfSqrt2 = std::sqrt(0.5);

template <class T>
Vec2<T> v(double x, double y) {
  return Vec2<T>(T(x), T(y));
}
template <class T>
CircleT<T> circle(double x, double y, double r) {
  return {v<T>(x, y), T(r)};
}
template <class T>
RectT<T> rect(double x0, double y0, double x1, double y1) {
  return {v<T>(x0, y0), v<T>(x1, y1)};
}
template <class T>
OrientedRectT<T> orect(double x, double y, double hx, double hy, double angle) {
  return {v<T>(x, y), v<T>(hx, hy), T(angle)};
}
// The square |x - cx| + |y - cy| <= r: half extents r / sqrt(2), turned by pi/4.
template <class T>
OrientedRectT<T> diamond(double cx, double cy, double r) {
  return orect<T>(cx, cy, r * kHalfSqrt2, r * kHalfSqrt2, kPi / 4);
}
template <class T>
Segment2T<T> segment(double x0, double y0, double x1, double y1) {
  return {v<T>(x0, y0), v<T>(x1, y1)};
}
// A ray with its direction normalised in double, then rounded (unit within eps).
template <class T>
Ray2T<T> ray(double ox, double oy, double dx, double dy) {
  const double length = std::hypot(dx, dy);
  return {v<T>(ox, oy), v<T>(dx / length, dy / length)};
}

template <class T>
::testing::AssertionResult near(const Vec2<T>& actual, const Vec2<T>& expected, double tolerance) {
  const double error = (actual.template cast<double>() - expected.template cast<double>()).norm();
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << actual.x() << ", " << actual.y() << ") is " << error << " from (" << expected.x()
         << ", " << expected.y() << "), tolerance " << tolerance;
}

struct ScalarName {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};
using Scalars = ::testing::Types<float, double>;

template <class T>
class Primitives2d : public ::testing::Test {};
template <class T>
class PointTests2d : public ::testing::Test {};
template <class T>
class Collisions2d : public ::testing::Test {};
template <class T>
class Manifolds2d : public ::testing::Test {};
template <class T>
class LineTests2d : public ::testing::Test {};
template <class T>
class Containing2d : public ::testing::Test {};
template <class T>
class HardCases2d : public ::testing::Test {};
template <class T>
class Oracle2d : public ::testing::Test {};
TYPED_TEST_SUITE(Primitives2d, Scalars, ScalarName);
TYPED_TEST_SUITE(PointTests2d, Scalars, ScalarName);
TYPED_TEST_SUITE(Collisions2d, Scalars, ScalarName);
TYPED_TEST_SUITE(Manifolds2d, Scalars, ScalarName);
TYPED_TEST_SUITE(LineTests2d, Scalars, ScalarName);
TYPED_TEST_SUITE(Containing2d, Scalars, ScalarName);
TYPED_TEST_SUITE(HardCases2d, Scalars, ScalarName);
TYPED_TEST_SUITE(Oracle2d, Scalars, ScalarName);

// =============================================================================================
// Primitives and validation

TYPED_TEST(Primitives2d, AccessorsAreHandWorked) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(1, 2, 3, 6);
  EXPECT_EQ(r.center(), v<T>(2, 4));       // ((1+3)/2, (2+6)/2), exact
  EXPECT_EQ(r.halfExtents(), v<T>(1, 2));  // ((3-1)/2, (6-2)/2)
  EXPECT_EQ(r.size(), v<T>(2, 4));
  const RectT<T> c = RectT<T>::fromCenter(v<T>(2, 4), v<T>(1, 2));
  EXPECT_EQ(c.min, r.min);
  EXPECT_EQ(c.max, r.max);
  const RectT<T> o = RectT<T>::fromOriginSize(v<T>(1, 2), v<T>(2, 4));  // the book's form
  EXPECT_EQ(o.max, v<T>(3, 6));

  EXPECT_EQ(orect<T>(0, 0, 1, 1, 0).axes(), Mat2<T>::Identity());  // cos 0 = 1, sin 0 = 0 exactly
  // A quarter turn: local x -> (0, 1), local y -> (-1, 0); cos(pi/2) is not exactly 0 in T, its
  // rounding (pi/2 itself is rounded) is below 1 eps.
  const Mat2<T> q = orect<T>(0, 0, 1, 1, kPi / 2).axes();
  EXPECT_TRUE(near<T>(q.col(0), v<T>(0, 1), 2 * kEps<T>));
  EXPECT_TRUE(near<T>(q.col(1), v<T>(-1, 0), 2 * kEps<T>));
  // Corners of center (1, 1), half (2, 1), quarter turn, counter-clockwise from local (-2, -1):
  // (1,1) - 2 (0,1) - 1 (-1,0) = (2, -1); then (2,3), (0,3), (0,-1). Tolerance: 4 eps * 3 for
  // the rounded axes times extents of 2.
  const auto k = orect<T>(1, 1, 2, 1, kPi / 2).corners();
  EXPECT_TRUE(near<T>(k[0], v<T>(2, -1), 12 * kEps<T>));
  EXPECT_TRUE(near<T>(k[1], v<T>(2, 3), 12 * kEps<T>));
  EXPECT_TRUE(near<T>(k[2], v<T>(0, 3), 12 * kEps<T>));
  EXPECT_TRUE(near<T>(k[3], v<T>(0, -1), 12 * kEps<T>));

  const Ray2T<T> fromTo = Ray2T<T>::fromTo(v<T>(1, 1), v<T>(4, 5));  // (3,4)/5
  EXPECT_TRUE(near<T>(fromTo.direction, v<T>(0.6, 0.8), 2 * kEps<T>));
  EXPECT_TRUE(near<T>(fromTo.at(T(5)), v<T>(4, 5), 16 * kEps<T>));
  EXPECT_EQ(segment<T>(0, 0, 3, 4).length(), T(5));
}

TYPED_TEST(Primitives2d, BoundingRectsAreHandWorked) {
  using T = TypeParam;
  const RectT<T> c = boundingRect(circle<T>(1, 2, 3));
  EXPECT_EQ(c.min, v<T>(-2, -1));
  EXPECT_EQ(c.max, v<T>(4, 5));
  // Half (2, 1) turned by pi/4: extents |R| h = (sqrt(.5) 2 + sqrt(.5) 1) on both axes = 2.1213.
  // Tolerance: 4 eps of the extent for the products and the sum.
  const RectT<T> o = boundingRect(orect<T>(0, 0, 2, 1, kPi / 4));
  EXPECT_TRUE(near<T>(o.max, v<T>(3 * kHalfSqrt2, 3 * kHalfSqrt2), 8 * kEps<T>));
  EXPECT_TRUE(near<T>(o.min, v<T>(-3 * kHalfSqrt2, -3 * kHalfSqrt2), 8 * kEps<T>));
  const RectT<T> s = boundingRect(segment<T>(3, -1, 1, 2));
  EXPECT_EQ(s.min, v<T>(1, -1));
  EXPECT_EQ(s.max, v<T>(3, 2));
}

TYPED_TEST(Primitives2d, CastToDoubleKeepsValues) {
  using T = TypeParam;
  const OrientedRectT<double> o = cast<double>(orect<T>(1, 2, 3, 4, 0.5));
  EXPECT_EQ(o.center, Vec2d(1, 2));
  EXPECT_EQ(o.halfExtents, Vec2d(3, 4));
  EXPECT_EQ(o.rotation, double(T(0.5)));
  EXPECT_EQ(cast<double>(circle<T>(1, 2, 3)).radius, 3.0);
  EXPECT_EQ(cast<double>(rect<T>(1, 2, 3, 4)).max, Vec2d(3, 4));
  EXPECT_EQ(cast<double>(segment<T>(1, 2, 3, 4)).end, Vec2d(3, 4));
  EXPECT_EQ(cast<double>(ray<T>(1, 2, 1, 0)).direction, Vec2d(1, 0));
}

TYPED_TEST(Primitives2d, ValidateAcceptsGoodAndZeroSizeShapes) {
  using T = TypeParam;
  EXPECT_NO_THROW(validate(circle<T>(1, 2, 0), "test"));
  EXPECT_NO_THROW(validate(rect<T>(1, 2, 1, 2), "test"));
  EXPECT_NO_THROW(validate(orect<T>(1, 2, 0, 0, -7), "test"));
  EXPECT_NO_THROW(validate(segment<T>(1, 2, 1, 2), "test"));
  EXPECT_NO_THROW(validate(ray<T>(1, 2, 3, 4), "test"));
  EXPECT_NO_THROW(validate(v<T>(1, 2), "test"));
}

TYPED_TEST(Primitives2d, ValidateSaysWhatAndWhere) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  expectError([&] { validate(circle<T>(0, 0, -1), "load"); }, "load: radius is -1, must be >= 0");
  expectError([&] { validate(CircleT<T>{v<T>(0, 0), nan}, "load"); }, "load: radius is nan");
  expectError([&] { validate(CircleT<T>{Vec2<T>(0, nan), 1}, "load"); }, "load: center.y is nan");
  expectError([&] { validate(rect<T>(3, 0, 1, 1), "load"); }, "load: min.x (3) > max.x (1)");
  expectError([&] { validate(rect<T>(0, 2, 1, 1), "load"); }, "load: min.y (2) > max.y (1)");
  expectError(
      [&] {
        validate(RectT<T>{v<T>(0, 0), Vec2<T>(inf, 1)}, "load");
      },
      "load: max.x is inf");
  expectError([&] { validate(orect<T>(0, 0, 1, -0.5, 0), "load"); },
              "load: halfExtents.y is -0.5, must be >= 0");
  expectError(
      [&] {
        validate(OrientedRectT<T>{v<T>(0, 0), v<T>(1, 1), inf}, "load");
      },
      "load: rotation is inf");
  expectError(
      [&] {
        validate(Segment2T<T>{v<T>(0, 0), Vec2<T>(1, -inf)}, "load");
      },
      "load: end.y is -inf");
  expectError(
      [&] {
        validate(Ray2T<T>{v<T>(0, 0), v<T>(1, 1)}, "load");
      },
      "load: direction is not unit length");
  expectError([&] { validate(Vec2<T>(nan, 0), "load"); }, "load: point.x is nan");
  expectError([&] { Ray2T<T>::fromTo(v<T>(1, 1), v<T>(1, 1)); }, "Ray2::fromTo");
  BoundingShape2T<T> shape;
  shape.rects = {rect<T>(0, 0, 1, 1), rect<T>(0, 3, 1, 2)};
  expectError([&] { validate(shape, "load"); }, "load: rects[1]: min.y (3) > max.y (2)");
}

// =============================================================================================
// Point containment and closest points. Tolerances: a few roundings of values up to ~5, so
// 16 eps * 5 unless stated.

TYPED_TEST(PointTests2d, CircleIsHandWorked) {
  using T = TypeParam;
  const CircleT<T> c = circle<T>(1, 1, 2);
  EXPECT_TRUE(contains(c, v<T>(1, 3)));       // on the boundary: distance exactly 2
  EXPECT_TRUE(contains(c, v<T>(2.9, 1)));     // 1.9 < 2
  EXPECT_FALSE(contains(c, v<T>(3.1, 1)));    // 2.1 > 2
  EXPECT_FALSE(contains(c, v<T>(2.2, 2.7)));  // 1.2^2 + 1.7^2 = 4.33 > 4
  // (4, 5) is (3, 4) from the center, distance 5: the boundary point is c + 2 (0.6, 0.8).
  EXPECT_TRUE(near<T>(closestPoint(c, v<T>(4, 5)), v<T>(2.2, 2.6), 16 * kEps<T> * 5));
  const Vec2<T> inside = v<T>(1.5, 1);
  EXPECT_EQ(closestPoint(c, inside), inside);  // solid: a point inside is its own closest point
}

TYPED_TEST(PointTests2d, RectIsHandWorkedAndExact) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(-1, 0, 2, 3);
  EXPECT_TRUE(contains(r, v<T>(2, 3)));  // a corner: closed
  EXPECT_TRUE(contains(r, v<T>(0, 1.5)));
  EXPECT_FALSE(contains(r, Vec2<T>(std::nextafter(T(2), T(3)), T(1))));  // one ulp outside
  EXPECT_EQ(closestPoint(r, v<T>(5, -2)), v<T>(2, 0));                   // clamped to a corner
  EXPECT_EQ(closestPoint(r, v<T>(0.5, 7)), v<T>(0.5, 3));                // onto the top face
  EXPECT_EQ(closestPoint(r, v<T>(1, 1)), v<T>(1, 1));
}

TYPED_TEST(PointTests2d, OrientedRectIsHandWorked) {
  using T = TypeParam;
  // Center (2, 1), half (2, 1), a quarter turn: local x is world +y, local y is world -x, so it
  // covers x in [1, 3], y in [-1, 3].
  const OrientedRectT<T> b = orect<T>(2, 1, 2, 1, kPi / 2);
  EXPECT_TRUE(contains(b, v<T>(3, 3)));   // a corner, within the tolerance
  EXPECT_TRUE(contains(b, v<T>(1, -1)));  // the opposite corner
  EXPECT_TRUE(contains(b, v<T>(2.9, -0.9)));
  EXPECT_FALSE(contains(b, v<T>(3.01, 0)));  // 0.01 beyond the x = 3 face
  EXPECT_FALSE(contains(b, v<T>(2, 3.01)));
  // (5, 1): offset (3, 0), local (0, -3) -> clamped (0, -1) -> world (2,1) - (-1, 0) = (3, 1).
  EXPECT_TRUE(near<T>(closestPoint(b, v<T>(5, 1)), v<T>(3, 1), 16 * kEps<T> * 5));
  // (4, 5): offset (2, 4), local (4, -2) -> clamped (2, -1) -> world (2,1) + (0,2) + (1,0).
  EXPECT_TRUE(near<T>(closestPoint(b, v<T>(4, 5)), v<T>(3, 3), 16 * kEps<T> * 5));
  EXPECT_EQ(closestPoint(b, v<T>(2.5, 0)), v<T>(2.5, 0));  // inside: unchanged, exactly
  // The diamond |x| + |y| <= 2: (1, 1) is on its edge, (1.01, 1) outside, (0, 1.99) inside; the
  // point of the edge x + y = 2 closest to (2, 2) is (1, 1).
  const OrientedRectT<T> d = diamond<T>(0, 0, 2);
  EXPECT_TRUE(contains(d, v<T>(1, 1)));
  EXPECT_FALSE(contains(d, v<T>(1.01, 1)));
  EXPECT_TRUE(contains(d, v<T>(0, 1.99)));
  EXPECT_TRUE(near<T>(closestPoint(d, v<T>(2, 2)), v<T>(1, 1), 16 * kEps<T> * 5));
}

TYPED_TEST(PointTests2d, SegmentIsHandWorked) {
  using T = TypeParam;
  const Segment2T<T> s = segment<T>(0, 0, 4, 2);
  EXPECT_TRUE(contains(s, v<T>(2, 1)));  // its midpoint
  EXPECT_TRUE(contains(s, v<T>(4, 2)));  // an end
  EXPECT_FALSE(contains(s, v<T>(2, 1.01)));
  EXPECT_FALSE(contains(s, v<T>(6, 3)));    // on the line, beyond the end
  EXPECT_FALSE(contains(s, v<T>(-2, -1)));  // on the line, before the start
  // (0, 5): (0,5).(4,2) = 10, |d|^2 = 20, t = 1/2 -> (2, 1).
  EXPECT_TRUE(near<T>(closestPoint(s, v<T>(0, 5)), v<T>(2, 1), 16 * kEps<T> * 5));
  EXPECT_EQ(closestPoint(s, v<T>(10, 0)), v<T>(4, 2));  // t = 40/20 = 2, clamped to 1
  EXPECT_EQ(closestPoint(s, v<T>(-3, 0)), v<T>(0, 0));  // t = -12/20, clamped to 0
}

// =============================================================================================
// Shape-versus-shape tests, hand-worked (both argument orders every time).

template <class A, class B>
void expectIntersects(const A& a, const B& b, bool expected, const char* what) {
  EXPECT_EQ(intersects(a, b), expected) << what;
  EXPECT_EQ(intersects(b, a), expected) << what << " (reversed)";
  EXPECT_EQ(collide(a, b).colliding, expected) << what;
  EXPECT_EQ(collide(b, a).colliding, expected) << what << " (reversed)";
}

TYPED_TEST(Collisions2d, CircleCircle) {
  using T = TypeParam;
  const CircleT<T> a = circle<T>(0, 0, 1);
  expectIntersects(a, circle<T>(1.5, 0, 1), true, "overlap by 0.5");
  expectIntersects(a, circle<T>(2, 0, 1), true, "touching: distance 2 = 1 + 1");
  expectIntersects(a, circle<T>(2.01, 0, 1), false, "0.01 apart");
  expectIntersects(circle<T>(0, 0, 1), circle<T>(3, 4, 4), true, "distance 5 = 1 + 4");
  expectIntersects(circle<T>(0, 0, 1), circle<T>(3, 4, 3.9), false, "distance 5 > 4.9");
  expectIntersects(circle<T>(1, 1, 3), circle<T>(1.5, 1, 0.5), true, "one inside the other");
}

TYPED_TEST(Collisions2d, CircleRect) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(0, 0, 4, 2);
  expectIntersects(circle<T>(6, 1, 2), r, true, "touching the x = 4 face at (4, 1)");
  expectIntersects(circle<T>(6, 1, 1.9), r, false, "0.1 short of the face");
  expectIntersects(circle<T>(5, 3, kSqrt2), r, true, "touching the corner (4, 2) at sqrt 2");
  expectIntersects(circle<T>(5, 3, 1.4), r, false, "1.4 < sqrt 2 = 1.414 from the corner");
  expectIntersects(circle<T>(2, 1, 0.1), r, true, "center inside");
  expectIntersects(circle<T>(-0.5, -0.5, 0.71), r, true, "0.7071 from the corner (0, 0)");
  expectIntersects(circle<T>(-0.5, -0.5, 0.7), r, false, "0.7071 from the corner (0, 0)");
}

TYPED_TEST(Collisions2d, CircleOrientedRect) {
  using T = TypeParam;
  // Half (2, 1) turned a quarter: covers [-1, 1] x [-2, 2].
  const OrientedRectT<T> b = orect<T>(0, 0, 2, 1, kPi / 2);
  expectIntersects(circle<T>(3, 0, 2), b, true, "touching the x = 1 face at (1, 0)");
  expectIntersects(circle<T>(3, 0, 1.9), b, false, "0.1 short");
  expectIntersects(circle<T>(0, 3.5, 1.6), b, true, "0.1 into the y = 2 face");
  expectIntersects(circle<T>(0, 3.5, 1.4), b, false, "0.1 short of the y = 2 face");
  // The diamond |x| + |y| <= 2: (2, 2) is (4 - 2) / sqrt 2 = sqrt 2 from the edge x + y = 2.
  expectIntersects(circle<T>(2, 2, kSqrt2), diamond<T>(0, 0, 2), true, "touching the edge");
  expectIntersects(circle<T>(2, 2, 1.4), diamond<T>(0, 0, 2), false, "0.014 short");
}

TYPED_TEST(Collisions2d, RectRectIsExact) {
  using T = TypeParam;
  const RectT<T> a = rect<T>(0, 0, 2, 2);
  expectIntersects(a, rect<T>(2, 0, 3, 1), true, "sharing the x = 2 edge");
  expectIntersects(a, rect<T>(2, 2, 3, 3), true, "sharing the corner (2, 2)");
  const T justPast = std::nextafter(T(2), T(3));
  expectIntersects(a, RectT<T>{Vec2<T>(justPast, 0), v<T>(3, 1)}, false, "one ulp apart");
  expectIntersects(a, rect<T>(0.5, 0.5, 1, 1), true, "one inside the other");
  expectIntersects(a, rect<T>(-1, 0.5, 3, 1), true, "a cross");
}

TYPED_TEST(Collisions2d, RectOrientedRect) {
  using T = TypeParam;
  const RectT<T> a = rect<T>(0, 0, 2, 2);
  // Diamonds of radius 1: the left vertex is at center.x - 1.
  expectIntersects(a, diamond<T>(3, 1, 1), true, "vertex (2, 1) touching the x = 2 face");
  expectIntersects(a, diamond<T>(3.01, 1, 1), false, "vertex 0.01 from the face");
  expectIntersects(a, diamond<T>(2.5, 1, 1), true, "vertex 0.5 into the face");
  // The diamond's edge x + y = c + 1 for a diamond at (c, 0): against the corner (2, 2)... the
  // diamond at (3.5, 3.5) of radius 3 has the edge x + y = 4, which passes through (2, 2).
  expectIntersects(a, diamond<T>(3.5, 3.5, 3), true, "edge x + y = 4 through the corner (2, 2)");
  expectIntersects(a, diamond<T>(3.51, 3.5, 3), false, "edge x + y = 4.01, 0.007 from the corner");
  // Rect and diamond with every corner projection overlapping on the rect's axes but separated on
  // the diamond's: the rect [0,2]^2 and the diamond at (3.4, 3.4) of radius 2.7 overlap on x
  // ([0.7, 6.1] vs [0, 2]) and y, but x + y >= 6.8 - 2.7 = 4.1 > 4 = the corner's x + y.
  expectIntersects(a, diamond<T>(3.4, 3.4, 2.7), false, "separated on a diamond axis only");
}

TYPED_TEST(Collisions2d, OrientedOrientedRect) {
  using T = TypeParam;
  expectIntersects(diamond<T>(0, 0, 1), diamond<T>(2, 0, 1), true, "vertices touching at (1, 0)");
  expectIntersects(diamond<T>(0, 0, 1), diamond<T>(2.01, 0, 1), false, "vertices 0.01 apart");
  expectIntersects(diamond<T>(0, 0, 1), diamond<T>(1, 1, 1), true, "edges x + y = 1 shared");
  expectIntersects(diamond<T>(0, 0, 1), diamond<T>(1.01, 1, 1), false, "edges 0.007 apart");
  // An axis-aligned square [-1, 1]^2 and the diamond at (2.9, 2.9) radius 2: x + y >= 3.8 > 2.
  expectIntersects(orect<T>(0, 0, 1, 1, 0), diamond<T>(2.9, 2.9, 2), false, "diamond axis");
  expectIntersects(orect<T>(0, 0, 1, 1, 0), diamond<T>(2, 2, 2), true, "edge through (1, 1)");
}

// =============================================================================================
// Manifolds, hand-worked. Tolerances: 16 eps times the magnitudes (up to ~5) unless stated.

template <class T>
void expectManifold(const Manifold2T<T>& m, const Vec2<T>& normal, double depth,
                    std::vector<Vec2<T>> contacts, double tolerance, const char* what) {
  ASSERT_TRUE(m.colliding) << what;
  EXPECT_TRUE(near<T>(m.normal, normal, tolerance)) << what;
  EXPECT_NEAR(double(m.depth), depth, tolerance) << what;
  ASSERT_EQ(m.count, int(contacts.size())) << what;
  for (int i = 0; i < m.count; ++i)
    EXPECT_TRUE(near<T>(m.contacts[i], contacts[i], tolerance)) << what << ", contact " << i;
}

template <class T>
void expectFlipped(const Manifold2T<T>& m, const Manifold2T<T>& reversed) {
  EXPECT_EQ(reversed.colliding, m.colliding);
  EXPECT_EQ(reversed.normal, Vec2<T>(-m.normal));
  EXPECT_EQ(reversed.depth, m.depth);
  ASSERT_EQ(reversed.count, m.count);
  for (int i = 0; i < m.count; ++i) EXPECT_EQ(reversed.contacts[i], m.contacts[i]);
}

TYPED_TEST(Manifolds2d, CircleCircle) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 5;
  // (0,0) r2 and (3,0) r2: n = +x, depth 2 + 2 - 3 = 1, surfaces at x = 2 (a) and 3 - 2 = 1 (b),
  // the contact halfway at (1.5, 0).
  expectManifold(collide(circle<T>(0, 0, 2), circle<T>(3, 0, 2)), v<T>(1, 0), 1, {v<T>(1.5, 0)},
                 tol, "along x");
  // 3-4-5: (0,0) r3 and (3,4) r3: n = (0.6, 0.8), depth 6 - 5 = 1, surfaces at 3n = (1.8, 2.4)
  // and (3,4) - 3n = (1.2, 1.6), contact (1.5, 2).
  const auto m = collide(circle<T>(0, 0, 3), circle<T>(3, 4, 3));
  expectManifold(m, v<T>(0.6, 0.8), 1, {v<T>(1.5, 2)}, tol, "3-4-5");
  expectFlipped(m, collide(circle<T>(3, 4, 3), circle<T>(0, 0, 3)));
}

TYPED_TEST(Manifolds2d, CircleRect) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 5;
  const RectT<T> r = rect<T>(0, 0, 4, 2);
  // Circle (5,1) r2: closest rect point (4,1), 1 away: n = -x (circle towards rect), depth 1,
  // circle surface at (3,1), rect point (4,1): contact (3.5, 1).
  const auto m = collide(circle<T>(5, 1, 2), r);
  expectManifold(m, v<T>(-1, 0), 1, {v<T>(3.5, 1)}, tol, "face");
  expectFlipped(m, collide(r, circle<T>(5, 1, 2)));
  // Circle (5,3) r2 near the corner (4,2): n = (-1,-1)/sqrt2, depth 2 - sqrt2, contact halfway
  // between (5,3) + 2n and (4,2): (5,3) - (sqrt2 + 1)/2 (1,1) = (3.7929, 1.7929).
  const double k = (kSqrt2 + 1) / 2;
  expectManifold(collide(circle<T>(5, 3, 2), r), v<T>(-kHalfSqrt2, -kHalfSqrt2), 2 - kSqrt2,
                 {v<T>(5 - k, 3 - k)}, tol, "corner");
  // Center (1, 1.5) inside, r 0.5: faces at 1 (left), 3 (right), 1.5 (bottom), 0.5 (top): out
  // through the top, the rect pushed down: n = -y, depth 0.5 + 0.5 = 1; the circle's surface
  // point along n is (1, 1) and the face point (1, 2), contact (1, 1.5).
  expectManifold(collide(circle<T>(1, 1.5, 0.5), r), v<T>(0, -1), 1, {v<T>(1, 1.5)}, tol,
                 "center inside");
  // Center (2, 1) r 0.5: faces 2, 2, 1, 1: the tie goes to the bottom face (listed before the
  // top): n = +y, depth 1.5, contact halfway between (2, 1.5) and (2, 0): (2, 0.75).
  expectManifold(collide(circle<T>(2, 1, 0.5), r), v<T>(0, 1), 1.5, {v<T>(2, 0.75)}, tol,
                 "center inside, tie");
}

TYPED_TEST(Manifolds2d, CircleOrientedRect) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 5;
  // The box covering [-1,1] x [-2,2] (half (2,1), a quarter turn); circle (0, 3.5) r 1.6: the
  // closest box point is (0, 2), 1.5 away: n = -y, depth 0.1, contact between (0, 1.9) and (0, 2).
  const OrientedRectT<T> b = orect<T>(0, 0, 2, 1, kPi / 2);
  const auto m = collide(circle<T>(0, 3.5, 1.6), b);
  expectManifold(m, v<T>(0, -1), 0.1, {v<T>(0, 1.95)}, tol, "top face");
  expectFlipped(m, collide(b, circle<T>(0, 3.5, 1.6)));
  // The diamond |x| + |y| <= 2 and the circle (2, 2) r 2: sqrt 2 from the edge x + y = 2 at
  // (1, 1): n = -(1,1)/sqrt 2, depth 2 - sqrt 2, contact halfway between (1, 1) and (2,2) + 2n.
  const double c = 2 - kSqrt2;  // (2,2) + 2n = (2 - sqrt2, 2 - sqrt2)
  expectManifold(collide(circle<T>(2, 2, 2), diamond<T>(0, 0, 2)), v<T>(-kHalfSqrt2, -kHalfSqrt2),
                 2 - kSqrt2, {v<T>((1 + c) / 2, (1 + c) / 2)}, tol, "diamond edge");
}

TYPED_TEST(Manifolds2d, RectRect) {
  using T = TypeParam;
  const RectT<T> a = rect<T>(0, 0, 4, 2);
  // b = [3, 0.5] - [6, 5]: pushes +x 4 - 3 = 1, -x 6 - 0 = 6, +y 2 - 0.5 = 1.5, -y 5 - 0 = 5:
  // n = +x, depth 1; faces x = 4 (a) and 3 (b), halfway 3.5; the faces overlap on y in [0.5, 2].
  const auto m = collide(a, rect<T>(3, 0.5, 6, 5));
  expectManifold(m, v<T>(1, 0), 1, {v<T>(3.5, 0.5), v<T>(3.5, 2)}, 0, "x face, exact");
  expectFlipped(m, collide(rect<T>(3, 0.5, 6, 5), a));
  // b = [1, 1.5] - [3, 4]: pushes 3, 3, 0.5, 4: n = +y, depth 0.5, faces y = 2 and 1.5, halfway
  // 1.75, overlap on x in [1, 3].
  expectManifold(collide(a, rect<T>(1, 1.5, 3, 4)), v<T>(0, 1), 0.5, {v<T>(1, 1.75), v<T>(3, 1.75)},
                 0, "y face, exact");
  // b = [3, 1] - [6, 5]: pushes 1, 6, 1, 5: a tie between +x and +y, which +x wins.
  expectManifold(collide(a, rect<T>(3, 1, 6, 5)), v<T>(1, 0), 1, {v<T>(3.5, 1), v<T>(3.5, 2)}, 0,
                 "tie");
  // b inside a: [1, 0.5] - [2, 1]: pushes 3, 2, 1.5, 1: -y, depth 1, faces y = 0 (a) and 1 (b),
  // halfway 0.5, overlap on x [1, 2].
  expectManifold(collide(a, rect<T>(1, 0.5, 2, 1)), v<T>(0, -1), 1, {v<T>(1, 0.5), v<T>(2, 0.5)}, 0,
                 "inside");
}

TYPED_TEST(Manifolds2d, RectOrientedRect) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 5;
  // Rect [0,2]^2 and the diamond at (2.5, 1) of radius 1 (vertex (1.5, 1) in the x = 2 face).
  // SAT: on x, |2.5 - 1| - 1 - 1 = -0.5; on y, 0 - 1 - 1 = -2; on the diamond's axes,
  // 1.5 sqrt(.5) - sqrt(.5) - 2 sqrt(.5) = -1.06: reference face x = 2 of the rect, n = +x,
  // depth 0.5. The incident edge runs from the vertex (1.5, 1) to (2.5, 0) or (2.5, 2) (the two
  // faces tie); only the vertex is behind the face (separation -0.5), so one contact, moved
  // halfway to the face: (1.75, 1).
  const auto m = collide(rect<T>(0, 0, 2, 2), diamond<T>(2.5, 1, 1));
  expectManifold(m, v<T>(1, 0), 0.5, {v<T>(1.75, 1)}, tol, "vertex into a face");
  expectFlipped(m, collide(diamond<T>(2.5, 1, 1), rect<T>(0, 0, 2, 2)));
  // Rect [0,2]^2 and an unturned box (orect rotation 0) centred (3, 1), half (1.5, 0.5): the rect's
  // x = 2 face and the box's x = 1.5 face overlap on y in [0.5, 1.5]; depth 0.5, contacts at x =
  // 1.75.
  expectManifold(collide(rect<T>(0, 0, 2, 2), orect<T>(3, 1, 1.5, 0.5, 0)), v<T>(1, 0), 0.5,
                 {v<T>(1.75, 0.5), v<T>(1.75, 1.5)}, tol, "parallel faces");
}

TYPED_TEST(Manifolds2d, OrientedOrientedRect) {
  using T = TypeParam;
  // Both turned by 0.5 rad, half (2, 1); b's center is a's + 3.5 u0 + 0.5 u1 (u0, u1: the common
  // local axes). In the local frame b is at (3.5, 0.5): x overlap 2 + 2 - 3.5 = 0.5 (y overlap
  // 1 + 1 - 0.5 = 1.5): n = u0, depth 0.5; reference face local x = 2 with y in [-1, 1];
  // incident face local x = 1.5 with y in [-0.5, 1.5], clipped to [-0.5, 1]; contacts halfway at
  // x = 1.75. Tolerance 16 eps * 5 on local values of up to 3.5.
  const double c = std::cos(0.5), s = std::sin(0.5);
  const auto world = [&](double x, double y) { return v<T>(c * x - s * y, s * x + c * y); };
  const Vec2<T> bc = world(3.5, 0.5);
  const OrientedRectT<T> a = orect<T>(0, 0, 2, 1, 0.5);
  const OrientedRectT<T> b{bc, v<T>(2, 1), T(0.5)};
  const auto m = collide(a, b);
  expectManifold(m, world(1, 0), 0.5, {world(1.75, -0.5), world(1.75, 1)}, 16 * kEps<T> * 5,
                 "parallel faces");
  expectFlipped(m, collide(b, a));
}

TYPED_TEST(Manifolds2d, NotCollidingIsEmpty) {
  using T = TypeParam;
  const auto m = collide(orect<T>(0, 0, 1, 1, 0.3), orect<T>(5, 0, 1, 1, 0.2));
  EXPECT_FALSE(m.colliding);
  EXPECT_EQ(m.count, 0);
  EXPECT_EQ(m.depth, T(0));
  EXPECT_EQ(m.normal, Vec2<T>::Zero());
  EXPECT_FALSE(collide(circle<T>(0, 0, 1), rect<T>(3, 3, 4, 4)).colliding);
}

// =============================================================================================
// Segments and raycasts, hand-worked.

TYPED_TEST(LineTests2d, SegmentCircle) {
  using T = TypeParam;
  EXPECT_TRUE(intersects(segment<T>(-3, 0, 3, 0), circle<T>(0, 1, 1)));  // tangent at (0, 0)
  EXPECT_FALSE(intersects(segment<T>(-3, 0, 3, 0), circle<T>(0, 1.01, 1)));
  EXPECT_FALSE(intersects(segment<T>(-3, 0, -2, 0), circle<T>(0, 0, 1)));  // ends 2 away
  EXPECT_TRUE(intersects(segment<T>(-3, 0, -1, 0), circle<T>(0, 0, 1)));   // ends on it
  // Ends inside, the line's closest point (the center) beyond the end: the book misses this one.
  EXPECT_TRUE(intersects(segment<T>(-3, 0, -0.5, 0), circle<T>(0, 0, 1)));
  EXPECT_TRUE(intersects(circle<T>(0, 0, 1), segment<T>(-0.5, 0, 0.5, 0)));  // inside
}

TYPED_TEST(LineTests2d, SegmentRect) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(0, 0, 2, 1);
  EXPECT_TRUE(intersects(segment<T>(-1, 0.5, 3, 0.5), r));  // through (the book misses it)
  EXPECT_TRUE(intersects(segment<T>(-1, -1, 3, 3), r));     // y = x enters at (0,0), leaves (1,1)
  EXPECT_FALSE(intersects(segment<T>(-1, 2, 3, 2), r));     // above
  EXPECT_TRUE(intersects(segment<T>(-1, 1, 1, -1), r));     // x + y = 0: only the corner (0, 0)
  EXPECT_FALSE(intersects(segment<T>(-1, 0.99, 0.99, -1), r));  // x + y = -0.01
  EXPECT_TRUE(intersects(segment<T>(-1, 1.01, 1.01, -1), r));   // x + y = 0.01
  EXPECT_FALSE(intersects(segment<T>(1, -1, 1, -0.01), r));     // vertical, stops short
  EXPECT_TRUE(intersects(segment<T>(1, -1, 1, 0), r));          // vertical, ends on the face
  EXPECT_TRUE(intersects(r, segment<T>(0.5, 0.5, 1, 0.5)));     // inside
}

TYPED_TEST(LineTests2d, SegmentOrientedRect) {
  using T = TypeParam;
  const OrientedRectT<T> d = diamond<T>(0, 0, 2);       // |x| + |y| <= 2
  EXPECT_TRUE(intersects(segment<T>(-3, 2, 3, 2), d));  // touches the vertex (0, 2)
  EXPECT_FALSE(intersects(segment<T>(-3, 2.01, 3, 2.01), d));
  EXPECT_TRUE(intersects(segment<T>(-3, 0, 3, 0), d));      // through two vertices
  EXPECT_TRUE(intersects(segment<T>(0.5, 0.5, 3, 3), d));   // starts inside
  EXPECT_FALSE(intersects(segment<T>(1.1, 1.1, 3, 3), d));  // x + y >= 2.2
}

TYPED_TEST(LineTests2d, RaycastCircle) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 10;  // a few roundings of values up to 10
  // From the origin along +x to the circle (5, 0) r 1: enters at x = 4, normal -x.
  auto hit = raycast(ray<T>(0, 0, 1, 0), circle<T>(5, 0, 1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 4, tol);
  EXPECT_TRUE(near<T>(hit->point, v<T>(4, 0), tol));
  EXPECT_TRUE(near<T>(hit->normal, v<T>(-1, 0), tol));
  EXPECT_FALSE(hit->inside);
  // 3-4-5: circle (0,0) r5, ray from (-10, 3) along +x: the line is 3 from the center, half chord
  // sqrt(25 - 9) = 4, the closest approach at t = 10, so t = 6 at (-4, 3), normal (-0.8, 0.6).
  hit = raycast(ray<T>(-10, 3, 1, 0), circle<T>(0, 0, 5));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 6, tol);
  EXPECT_TRUE(near<T>(hit->point, v<T>(-4, 3), tol));
  EXPECT_TRUE(near<T>(hit->normal, v<T>(-0.8, 0.6), tol));
  // Tangent: the circle (5, 1) r 1 touches y = 0 at (5, 0): t = 5, normal -y.
  hit = raycast(ray<T>(0, 0, 1, 0), circle<T>(5, 1, 1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 5, tol);
  EXPECT_TRUE(near<T>(hit->normal, v<T>(0, -1), tol));
  EXPECT_FALSE(raycast(ray<T>(0, 0, 1, 0), circle<T>(5, 1.01, 1)));  // passes 0.01 below
  EXPECT_FALSE(raycast(ray<T>(0, 0, -1, 0), circle<T>(5, 0, 1)));    // behind the origin
  // Inside: t = 0 at the origin, normal -direction.
  hit = raycast(ray<T>(5, 0.5, 0, 1), circle<T>(5, 0, 1));
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->inside);
  EXPECT_EQ(hit->t, T(0));
  EXPECT_EQ(hit->point, v<T>(5, 0.5));
  EXPECT_EQ(hit->normal, v<T>(0, -1));
}

TYPED_TEST(LineTests2d, RaycastRect) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 10;
  const RectT<T> r = rect<T>(1, -1, 3, 1);
  auto hit = raycast(ray<T>(0, 0, 1, 0), r);  // enters the x = 1 face at t = 1
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 1, tol);
  EXPECT_TRUE(near<T>(hit->normal, v<T>(-1, 0), 0));
  hit = raycast(ray<T>(2, -5, 0, 1), r);  // straight up into the y = -1 face at t = 4
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 4, tol);
  EXPECT_TRUE(near<T>(hit->point, v<T>(2, -1), tol));
  EXPECT_TRUE(near<T>(hit->normal, v<T>(0, -1), 0));
  hit = raycast(ray<T>(5, 0.5, -1, 0), r);  // from the right: the x = 3 face at t = 2, normal +x
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 2, tol);
  EXPECT_TRUE(near<T>(hit->normal, v<T>(1, 0), 0));
  EXPECT_FALSE(raycast(ray<T>(0, 0, -1, 0), r));  // away from it
  EXPECT_FALSE(raycast(ray<T>(0, 2, 1, 0), r));   // above it, parallel
  // Diagonal through the corner (1, -1): both slabs are entered at t = sqrt 2 (the same quotient
  // 1 / d with d.x == d.y); the x face wins the tie.
  const T s = std::sqrt(T(0.5));
  hit = raycast(Ray2T<T>{v<T>(0, -2), Vec2<T>(s, s)}, r);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), kSqrt2, tol);
  EXPECT_TRUE(near<T>(hit->normal, v<T>(-1, 0), 0));
  hit = raycast(ray<T>(2, 0, 0, 1), r);  // inside
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->inside);
  EXPECT_EQ(hit->t, T(0));
  EXPECT_EQ(hit->normal, v<T>(0, -1));
}

TYPED_TEST(LineTests2d, RaycastOrientedRect) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 10;
  // The diamond |x| + |y| <= 2, ray from (-5, 1) along +x: meets the edge -x + y = 2 at (-1, 1),
  // t = 4, outward normal (-1, 1) / sqrt 2.
  auto hit = raycast(ray<T>(-5, 1, 1, 0), diamond<T>(0, 0, 2));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 4, tol);
  EXPECT_TRUE(near<T>(hit->point, v<T>(-1, 1), tol));
  EXPECT_TRUE(near<T>(hit->normal, v<T>(-kHalfSqrt2, kHalfSqrt2), tol));
  EXPECT_FALSE(raycast(ray<T>(-5, 2.01, 1, 0), diamond<T>(0, 0, 2)));  // above the top vertex
  // The box covering [-1,1] x [-2,2] (half (2,1), a quarter turn), from (0, -5) up: enters the
  // y = -2 face at t = 3 with normal -y.
  hit = raycast(ray<T>(0, -5, 0, 1), orect<T>(0, 0, 2, 1, kPi / 2));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 3, tol);
  EXPECT_TRUE(near<T>(hit->normal, v<T>(0, -1), tol));
  hit = raycast(ray<T>(0.5, 0.5, 1, 0), diamond<T>(0, 0, 2));
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->inside);
  EXPECT_EQ(hit->normal, v<T>(-1, 0));
}

TYPED_TEST(LineTests2d, SlabTestWithZeroDirectionAndOriginOnASlabLine) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(1, -1, 3, 1);
  // Direction (1, 0): the y slab has a zero component and the origin lies exactly on its lines
  // y = 1 and y = -1 (0/0 in a naive slab test). Closed: the ray runs along the face and enters
  // the x = 1 face at t = 1.
  for (double y : {1.0, -1.0}) {
    const auto hit = raycast(ray<T>(0, y, 1, 0), r);
    ASSERT_TRUE(hit) << y;
    EXPECT_EQ(hit->t, T(1)) << y;  // (1 - 0) / 1, exact
    EXPECT_EQ(hit->normal, v<T>(-1, 0)) << y;
  }
  EXPECT_FALSE(raycast(ray<T>(0, 1.001, 1, 0), r));
  // Direction (0, -1) with the origin on the x = 3 line: enters the y = 1 face at t = 1.
  auto hit = raycast(ray<T>(3, 2, 0, -1), r);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, T(1));
  EXPECT_EQ(hit->normal, v<T>(0, 1));
  // Origin on the x = 1 line moving along +x: in the box (closed): inside, t = 0.
  hit = raycast(ray<T>(1, 0, 1, 0), r);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->inside);
  // The segment form: vertical segments on the x = 3 line, and a horizontal one on y = -1.
  EXPECT_TRUE(intersects(segment<T>(3, 5, 3, -5), r));
  EXPECT_TRUE(intersects(segment<T>(-5, -1, 5, -1), r));
  EXPECT_FALSE(intersects(segment<T>(3.001, 5, 3.001, -5), r));
}

// =============================================================================================
// Containing shapes and compound shapes.

TYPED_TEST(Containing2d, ContainingRectIsHandWorked) {
  using T = TypeParam;
  const std::vector<Vec2<T>> points{v<T>(1, 2), v<T>(-1, 5), v<T>(3, 0)};
  const RectT<T> r = containingRect(points);
  EXPECT_EQ(r.min, v<T>(-1, 0));
  EXPECT_EQ(r.max, v<T>(3, 5));
  expectError([] { containingRect(std::vector<Vec2<T>>{}); }, "containingRect: no points");
}

TYPED_TEST(Containing2d, ContainingCircleIsHandWorked) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 4;
  // Right angle at (1, 1) (legs (-1,-1) and (1,-1) are perpendicular): the hypotenuse is a
  // diameter, center (1, 0), radius 1.
  CircleT<T> c = containingCircle(std::vector<Vec2<T>>{v<T>(0, 0), v<T>(2, 0), v<T>(1, 1)});
  EXPECT_TRUE(near<T>(c.center, v<T>(1, 0), tol));
  EXPECT_NEAR(double(c.radius), 1, tol);
  // Obtuse at (2, 1): the longest side's diameter circle, center (2, 0), radius 2.
  c = containingCircle(std::vector<Vec2<T>>{v<T>(0, 0), v<T>(4, 0), v<T>(2, 1)});
  EXPECT_TRUE(near<T>(c.center, v<T>(2, 0), tol));
  EXPECT_NEAR(double(c.radius), 2, tol);
  // Equilateral of side 2: the circumcircle, center (1, sqrt3 / 3), radius 2 / sqrt3.
  const double r3 = std::sqrt(3.0);
  c = containingCircle(std::vector<Vec2<T>>{v<T>(0, 0), v<T>(2, 0), v<T>(1, r3)});
  EXPECT_TRUE(near<T>(c.center, v<T>(1, r3 / 3), tol));
  EXPECT_NEAR(double(c.radius), 2 / r3, tol);
  // A square's corners and inner points: center (0,0), radius sqrt 2.
  c = containingCircle(std::vector<Vec2<T>>{v<T>(1, 1), v<T>(0, 0), v<T>(-1, 1), v<T>(0.5, -0.3),
                                            v<T>(-1, -1), v<T>(1, -1)});
  EXPECT_TRUE(near<T>(c.center, v<T>(0, 0), tol));
  EXPECT_NEAR(double(c.radius), kSqrt2, tol);
  // Collinear points: the two extremes' diameter circle, center (1.5, 0), radius 1.5.
  c = containingCircle(std::vector<Vec2<T>>{v<T>(0, 0), v<T>(1, 0), v<T>(3, 0), v<T>(2, 0)});
  EXPECT_TRUE(near<T>(c.center, v<T>(1.5, 0), tol));
  EXPECT_NEAR(double(c.radius), 1.5, tol);
  // Bunched points: the book's centroid circle would be centred at 2.575 with radius 7.425; the
  // minimal one has the extremes (0,0), (10,0) on a diameter: center (5, 0), radius 5.
  c = containingCircle(
      std::vector<Vec2<T>>{v<T>(0, 0), v<T>(0.1, 0), v<T>(0.2, 0), v<T>(10, 0), v<T>(0.1, 0.1)});
  EXPECT_TRUE(near<T>(c.center, v<T>(5, 0), tol * 3));
  EXPECT_NEAR(double(c.radius), 5, tol * 3);
  // One point, and repeated points: radius 0 on the point.
  c = containingCircle(std::vector<Vec2<T>>{v<T>(1, 2), v<T>(1, 2), v<T>(1, 2)});
  EXPECT_EQ(c.center, v<T>(1, 2));
  EXPECT_EQ(c.radius, T(0));
  expectError([] { containingCircle(std::vector<Vec2<T>>{}); }, "containingCircle: no points");
  expectError(
      [] {
        containingCircle(std::vector<Vec2<T>>{v<T>(0, 0), v<T>(1, 0),
                                              Vec2<T>(std::numeric_limits<T>::quiet_NaN(), 0)});
      },
      "points[2]");
}

template <class T>
BoundingShape2T<T> compound() {
  BoundingShape2T<T> s;
  s.circles = {circle<T>(0, 0, 1)};
  s.rects = {rect<T>(2, -1, 4, 1)};
  s.orientedRects = {diamond<T>(7, 0, 1)};  // |x - 7| + |y| <= 1
  return s;
}

TYPED_TEST(Containing2d, BoundingShapeIsHandWorked) {
  using T = TypeParam;
  const BoundingShape2T<T> s = compound<T>();
  EXPECT_TRUE(contains(s, v<T>(0.5, 0)));   // the circle
  EXPECT_TRUE(contains(s, v<T>(3, 0.5)));   // the rect
  EXPECT_TRUE(contains(s, v<T>(7.5, 0)));   // the diamond
  EXPECT_FALSE(contains(s, v<T>(1.5, 0)));  // between circle and rect
  EXPECT_FALSE(contains(s, v<T>(5.5, 0)));  // between rect and diamond
  EXPECT_FALSE(contains(BoundingShape2T<T>{}, v<T>(0, 0)));
  // Circle (1.5, 0) r 0.5 touches the circle (distance 1.5 = 1 + 0.5) and the rect (x = 2).
  EXPECT_TRUE(intersects(s, circle<T>(1.5, 0, 0.5)));
  EXPECT_TRUE(intersects(circle<T>(1.5, 0, 0.5), s));
  EXPECT_FALSE(intersects(s, circle<T>(5, 2, 0.5)));
  EXPECT_TRUE(intersects(s, rect<T>(4.5, -0.5, 6, 0.5)));  // touches the diamond's vertex (6, 0)
  EXPECT_FALSE(intersects(s, rect<T>(4.5, -0.5, 5.9, 0.5)));
  EXPECT_TRUE(intersects(s, orect<T>(5, 0, 1, 0.1, 0)));  // reaches x = 6, the vertex
  EXPECT_FALSE(intersects(s, segment<T>(1.2, -3, 1.2, 3)));
  EXPECT_TRUE(intersects(segment<T>(5, 0, 6.5, 0), s));
  BoundingShape2T<T> other;
  other.rects = {rect<T>(8, -1, 9, 1)};  // touches the diamond's vertex (8, 0)
  EXPECT_TRUE(intersects(s, other));
  other.rects[0].min.x() = T(8.1);
  EXPECT_FALSE(intersects(other, s));
  // Raycasts: the nearest part.
  auto hit = raycast(ray<T>(-5, 0, 1, 0), s);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 4, 16 * kEps<T> * 10);  // the circle at x = -1
  hit = raycast(ray<T>(1.5, 0, 1, 0), s);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 0.5, 16 * kEps<T> * 10);  // the rect at x = 2
  hit = raycast(ray<T>(5, 0, 1, 0), s);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 1, 16 * kEps<T> * 10);  // the diamond's vertex (6, 0)
  EXPECT_FALSE(raycast(ray<T>(-5, 3, 1, 0), s));
  // The bounding rect: [-1, -1] to [8, 1] (the diamond's extents sqrt(.5)(cos + sin) = 1, 4 eps).
  const RectT<T> box = boundingRect(s);
  EXPECT_TRUE(near<T>(box.min, v<T>(-1, -1), 4 * kEps<T> * 8));
  EXPECT_TRUE(near<T>(box.max, v<T>(8, 1), 4 * kEps<T> * 8));
  expectError([] { boundingRect(BoundingShape2T<T>{}); }, "empty");
}

// =============================================================================================
// Named hard cases, one test each.

TYPED_TEST(HardCases2d, TouchingShapes) {
  using T = TypeParam;
  // Each pair touches (exactly, or within the rounding of a rotation): it intersects in both
  // orders with depth 0 and its contacts at the touching point; moved 1e-3 apart along the normal
  // it does not. Tolerance 16 eps * 8 (roundings of values up to 4, rotations included).
  const T tol = 16 * kEps<T> * 8;
  const auto check = [&](const auto& a, const auto& b, const Vec2<T>& normal,
                         std::vector<Vec2<T>> contacts, const char* what) {
    expectIntersects(a, b, true, what);
    const Manifold2T<T> m = collide(a, b);
    expectManifold(m, normal, 0, contacts, tol, what);
    auto apart = b;
    if constexpr (std::is_same_v<std::decay_t<decltype(b)>, RectT<T>>) {
      apart.min += T(1e-3) * normal;
      apart.max += T(1e-3) * normal;
    } else {
      apart.center += T(1e-3) * normal;
    }
    expectIntersects(a, apart, false, what);
  };
  check(circle<T>(0, 0, 1), circle<T>(2, 0, 1), v<T>(1, 0), {v<T>(1, 0)}, "circle-circle");
  check(circle<T>(-1, 0.5, 1), rect<T>(0, 0, 2, 1), v<T>(1, 0), {v<T>(0, 0.5)}, "circle-rect");
  // Half (1, 0.5) turned by pi covers [0, 2] x [-0.5, 0.5]; the circle touches it at (0, 0).
  check(circle<T>(-1, 0, 1), orect<T>(1, 0, 1, 0.5, kPi), v<T>(1, 0), {v<T>(0, 0)},
        "circle-oriented");
  check(rect<T>(0, 0, 1, 1), rect<T>(1, 0.5, 2, 2), v<T>(1, 0), {v<T>(1, 0.5), v<T>(1, 1)},
        "rect-rect edges");
  // Corner to corner: pushes +x 0, -x 2, +y 0, -y 2; +x wins the tie; the faces' overlap on y is
  // the single point 1, so one contact.
  check(rect<T>(0, 0, 1, 1), rect<T>(1, 1, 2, 2), v<T>(1, 0), {v<T>(1, 1)}, "rect-rect corners");
  check(rect<T>(0, 0, 2, 2), diamond<T>(3, 1, 1), v<T>(1, 0), {v<T>(2, 1)}, "rect-diamond vertex");
  // Two parallel boxes (turned 0.5, half (2, 1)) 4 apart along their x axis share a face: the
  // contacts are its ends, local (2, -1) and (2, 1).
  const double c = std::cos(0.5), s = std::sin(0.5);
  const auto world = [&](double x, double y) { return v<T>(c * x - s * y, s * x + c * y); };
  check(orect<T>(0, 0, 2, 1, 0.5), OrientedRectT<T>{world(4, 0), v<T>(2, 1), T(0.5)}, world(1, 0),
        {world(2, -1), world(2, 1)}, "oriented faces");
  // Diamonds touching vertex to vertex at (1, 0): the normal is a face normal of one of them (the
  // SAT cannot tell which face; both separate by 0), the contact is the vertex.
  const Manifold2T<T> m = collide(diamond<T>(0, 0, 1), diamond<T>(2, 0, 1));
  ASSERT_TRUE(m.colliding);
  EXPECT_NEAR(double(m.depth), 0, tol);
  EXPECT_NEAR(std::abs(double(m.normal.x())), kHalfSqrt2, tol);  // a face of a diamond
  EXPECT_GT(m.normal.x(), T(0));                                 // from a towards b
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(near<T>(m.contacts[0], v<T>(1, 0), tol));
}

TYPED_TEST(HardCases2d, ZeroSizeShapes) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 4;
  // A zero-radius circle is a point: it contains only itself and is everyone's closest point.
  const CircleT<T> point = circle<T>(1, 1, 0);
  EXPECT_TRUE(contains(point, v<T>(1, 1)));
  EXPECT_FALSE(contains(point, v<T>(1, 1.001)));
  EXPECT_EQ(closestPoint(point, v<T>(5, 5)), v<T>(1, 1));
  // On the boundary of another circle: touching, normal along the centers from the first of the
  // canonical order (the larger circle, (0,0) < (2,0)): +x, the contact on the point.
  expectManifold(collide(circle<T>(0, 0, 2), circle<T>(2, 0, 0)), v<T>(1, 0), 0, {v<T>(2, 0)}, tol,
                 "point on a circle");
  expectManifold(collide(circle<T>(2, 0, 0), circle<T>(0, 0, 2)), v<T>(-1, 0), 0, {v<T>(2, 0)}, tol,
                 "the same, reversed");
  // Two coincident points: colliding, depth 0, the default normal +x, the contact on them.
  expectManifold(collide(point, point), v<T>(1, 0), 0, {v<T>(1, 1)}, 0, "coincident points");
  // A zero-size rect on a corner: pushes +x 0, -x 1, +y 0, -y 1: +x, one contact.
  const RectT<T> corner = rect<T>(1, 1, 1, 1);
  expectIntersects(rect<T>(0, 0, 1, 1), corner, true, "point rect on a corner");
  expectIntersects(rect<T>(0, 0, 0.9, 0.9), corner, false, "point rect off the corner");
  expectManifold(collide(rect<T>(0, 0, 1, 1), corner), v<T>(1, 0), 0, {v<T>(1, 1)}, 0,
                 "point rect manifold");
  // A flat (zero-height) rect under a circle: touching at (1, 1), normal -y (circle to rect).
  expectManifold(collide(circle<T>(1, 1.5, 0.5), rect<T>(0, 1, 2, 1)), v<T>(0, -1), 0, {v<T>(1, 1)},
                 tol, "flat rect");
  // A zero-size oriented rect on the diamond's vertex (1, 0): touching; its incident "edge" is a
  // point, so the two clipped contacts coincide and one is reported.
  const OrientedRectT<T> dot = orect<T>(1, 0, 0, 0, 0.3);
  expectIntersects(diamond<T>(0, 0, 1), dot, true, "point box on a vertex");
  expectIntersects(diamond<T>(0, 0, 1), orect<T>(1.01, 0, 0, 0, 0.3), false, "point box off it");
  Manifold2T<T> m = collide(diamond<T>(0, 0, 1), dot);
  ASSERT_TRUE(m.colliding);
  EXPECT_NEAR(double(m.depth), 0, tol);
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(near<T>(m.contacts[0], v<T>(1, 0), tol));
  m = collide(dot, dot);  // coincident point boxes
  ASSERT_TRUE(m.colliding);
  EXPECT_EQ(m.depth, T(0));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(near<T>(m.contacts[0], v<T>(1, 0), tol));
  EXPECT_TRUE(contains(dot, v<T>(1, 0)));
  EXPECT_EQ(closestPoint(dot, v<T>(3, 3)), v<T>(1, 0));
  // A zero-length segment is a point.
  const Segment2T<T> p = segment<T>(0.5, 0.5, 0.5, 0.5);
  EXPECT_TRUE(intersects(p, rect<T>(0, 0, 1, 1)));
  EXPECT_FALSE(intersects(p, circle<T>(0, 0, 0.5)));  // 0.707 from the center
  EXPECT_TRUE(intersects(p, diamond<T>(0, 0, 1)));    // |0.5| + |0.5| = 1: on the edge
  EXPECT_TRUE(contains(p, v<T>(0.5, 0.5)));
  EXPECT_EQ(closestPoint(p, v<T>(3, 3)), v<T>(0.5, 0.5));
  // Rays at points: the hit is the point itself; a point circle has no surface, so its normal is
  // -direction (the inside convention); a point rect reports the x face it "enters".
  auto hit = raycast(ray<T>(0, 0, 1, 0), circle<T>(3, 0, 0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, T(3));
  EXPECT_EQ(hit->normal, v<T>(-1, 0));
  hit = raycast(ray<T>(0, 0, 1, 0), rect<T>(2, 0, 2, 0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, T(2));
  EXPECT_EQ(hit->normal, v<T>(-1, 0));
  // An empty compound shape meets nothing.
  const BoundingShape2T<T> none;
  EXPECT_FALSE(intersects(none, circle<T>(0, 0, 100)));
  EXPECT_FALSE(raycast(ray<T>(0, 0, 1, 0), none));
}

TYPED_TEST(HardCases2d, ParallelEdgesInSat) {
  using T = TypeParam;
  const T tol = 16 * kEps<T> * 5;
  const double c = std::cos(0.5), s = std::sin(0.5);
  const auto world = [&](double x, double y) { return v<T>(c * x - s * y, s * x + c * y); };
  const OrientedRectT<T> a = orect<T>(0, 0, 2, 1, 0.5);
  // Same rotation: every SAT axis appears twice. 0.01 apart along the common x axis: separate.
  expectIntersects(a, OrientedRectT<T>{world(4.01, 0.3), v<T>(2, 1), T(0.5)}, false, "gap 0.01");
  expectIntersects(a, OrientedRectT<T>{world(3.99, 0.3), v<T>(2, 1), T(0.5)}, true, "overlap 0.01");
  // The same box described two ways (turned by a further pi/2 with its half extents swapped)
  // gives the same answers against anything.
  const OrientedRectT<T> same = orect<T>(0, 0, 1, 2, 0.5 + kPi / 2);
  for (double x : {2.5, 3.0, 3.5, 3.9, 4.1}) {
    const OrientedRectT<T> b = orect<T>(x, 1, 1, 0.5, 0.2);
    EXPECT_EQ(intersects(a, b), intersects(same, b)) << x;
    const auto ma = collide(a, b), ms = collide(same, b);
    ASSERT_EQ(ma.colliding, ms.colliding) << x;
    if (ma.colliding) {
      EXPECT_NEAR(double(ma.depth), double(ms.depth), tol) << x;
      EXPECT_TRUE(near<T>(ma.normal, ms.normal, tol)) << x;
    }
  }
  // A rect against a box turned by pi (the rect's edges are parallel to its, cos pi = -1): the box
  // covers [1.5, 4.5] x [0.5, 1.5]; the x = 2 face and the x = 1.5 face overlap on y in [0.5, 1.5]:
  // depth 0.5, two contacts at x = 1.75 (in either order).
  const auto m = collide(rect<T>(0, 0, 2, 2), orect<T>(3, 1, 1.5, 0.5, kPi));
  ASSERT_TRUE(m.colliding);
  EXPECT_TRUE(near<T>(m.normal, v<T>(1, 0), tol));
  EXPECT_NEAR(double(m.depth), 0.5, tol);
  ASSERT_EQ(m.count, 2);
  const Vec2<T> lo = m.contacts[0].y() < m.contacts[1].y() ? m.contacts[0] : m.contacts[1];
  const Vec2<T> hi = m.contacts[0].y() < m.contacts[1].y() ? m.contacts[1] : m.contacts[0];
  EXPECT_TRUE(near<T>(lo, v<T>(1.75, 0.5), tol));
  EXPECT_TRUE(near<T>(hi, v<T>(1.75, 1.5), tol));
}

TYPED_TEST(HardCases2d, SegmentsCollinearWithAnEdge) {
  using T = TypeParam;
  const RectT<T> r = rect<T>(0, 0, 2, 1);
  EXPECT_TRUE(intersects(segment<T>(-1, 1, 3, 1), r));      // along the top edge, past both ends
  EXPECT_TRUE(intersects(segment<T>(0.5, 0, 1.5, 0), r));   // inside the bottom edge
  EXPECT_FALSE(intersects(segment<T>(2.5, 1, 4, 1), r));    // on the top edge's line, beyond it
  EXPECT_TRUE(intersects(segment<T>(2, 1, 4, 1), r));       // starting at the corner
  EXPECT_FALSE(intersects(segment<T>(0, -3, 0, -0.5), r));  // on the left edge's line, short
  EXPECT_TRUE(intersects(segment<T>(0, -3, 0, 0), r));      // ending at the corner
  // An oriented rect's +x face from corner k1 to k2 (computed in T, so rounded): a segment along
  // it, beyond it, around it, and parallel just outside it.
  const OrientedRectT<T> b = orect<T>(0.3, -0.2, 1.5, 0.75, 0.5);
  const auto k = b.corners();
  const Vec2<T> e = (k[2] - k[1]).normalized();
  const Vec2<T> out = b.axes().col(0);  // the face's outward normal
  EXPECT_TRUE(intersects(Segment2T<T>{k[1], k[2]}, b));
  EXPECT_TRUE(intersects(Segment2T<T>{k[2], k[1]}, b));
  EXPECT_TRUE(intersects(Segment2T<T>{Vec2<T>(k[1] - e), Vec2<T>(k[2] + e)}, b));
  EXPECT_FALSE(intersects(Segment2T<T>{Vec2<T>(k[2] + T(0.1) * e), Vec2<T>(k[2] + e)}, b));
  EXPECT_FALSE(intersects(Segment2T<T>{Vec2<T>(k[1] - e), Vec2<T>(k[1] - T(0.1) * e)}, b));
  EXPECT_FALSE(
      intersects(Segment2T<T>{Vec2<T>(k[1] + T(0.01) * out), Vec2<T>(k[2] + T(0.01) * out)}, b));
  // A ray along that face from 2 before k1: it enters at k1, t = 2, through the -y face (normal
  // -u1) as the face's own slab is grazed. Tolerance 16 eps * 4.
  const auto hit = raycast(Ray2T<T>{Vec2<T>(k[1] - T(2) * e), e}, b);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 2, 16 * kEps<T> * 4);
  EXPECT_TRUE(near<T>(hit->point, k[1], 16 * kEps<T> * 4));
  EXPECT_TRUE(near<T>(hit->normal, Vec2<T>(-b.axes().col(1)), 16 * kEps<T> * 4));
}

TYPED_TEST(HardCases2d, CoordinatesAt1e5) {
  using T = TypeParam;
  // Everything shifted by (1e5, -1e5). Offsets are multiples of 2^-7 (an ulp of 1e5 in float), so
  // the inputs are exact in both types. Differences are taken before anything is multiplied, so
  // depths and hit distances keep the precision of the shapes' size (16 eps * 8), not of their
  // position; only results given in absolute coordinates round to an ulp of 1e5 (1e5 eps: 0.0078
  // in float).
  const double X = 1e5, Y = -1e5;
  const T local = 16 * kEps<T> * 8, absolute = T(1e5) * kEps<T>;
  const auto m = collide(circle<T>(X, Y, 1), circle<T>(X + 1.75, Y, 1));
  expectManifold(m, v<T>(1, 0), 0.25, {v<T>(X + 0.875, Y)}, absolute, "circles");
  EXPECT_NEAR(double(m.depth), 0.25, local);
  expectIntersects(circle<T>(X, Y, 1), circle<T>(X + 2.25, Y, 1), false, "circles apart");
  // Exact rect manifold: (100004 + 100003) / 2 = 100003.5 is exact in float.
  expectManifold(collide(rect<T>(X, Y, X + 4, Y + 2), rect<T>(X + 3, Y + 0.5, X + 6, Y + 5)),
                 v<T>(1, 0), 1, {v<T>(X + 3.5, Y + 0.5), v<T>(X + 3.5, Y + 2)}, 0, "rects, exact");
  // Circle into a rect face: depth 1 exactly as at the origin.
  const auto cr = collide(circle<T>(X + 5, Y + 1, 2), rect<T>(X, Y, X + 4, Y + 2));
  EXPECT_NEAR(double(cr.depth), 1, local);
  EXPECT_TRUE(near<T>(cr.contacts[0], v<T>(X + 3.5, Y + 1), absolute));
  // Boxes turned by 0.5 in the parallel-faces configuration (see Manifolds2d): b's center is
  // rounded to the grid of 1e5, so the expected depth is computed in double from the rounded
  // center: 4 - (its offset along u0); the SAT works relative to a's center and keeps 16 eps * 8.
  const double c = std::cos(0.5), s = std::sin(0.5);
  const Vec2<T> bc = v<T>(X + c * 3.5 - s * 0.5, Y + s * 3.5 + c * 0.5);
  const double along = (double(bc.x()) - X) * double(std::cos(T(0.5))) +
                       (double(bc.y()) - Y) * double(std::sin(T(0.5)));
  const auto ob = collide(orect<T>(X, Y, 2, 1, 0.5), OrientedRectT<T>{bc, v<T>(2, 1), T(0.5)});
  ASSERT_TRUE(ob.colliding);
  EXPECT_NEAR(double(ob.depth), 4 - along, local);
  EXPECT_TRUE(near<T>(ob.normal, v<T>(c, s), local));
  EXPECT_EQ(ob.count, 2);
  // Containment at 1e5: the boundary point 0.75 away is in, the next grid points out are not.
  EXPECT_TRUE(contains(circle<T>(X, Y, 0.75), v<T>(X + 0.75, Y)));
  EXPECT_FALSE(contains(circle<T>(X, Y, 0.75), v<T>(X + 0.765625, Y)));
  EXPECT_TRUE(contains(orect<T>(X, Y, 1, 0.5, kPi / 2), v<T>(X + 0.5, Y + 1)));  // a corner
  EXPECT_FALSE(contains(orect<T>(X, Y, 1, 0.5, kPi / 2), v<T>(X + 0.515625, Y)));
  // Raycasts and segments: t is a difference of coordinates, exact here.
  auto hit = raycast(ray<T>(X - 5, Y, 1, 0), rect<T>(X + 1, Y - 1, X + 3, Y + 1));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, T(6));
  hit = raycast(ray<T>(X - 5, Y, 1, 0), circle<T>(X + 5, Y, 1));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 9, local);
  hit = raycast(ray<T>(X - 5, Y + 1, 1, 0), diamond<T>(X, Y, 2));  // the edge at (-1, 1)
  ASSERT_TRUE(hit);
  EXPECT_NEAR(double(hit->t), 4, local);
  EXPECT_TRUE(intersects(segment<T>(X - 1, Y + 1, X + 3, Y + 1), rect<T>(X, Y, X + 2, Y + 1)));
  EXPECT_FALSE(intersects(segment<T>(X - 1, Y + 1.0078125, X + 3, Y + 1.0078125),
                          rect<T>(X, Y, X + 2, Y + 1)));
  // The containing circle of points around 1e5 is computed relative to one of them.
  const CircleT<T> cc = containingCircle(
      std::vector<Vec2<T>>{v<T>(X, Y), v<T>(X + 2, Y), v<T>(X + 1, Y + 1), v<T>(X + 1, Y - 0.5)});
  EXPECT_NEAR(double(cc.radius), 1, local);
  EXPECT_TRUE(near<T>(cc.center, v<T>(X + 1, Y), absolute));
}

// =============================================================================================
// The double-precision oracle, written from first principles: signed distance functions,
// closest points by clamping in double, dense boundary sampling, and the separation of two
// convex shapes from their corner projections (for boxes) or center distances (for circles).

namespace oracle {

struct Shape {
  bool circle;
  Vec2d c;
  double r;
  Vec2d h;
  Mat2d axes;
  double size() const { return circle ? r : h.x() + h.y(); }
};
template <class T>
Shape of(const CircleT<T>& s) {
  return {true, s.center.template cast<double>(), double(s.radius), Vec2d::Zero(),
          Mat2d::Identity()};
}
template <class T>
Shape of(const RectT<T>& s) {
  const Vec2d lo = s.min.template cast<double>(), hi = s.max.template cast<double>();
  return {false, (lo + hi) / 2, 0, (hi - lo) / 2, Mat2d::Identity()};
}
template <class T>
Shape of(const OrientedRectT<T>& s) {
  const double a = double(s.rotation);
  Mat2d axes;
  axes << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return {false, s.center.template cast<double>(), 0, s.halfExtents.template cast<double>(), axes};
}
Shape moved(Shape s, const Vec2d& by) {
  s.c += by;
  return s;
}

double sdf(const Shape& s, const Vec2d& p) {
  if (s.circle) return (p - s.c).norm() - s.r;
  const Vec2d q = (s.axes.transpose() * (p - s.c)).cwiseAbs() - s.h;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

Vec2d closest(const Shape& s, const Vec2d& p) {
  if (s.circle) {
    const double d = (p - s.c).norm();
    return d <= s.r ? p : Vec2d(s.c + (p - s.c) * (s.r / d));
  }
  const Vec2d local = s.axes.transpose() * (p - s.c);
  const Vec2d clamped = local.cwiseMax(-s.h).cwiseMin(s.h);
  return clamped == local ? p : Vec2d(s.c + s.axes * clamped);
}

std::vector<Vec2d> corners(const Shape& s) {
  const Vec2d ex = s.axes.col(0) * s.h.x(), ey = s.axes.col(1) * s.h.y();
  return {s.c - ex - ey, s.c + ex - ey, s.c + ex + ey, s.c - ex + ey};
}

double perimeter(const Shape& s) { return s.circle ? 2 * kPi * s.r : 4 * (s.h.x() + s.h.y()); }

// n points evenly spaced along the boundary (by arc length).
std::vector<Vec2d> boundary(const Shape& s, int n) {
  std::vector<Vec2d> out;
  if (s.circle) {
    for (int k = 0; k < n; ++k)
      out.push_back(s.c + s.r * Vec2d(std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n)));
    return out;
  }
  const auto k = corners(s);
  const double total = perimeter(s);
  for (int i = 0; i < n; ++i) {
    double at = total * i / n;
    for (int e = 0; e < 4; ++e) {
      const double length = (k[(e + 1) % 4] - k[e]).norm();
      if (at <= length || e == 3) {
        out.push_back(length > 0 ? Vec2d(k[e] + (k[(e + 1) % 4] - k[e]) * (at / length)) : k[e]);
        break;
      }
      at -= length;
    }
  }
  return out;
}

// The signed separation: > 0 apart, 0 touching, < 0 overlapping by that much (the minimum
// translation distance). Circles: center distances; boxes: the largest gap between the corner
// projections on the four face normals (the separating axis theorem, restated without the
// projected-radius formula the implementation uses).
double separation(const Shape& a, const Shape& b) {
  if (a.circle && b.circle) return (b.c - a.c).norm() - a.r - b.r;
  if (a.circle) return sdf(b, a.c) - a.r;
  if (b.circle) return sdf(a, b.c) - b.r;
  const auto ka = corners(a), kb = corners(b);
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec2d& n :
       {Vec2d(a.axes.col(0)), Vec2d(a.axes.col(1)), Vec2d(b.axes.col(0)), Vec2d(b.axes.col(1))}) {
    double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
    for (const Vec2d& p : ka) loA = std::min(loA, p.dot(n)), hiA = std::max(hiA, p.dot(n));
    for (const Vec2d& p : kb) loB = std::min(loB, p.dot(n)), hiB = std::max(hiB, p.dot(n));
    best = std::max(best, std::max(loB - hiA, loA - hiB));
  }
  return best;
}

enum class Verdict { kApart, kOverlap, kUnsure };

// Dense sampling: the smallest signed distance of either boundary's samples to the other shape.
// Some sample inside by more than the margin: overlap. If the shapes met, a boundary point of
// one would lie on the other (or one would contain the other) and the nearest sample would be
// within half the spacing of it; so all samples farther than that (plus the margin): apart.
Verdict sampled(const Shape& a, const Shape& b, double margin) {
  constexpr int kSamples = 1024;
  double least = std::numeric_limits<double>::infinity();
  for (const Vec2d& p : boundary(a, kSamples)) least = std::min(least, sdf(b, p));
  for (const Vec2d& p : boundary(b, kSamples)) least = std::min(least, sdf(a, p));
  const double spacing = std::max(perimeter(a), perimeter(b)) / kSamples;
  if (least < -margin) return Verdict::kOverlap;
  if (least > spacing / 2 + margin) return Verdict::kApart;
  return Verdict::kUnsure;
}

}  // namespace oracle

// Random shapes from float draws: centers in [-3, 3]^2, sizes in [0.05, 2], any rotation. The
// draws are floats, so the same shapes are tested in float and in double.
template <class T>
CircleT<T> randomCircle(workloads::Random& r) {
  const float x = r.uniform(-3, 3), y = r.uniform(-3, 3);
  return {Vec2<T>(x, y), T(r.uniform(0.05f, 2))};
}
template <class T>
RectT<T> randomRect(workloads::Random& r) {
  const float x = r.uniform(-3, 3), y = r.uniform(-3, 3);
  const float hx = r.uniform(0.05f, 2), hy = r.uniform(0.05f, 2);
  return {Vec2<T>(x - hx, y - hy), Vec2<T>(x + hx, y + hy)};
}
template <class T>
OrientedRectT<T> randomOriented(workloads::Random& r) {
  const float x = r.uniform(-3, 3), y = r.uniform(-3, 3);
  const float hx = r.uniform(0.05f, 2), hy = r.uniform(0.05f, 2);
  return {Vec2<T>(x, y), Vec2<T>(hx, hy), T(r.uniform(-3.2f, 3.2f))};
}

// The oracle's margin: what the implementation may count as touching (16 eps * scale, scale at
// most ~25 here: 5e-5 in float) plus the float rotation's cos and sin, which differ from the
// double ones by an ulp (1e-7 of sizes up to 2). 1e-4 covers both.
constexpr double kMargin = 1e-4;

// Against the sampling oracle: intersects in both orders, and collide's manifold: the normal is
// unit, the depth is the minimum translation distance, moving b by depth * normal leaves the
// shapes touching, each contact is within depth / 2 of both shapes, and the reversed call gives
// the flipped manifold bit for bit.
template <class T, class GenA, class GenB>
void checkPairs(GenA genA, GenB genB, std::uint64_t seed, const char* what) {
  workloads::Random rng(seed);
  constexpr int kCases = 1000;
  int overlaps = 0, aparts = 0, unsure = 0;
  for (int k = 0; k < kCases; ++k) {
    const auto a = genA(rng);
    const auto b = genB(rng);
    const oracle::Shape sa = oracle::of(a), sb = oracle::of(b);
    const bool got = intersects(a, b);
    ASSERT_EQ(intersects(b, a), got) << what << " case " << k;
    const oracle::Verdict verdict = oracle::sampled(sa, sb, kMargin);
    if (verdict == oracle::Verdict::kUnsure) {
      ++unsure;
    } else {
      const bool overlap = verdict == oracle::Verdict::kOverlap;
      (overlap ? overlaps : aparts)++;
      EXPECT_EQ(got, overlap) << what << " case " << k;
      // The oracle's two halves agree where the sampling decided.
      EXPECT_EQ(oracle::separation(sa, sb) <= 0, overlap) << what << " case " << k;
    }
    const Manifold2T<T> m = collide(a, b);
    ASSERT_EQ(m.colliding, got) << what << " case " << k;
    expectFlipped(m, collide(b, a));
    if (!m.colliding) continue;
    // Tolerance: 64 eps * scale: the depth and normal round by a few eps of the scale, the
    // reference face may be one whose separation is within the 16 eps * scale slack of the best,
    // and the float rotation differs from the double one by an ulp.
    const double scale = (sb.c - sa.c).norm() + sa.size() + sb.size();
    const double tol = 64 * double(kEps<T>) * scale;
    const Vec2d n = m.normal.template cast<double>();
    const double depth = double(m.depth);
    EXPECT_NEAR(n.norm(), 1, 4 * double(kEps<T>)) << what << " case " << k;
    EXPECT_GE(depth, 0) << what << " case " << k;
    EXPECT_NEAR(depth, std::max(0.0, -oracle::separation(sa, sb)), tol) << what << " case " << k;
    EXPECT_NEAR(oracle::separation(sa, oracle::moved(sb, depth * n)), 0, tol)
        << what << " case " << k;
    ASSERT_GE(m.count, 1);
    ASSERT_LE(m.count, 2);
    for (int i = 0; i < m.count; ++i) {
      const Vec2d p = m.contacts[i].template cast<double>();
      EXPECT_LE(oracle::sdf(sa, p), depth / 2 + tol) << what << " case " << k << " contact " << i;
      EXPECT_LE(oracle::sdf(sb, p), depth / 2 + tol) << what << " case " << k << " contact " << i;
    }
  }
  // The oracle decides nearly every case, and both answers occur often.
  EXPECT_LE(unsure, kCases / 100) << what;
  EXPECT_GE(overlaps, kCases / 10) << what;
  EXPECT_GE(aparts, kCases / 10) << what;
}

TYPED_TEST(Oracle2d, CollisionsMatchBruteForceAndManifoldsSeparate) {
  using T = TypeParam;
  const auto c = [](workloads::Random& r) { return randomCircle<T>(r); };
  const auto a = [](workloads::Random& r) { return randomRect<T>(r); };
  const auto o = [](workloads::Random& r) { return randomOriented<T>(r); };
  checkPairs<T>(c, c, 101, "circle-circle");
  checkPairs<T>(c, a, 102, "circle-rect");
  checkPairs<T>(c, o, 103, "circle-oriented");
  checkPairs<T>(a, a, 104, "rect-rect");
  checkPairs<T>(a, o, 105, "rect-oriented");
  checkPairs<T>(o, o, 106, "oriented-oriented");
}

// Point tests against the oracle's sdf and clamped closest points, on random points in [-6, 6]^2.
template <class T, class Gen>
void checkPoints(Gen gen, std::uint64_t seed, const char* what) {
  workloads::Random rng(seed);
  for (int k = 0; k < 2000; ++k) {
    const auto s = gen(rng);
    const Vec2<T> p(rng.uniform(-6, 6), rng.uniform(-6, 6));
    const oracle::Shape o = oracle::of(s);
    const Vec2d pd = p.template cast<double>();
    const double d = oracle::sdf(o, pd);
    if (std::abs(d) > kMargin) {
      EXPECT_EQ(contains(s, p), d <= 0) << what << " case " << k;
    }
    // Tolerance: 64 eps * (|p - c| + size), the magnitudes the local frame and clamp round with.
    const double tol = 64 * double(kEps<T>) * ((pd - o.c).norm() + o.size());
    const Vec2<T> q = closestPoint(s, p);
    EXPECT_TRUE(near<T>(q, oracle::closest(o, pd).template cast<T>(), tol)) << what << " " << k;
    EXPECT_LE(oracle::sdf(o, q.template cast<double>()), tol) << what << " case " << k;
  }
}

TYPED_TEST(Oracle2d, PointTestsMatchDouble) {
  using T = TypeParam;
  checkPoints<T>([](workloads::Random& r) { return randomCircle<T>(r); }, 201, "circle");
  checkPoints<T>([](workloads::Random& r) { return randomRect<T>(r); }, 202, "rect");
  checkPoints<T>([](workloads::Random& r) { return randomOriented<T>(r); }, 203, "oriented");
}

// Segments against dense sampling along them (spacing = length / 1023, the same argument as for
// the boundaries: a segment that meets the shape has a sample within half a spacing of it).
template <class T, class Gen>
void checkSegments(Gen gen, std::uint64_t seed, const char* what) {
  workloads::Random rng(seed);
  int unsure = 0, hits = 0, misses = 0;
  constexpr int kCases = 1500, kSamples = 1024;
  for (int k = 0; k < kCases; ++k) {
    const auto s = gen(rng);
    Segment2T<T> seg{Vec2<T>(rng.uniform(-6, 6), rng.uniform(-6, 6)),
                     Vec2<T>(rng.uniform(-6, 6), rng.uniform(-6, 6))};
    if (k % 10 == 0) seg.end = seg.start;  // some points
    const oracle::Shape o = oracle::of(s);
    const Vec2d a = seg.start.template cast<double>(), b = seg.end.template cast<double>();
    double least = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kSamples; ++i)
      least = std::min(least, oracle::sdf(o, a + (b - a) * (double(i) / (kSamples - 1))));
    const bool got = intersects(seg, s);
    EXPECT_EQ(intersects(s, seg), got);
    if (least < -kMargin) {
      ++hits;
      EXPECT_TRUE(got) << what << " case " << k;
    } else if (least > (b - a).norm() / (kSamples - 1) / 2 + kMargin) {
      ++misses;
      EXPECT_FALSE(got) << what << " case " << k;
    } else {
      ++unsure;
    }
  }
  EXPECT_LE(unsure, kCases / 100) << what;
  EXPECT_GE(hits, kCases / 10) << what;
  EXPECT_GE(misses, kCases / 10) << what;
}

TYPED_TEST(Oracle2d, SegmentTestsMatchSampling) {
  using T = TypeParam;
  checkSegments<T>([](workloads::Random& r) { return randomCircle<T>(r); }, 301, "circle");
  checkSegments<T>([](workloads::Random& r) { return randomRect<T>(r); }, 302, "rect");
  checkSegments<T>([](workloads::Random& r) { return randomOriented<T>(r); }, 303, "oriented");
}

// Raycasts against sampling along the ray (spacing 0.005, from t = 0 until the ray is past the
// shape: t > |origin - center| + size, where the distance to the shape only grows). A hit point
// lies on the boundary, no sample before it is inside, its normal faces the ray and points out (one
// step of 1e-3 along it leaves the shape by 1e-3). Some origins are snapped onto a rectangle's slab
// lines and some directions are axis-aligned.
template <class T, class Gen>
void checkRays(Gen gen, std::uint64_t seed, const char* what) {
  workloads::Random rng(seed);
  int unsure = 0, hits = 0, misses = 0, insides = 0;
  constexpr int kCases = 1500;
  constexpr double kStep = 0.005, kFar = 40;
  for (int k = 0; k < kCases; ++k) {
    const auto s = gen(rng);
    const oracle::Shape o = oracle::of(s);
    Vec2<T> origin(rng.uniform(-8, 8), rng.uniform(-8, 8));
    if constexpr (std::is_same_v<decltype(s), const RectT<T>>) {
      if (k % 5 == 0) origin.x() = k % 10 == 0 ? s.min.x() : s.max.x();  // on a slab line
    }
    // Odd cases aim near the shape (so that about half the rays hit), even ones anywhere.
    const Vec2d toShape = o.c - origin.template cast<double>();
    const double angle = k % 2 == 1
                             ? std::atan2(toShape.y(), toShape.x()) + rng.uniform(-0.4f, 0.4f)
                             : double(rng.uniform(-3.2f, 3.2f));
    Vec2<T> dir = v<T>(std::cos(angle), std::sin(angle));
    if (k % 7 == 0 && k % 5 != 0)  // axis-aligned: zero direction components
      dir = k % 14 == 0 ? v<T>(dir.x() < 0 ? -1 : 1, 0) : v<T>(0, dir.y() < 0 ? -1 : 1);
    const Ray2T<T> r{origin, dir};
    const Vec2d od = origin.template cast<double>(), dd = dir.template cast<double>();
    // Beyond |origin - center| + size the ray is past the shape: sample up to there.
    const double far = std::min(kFar, (od - o.c).norm() + 2 * o.size() + 1);
    double least = std::numeric_limits<double>::infinity(), firstIn = kFar;
    for (double t = 0; t <= far; t += kStep) {
      const double d = oracle::sdf(o, od + t * dd);
      least = std::min(least, d);
      if (d < -kMargin && firstIn == kFar) firstIn = t;
    }
    const auto hit = raycast(r, s);
    if (least > kStep / 2 + kMargin) {
      ++misses;
      EXPECT_FALSE(hit) << what << " case " << k;
      continue;
    }
    if (least >= -kMargin) {
      ++unsure;
      continue;
    }
    ++hits;
    ASSERT_TRUE(hit) << what << " case " << k;
    const double start = oracle::sdf(o, od);
    if (start < -kMargin) {
      ++insides;
      EXPECT_TRUE(hit->inside) << what << " case " << k;
      EXPECT_EQ(hit->t, T(0));
      continue;
    }
    if (start > kMargin) {
      EXPECT_FALSE(hit->inside) << what << " case " << k;
    }
    if (hit->inside) continue;
    // Tolerance: 64 eps * (distance + size): t is a quotient of offsets of that magnitude.
    const double tol = 64 * double(kEps<T>) * ((od - o.c).norm() + o.size() + far);
    const Vec2d p = hit->point.template cast<double>(), n = hit->normal.template cast<double>();
    EXPECT_NEAR(oracle::sdf(o, p), 0, tol) << what << " case " << k;
    EXPECT_LE(double(hit->t), firstIn + tol) << what << " case " << k;
    EXPECT_NEAR((p - od).norm(), double(hit->t), tol) << what << " case " << k;
    EXPECT_NEAR(n.norm(), 1, 4 * double(kEps<T>)) << what << " case " << k;
    EXPECT_LE(n.dot(dd), tol) << what << " case " << k;
    EXPECT_NEAR(oracle::sdf(o, p + 1e-3 * n), 1e-3, 1e-5 + tol) << what << " case " << k;
  }
  EXPECT_LE(unsure, kCases / 100) << what;
  EXPECT_GE(hits, kCases / 10) << what;
  EXPECT_GE(misses, kCases / 10) << what;
  EXPECT_GE(insides, kCases / 100) << what;
}

TYPED_TEST(Oracle2d, RaycastsMatchSampling) {
  using T = TypeParam;
  checkRays<T>([](workloads::Random& r) { return randomCircle<T>(r); }, 401, "circle");
  checkRays<T>([](workloads::Random& r) { return randomRect<T>(r); }, 402, "rect");
  checkRays<T>([](workloads::Random& r) { return randomOriented<T>(r); }, 403, "oriented");
}

// Welzl against brute force: the smallest of the diameter circles of all pairs and the
// circumcircles of all triples that contain every point (in double). Point sets of 1 to 12,
// half of them snapped to a 0.5 grid (duplicates, collinear triples, cocircular points).
TYPED_TEST(Oracle2d, ContainingCircleIsMinimal) {
  using T = TypeParam;
  workloads::Random rng(501);
  for (int k = 0; k < 400; ++k) {
    const int n = 1 + int(rng.next() % 12);
    std::vector<Vec2<T>> points;
    for (int i = 0; i < n; ++i) {
      float x = rng.uniform(-4, 4), y = rng.uniform(-4, 4);
      if (k % 2 == 0) x = std::round(x * 2) / 2, y = std::round(y * 2) / 2;
      points.push_back(Vec2<T>(x, y));
    }
    const CircleT<T> c = containingCircle(points);
    for (const Vec2<T>& p : points) EXPECT_TRUE(contains(c, p)) << "case " << k;  // no tolerance
    std::vector<Vec2d> pd;
    double spread = 0;
    for (const Vec2<T>& p : points) pd.push_back(p.template cast<double>());
    for (const Vec2d& p : pd) spread = std::max(spread, (p - pd[0]).norm());
    double best = n == 1 ? 0 : std::numeric_limits<double>::infinity();
    const auto consider = [&](const Vec2d& center, double radius) {
      for (const Vec2d& p : pd)
        if ((p - center).norm() > radius * (1 + 1e-12) + 1e-12) return;
      best = std::min(best, radius);
    };
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        consider((pd[i] + pd[j]) / 2, (pd[i] - pd[j]).norm() / 2);
        for (int l = j + 1; l < n; ++l) {
          const Vec2d ab = pd[j] - pd[i], ac = pd[l] - pd[i];
          const double cross = ab.x() * ac.y() - ab.y() * ac.x();
          if (std::abs(cross) < 1e-12) continue;
          const Vec2d center =
              pd[i] + Vec2d(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                            ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) /
                          (2 * cross);
          consider(center, (pd[i] - center).norm());
        }
      }
    // Tolerance: 64 eps * spread (the circumcenter's rounding; the final pass may grow the radius
    // by the rounding of a distance).
    EXPECT_NEAR(double(c.radius), best, 64 * double(kEps<T>) * std::max(spread, 1.0))
        << "case " << k << ", " << n << " points";
  }
}

TYPED_TEST(Oracle2d, ContainingRectIsTheMinMax) {
  using T = TypeParam;
  workloads::Random rng(502);
  for (int k = 0; k < 100; ++k) {
    std::vector<Vec2<T>> points;
    const int n = 1 + int(rng.next() % 20);
    for (int i = 0; i < n; ++i) points.push_back(Vec2<T>(rng.uniform(-9, 9), rng.uniform(-9, 9)));
    const RectT<T> r = containingRect(points);
    for (const Vec2<T>& p : points) EXPECT_TRUE(contains(r, p));
    // Every side touches a point (exact).
    const auto touches = [&](auto side) { return std::any_of(points.begin(), points.end(), side); };
    EXPECT_TRUE(touches([&](const Vec2<T>& p) { return p.x() == r.min.x(); }));
    EXPECT_TRUE(touches([&](const Vec2<T>& p) { return p.x() == r.max.x(); }));
    EXPECT_TRUE(touches([&](const Vec2<T>& p) { return p.y() == r.min.y(); }));
    EXPECT_TRUE(touches([&](const Vec2<T>& p) { return p.y() == r.max.y(); }));
  }
}

}  // namespace
}  // namespace simdphys

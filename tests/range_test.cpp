// The supported range (math.hpp: kMaxCoordinate, docs/architecture.md), 2D and 3D: values outside
// it are rejected where they enter (validate(), the streams, the batch queries' arguments) with
// an Error saying what and where; inside it, at its edges, every query answers right and every
// path (OnEveryPath) agrees with the reference. Issue 11, section 3.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "expect_error.hpp"
#include "paths.hpp"
#include "simdphys/geometry2d.hpp"
#include "simdphys/geometry2d/batch.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/geometry3d/batch.hpp"

namespace simdphys {
namespace {

using test::expectError;
using test::OnEveryPath;
using Ids = std::vector<std::uint32_t>;

constexpr float kMax = kMaxCoordinate;  // 1e18f
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kEps = std::numeric_limits<float>::epsilon();

// A rotation by `angle` about z.
Mat3f turnZ(float angle) { return Eigen::AngleAxisf(angle, Vec3f::UnitZ()).toRotationMatrix(); }

// ---- what enters: validate() and the streams ----------------------------------------------------

TEST(Range, PrimitivesOutsideTheRangeAreRejected3d) {
  // The message: field and axis, value, the range.
  expectError(
      [] {
        validate(Aabb{{0, 0, 0}, {1, 1e20f, 1}}, "here");
      },
      "here: max.y is 1e+20, outside the supported range +-1e+18");
  expectError([] { validate(Aabb{{0, -1e20f, 0}, {1, 1, 1}}, "here"); }, "min.y is -1e+20");
  expectError([] { validate(Aabb{{0, kNaN, 0}, {1, 1, 1}}, "here"); }, "min.y is nan, not finite");
  expectError([] { validate(Sphere{{-1e20f, 0, 0}, 1}, "s"); }, "s: center.x is -1e+20, outside");
  expectError([] { validate(Sphere{{0, 0, 0}, 2e18f}, "s"); }, "center +- radius reaches");
  expectError([] { validate(Sphere{{0, 0, 0.6e18f}, 0.5e18f}, "s"); }, "on z, outside");
  expectError([] { validate(Segment{{0, 0, 0}, {0, 0, 3e18f}}, "g"); }, "g: end.z is 3e+18");
  expectError([] { validate(Ray{{0, 2e18f, 0}, {1, 0, 0}}, "r"); }, "r: origin.y is 2e+18");
  expectError([] { validate(Plane{{0, 1, 0}, -2e18f}, "p"); }, "p: d is -2e+18, outside");
  expectError([] { validate(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1e19f, 0}}, "t"); }, "t: c.y is");
  expectError(
      [] {
        validate(Obb{{1e19f, 0, 0}, {1, 1, 1}, Mat3f::Identity()}, "b");
      },
      "b: center.x is 1e+19");
  expectError(
      [] {
        validate(Obb{{0, 0, 0}, {1, 2e18f, 1}, Mat3f::Identity()}, "b");
      },
      "b: halfExtents.y is 2e+18");
  // Turned by 45 degrees, half extents of 0.71e18 reach 0.71e18 * sqrt(2) = 1.004e18 on x and y.
  expectError(
      [] {
        validate(Obb{{0, 0, 0}, {0.71e18f, 0.71e18f, 1}, turnZ(0.785398163f)}, "b");
      },
      "b: the box (center +- |axes| halfExtents) reaches");
  // The same in double: the range is the same for both scalars.
  expectError([] { validate(Sphered{{0, 0, 0}, 1.5e18}, "d"); }, "center +- radius reaches");
  expectError([] { validate(Aabbd{{0, 0, -1e30}, {1, 1, 1}}, "d"); }, "min.z is -1e+30, outside");
}

TEST(Range, PrimitivesAtTheEdgeOfTheRangeAreAccepted3d) {
  validate(Aabb{{-kMax, -kMax, -kMax}, {kMax, kMax, kMax}}, "edge");
  validate(Sphere{{0.5e18f, 0, 0}, 0.5e18f}, "edge");
  validate(Sphere{{-kMax, kMax, 0}, 0}, "edge");
  validate(Segment{{-kMax, 0, 0}, {kMax, 0, 0}}, "edge");
  validate(Ray{{-kMax, 0, 0}, {1, 0, 0}}, "edge");
  validate(Plane{{0, 0, 1}, kMax}, "edge");
  validate(Triangle{{-kMax, 0, 0}, {kMax, 0, 0}, {0, kMax, 0}}, "edge");
  validate(Obb{{0, 0, 0}, {0.7e18f, 0.7e18f, kMax}, turnZ(0.785398163f)}, "edge");  // 0.99e18
  validate(Aabbd{{-1e18, 0, 0}, {1e18f, 1, 1}}, "edge");
}

TEST(Range, PrimitivesOutsideTheRangeAreRejected2d) {
  expectError([] { validate(Vec2f(1e20f, 0), "p"); }, "p: point.x is 1e+20, outside");
  expectError([] { validate(Circle{{0, -1e20f}, 1}, "c"); }, "c: center.y is -1e+20");
  expectError([] { validate(Circle{{0, 0}, 2e18f}, "c"); }, "c: center +- radius reaches 2e+18");
  expectError([] { validate(Circle{{0.6e18f, 0}, 0.5e18f}, "c"); }, "center +- radius reaches");
  expectError([] { validate(Rect{{0, 0}, {3e18f, 1}}, "r"); }, "r: max.x is 3e+18");
  expectError([] { validate(Segment2{{0, 0}, {0, 3e18f}}, "s"); }, "s: end.y is 3e+18");
  expectError([] { validate(Ray2{{-3e18f, 0}, {1, 0}}, "y"); }, "y: origin.x is -3e+18");
  expectError(
      [] {
        validate(OrientedRect{{0, 0}, {0.71e18f, 0.71e18f}, 0.785398163f}, "o");
      },
      "o: the rectangle (center +- |axes| halfExtents) reaches");
  expectError([] { validate(OrientedRect{{0, 0}, {1, 1}, kInf}, "o"); }, "rotation is inf");
  // Edges: accepted. A rotation is an angle, not a coordinate: any finite one.
  validate(Rect{{-kMax, -kMax}, {kMax, kMax}}, "edge");
  validate(Circle{{-0.5e18f, 0}, 0.5e18f}, "edge");
  validate(OrientedRect{{0, 0}, {0.7e18f, 0.7e18f}, 0.785398163f}, "edge");
  validate(OrientedRect{{0, 0}, {1, 1}, 1e30f}, "edge");
  const std::vector<Vec2f> far{{0, 0}, {1e20f, 0}};
  expectError([&] { (void)containingCircle(far); }, "containingCircle: points[1].x is 1e+20");
  expectError([&] { (void)containingRect(far); }, "containingRect: points[1].x is 1e+20");
  const std::vector<Vec2f> nan{{0, 0}, {kNaN, 1}};
  expectError([&] { (void)containingCircle(nan); }, "containingCircle: points[1].x is nan");
}

TEST(Range, StreamsRejectWhatLeavesTheRange) {
  // The BoundsStream: centre 3e38 with extent 1e38 handed out max = inf.
  BoundsStream bounds;
  expectError(
      [&] {
        bounds.push({3e38f, 0, 0}, {1e38f, 1, 1});
      },
      "BoundsStream::push: element 0: center.x is 3e+38, outside");
  expectError(
      [&] {
        bounds.push({0.9e18f, 0, 0}, {0.2e18f, 1, 1});
      },
      "BoundsStream::push: element 0: center +- halfExtents reaches");
  EXPECT_EQ(bounds.size(), 0u);  // state unchanged
  bounds.push({0.5e18f, 0, 0}, {0.5e18f, 1, 1});
  EXPECT_EQ(bounds[0].max.x(), kMax);  // 0.5e18f + 0.5e18f is exactly kMax in float
  EXPECT_EQ(bounds[0].min.x(), 0);

  BoxStream boxes;
  boxes.push({{0, 0, 0}, {1, 1, 1}});
  expectError(
      [&] {
        boxes.push({{0, 0, 0}, {1, 1, 2e18f}});
      },
      "BoxStream::push: element 1: max.z is 2e+18");
  expectError([&] { boxes.set(0, {{-2e18f, 0, 0}, {1, 1, 1}}); }, "BoxStream::set: element 0");
  EXPECT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0].min.x(), 0);
  SphereStream spheres;
  expectError([&] { spheres.push({{0, 0, 0}, 1.5e18f}); }, "SphereStream::push: element 0");
  ObbStream obbs;
  expectError([&] { obbs.push({{0, 0, 2e18f}, {1, 1, 1}}); }, "ObbStream::push: element 0");
  TriangleStream triangles;
  expectError(
      [&] {
        triangles.push({{0, 0, 0}, {1, 0, 0}, {0, 2e18f, 0}});
      },
      "TriangleStream::push: element 0: c.y is 2e+18");
  PointStream points;
  expectError([&] { points.push({0, 0, 1e19f}); }, "PointStream::push: element 0: point.z");

  CircleStream circles;
  expectError([&] { circles.push({{1e19f, 0}, 1}); }, "CircleStream::push: element 0: center.x");
  RectStream rects;
  expectError([&] { rects.push({{0, 0}, {1, 1e19f}}); }, "RectStream::push: element 0: max.y");
  OrientedRectStream orects;
  expectError(
      [&] {
        orects.push({{0, 0}, {2e18f, 1}, 0});
      },
      "OrientedRectStream::push: element 0: halfExtents.x");
  EXPECT_EQ(circles.size() + rects.size() + orects.size(), 0u);
}

// ---- valid input accepted: directions of any finite non-zero length -----------------------------

TEST(Range, RayFromToAndPlaneFromPointNormalScaleBeforeNormalising) {
  // |d|^2 of 1e-25 underflows and of 1e20 overflows in float; the directions are exactly the
  // normalised ones up to the rounding of one division by the norm (2 eps).
  for (const float length : {1e-25f, 1e-40f, kMax}) {
    const Ray r = Ray::fromTo({0, 0, 0}, {length, 0, 0});
    EXPECT_EQ(r.direction, Vec3f(1, 0, 0)) << length;  // one non-zero component: exact
  }
  const Ray tiny = Ray::fromTo({1, 1, 1}, {1, 1 + 1.2e-7f, 1 + 1.2e-7f});  // ulps of 1
  EXPECT_NEAR(tiny.direction.y(), std::numbers::sqrt2_v<float> / 2, 2 * kEps);
  EXPECT_NEAR(tiny.direction.z(), std::numbers::sqrt2_v<float> / 2, 2 * kEps);
  const Ray small = Ray::fromTo({0, 0, 0}, {3e-25f, 4e-25f, 0});
  EXPECT_NEAR(small.direction.x(), 0.6f, 2 * kEps);
  EXPECT_NEAR(small.direction.y(), 0.8f, 2 * kEps);
  const Ray subnormal = Ray::fromTo({0, 0, 0}, {0, 0, -1e-40f});
  EXPECT_EQ(subnormal.direction, Vec3f(0, 0, -1));  // one non-zero component: exact
  const Ray across = Ray::fromTo({-kMax, -kMax, 0}, {kMax, kMax, 0});  // 2.8e18 long
  EXPECT_NEAR(across.direction.x(), std::numbers::sqrt2_v<float> / 2, 2 * kEps);
  EXPECT_NEAR(across.direction.y(), std::numbers::sqrt2_v<float> / 2, 2 * kEps);
  expectError([] { (void)Ray::fromTo({1, 2, 3}, {1, 2, 3}); }, "coincide");
  expectError(
      [] {
        (void)Ray::fromTo({0, 0, 0}, {1e20f, 0, 0});
      },
      "Ray::fromTo: target.x is 1e+20");
  const Ray2 r2 = Ray2::fromTo({0, 0}, {3e-25f, -4e-25f});
  EXPECT_NEAR(r2.direction.x(), 0.6f, 2 * kEps);
  EXPECT_NEAR(r2.direction.y(), -0.8f, 2 * kEps);
  const Ray2 r2far = Ray2::fromTo({-kMax, kMax}, {kMax, -kMax});
  EXPECT_NEAR(r2far.direction.x(), std::numbers::sqrt2_v<float> / 2, 2 * kEps);
  expectError(
      [] {
        (void)Ray2::fromTo({1, 2}, {1, 2});
      },
      "Ray2::fromTo: origin and target coincide");

  for (const float length : {1e-25f, 1e-40f, 1e20f, 3e38f}) {
    const Plane p = Plane::fromPointNormal({0, 0, 5}, {0, 0, length});
    EXPECT_EQ(p.normal, Vec3f(0, 0, 1)) << length;  // one non-zero component: exact
    EXPECT_EQ(p.d, -5) << length;
  }
  const Plane tilted = Plane::fromPointNormal({0, 0, 0}, {3e20f, 4e20f, 0});
  EXPECT_NEAR(tilted.normal.x(), 0.6f, 2 * kEps);
  EXPECT_NEAR(tilted.normal.y(), 0.8f, 2 * kEps);
  expectError([] { (void)Plane::fromPointNormal({1, 2, 3}, {0, 0, 0}); }, "normal is zero");
  expectError([] { (void)Plane::fromPointNormal({1, 2, 3}, {0, kInf, 0}); }, "not finite");
  // A plane through a corner of the range is 1.7e18 from the origin: beyond the range of d.
  expectError([] { (void)Plane::fromPointNormal({kMax, kMax, kMax}, {1, 1, 1}); }, "d is -1.7");
}

TEST(Range, QuadtreeQueriesValidateTheirArgument) {
  Quadtree tree(Rect{{-kMax, -kMax}, {kMax, kMax}});
  tree.insert(7, {{0.5e18f, 0.5e18f}, {kMax, kMax}});
  expectError([&] { (void)tree.query(Rect{{0, 0}, {kNaN, 1}}); }, "Quadtree::query: max.x is nan");
  expectError([&] { (void)tree.query(Circle{{0, 0}, -1}); }, "Quadtree::query: radius is -1");
  expectError([&] { (void)tree.query(Vec2f(2e18f, 0)); }, "Quadtree::query: point.x is 2e+18");
  expectError([&] { tree.insert(8, {{0, 0}, {1, 3e18f}}); }, "Quadtree::insert: box of id 8");
  EXPECT_EQ(tree.query(Vec2f(kMax, kMax)), std::vector<std::uint32_t>{7});  // the corner
  EXPECT_EQ(tree.query(Circle{{-0.5e18f, -0.5e18f}, 0.5e18f}), std::vector<std::uint32_t>{});
}

// ---- bad arguments of the batch queries ---------------------------------------------------------

class RangeBatch : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(RangeBatch);

TEST_P(RangeBatch, RaycastsRejectANegativeOrNaNTMax) {
  BoxStream boxes;
  boxes.push({{1, -1, -1}, {2, 1, 1}});
  SphereStream spheres;
  spheres.push({{3, 0, 0}, 1});
  TriangleStream triangles;
  triangles.push({{2, -1, -1}, {2, 1, -1}, {2, 0, 1}});
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  for (const float tMax : {kNaN, -1.0f, -kInf}) {
    expectError([&] { (void)raycast(ray, boxes, tMax); }, "raycast: tMax");
    expectError([&] { (void)raycast(ray, spheres, tMax); }, "is negative or NaN");
    expectError([&] { (void)raycast(ray, triangles, tMax); }, "raycast: tMax");
  }
  // tMax = 0 and +inf are valid: the ray starts outside, so 0 misses and inf hits.
  EXPECT_FALSE(raycast(ray, boxes, 0.0f).hit());
  ASSERT_TRUE(raycast(ray, spheres, kInf).hit());
  EXPECT_EQ(raycast(ray, spheres, kInf).t, 2);
  // Out-of-range rays are rejected like the streams' elements.
  expectError(
      [&] {
        (void)raycast(Ray{{-1e20f, 0, 0}, {1, 0, 0}}, spheres);
      },
      "raycast: origin.x is -1e+20");
}

TEST_P(RangeBatch, QueriesRejectArgumentsOutsideTheRange) {
  SphereStream spheres;
  BoxStream boxes;
  ObbStream obbs;
  PointStream out;
  Ids ids;
  expectError(
      [&] {
        overlapping(Sphere{{1e20f, 0, 0}, 1}, spheres, ids);
      },
      "overlapping: center.x");
  expectError([&] { overlapping(Sphere{{0, 0, 0}, 2e18f}, boxes, ids); }, "overlapping: center +-");
  expectError([&] { overlapping(Obb{{0, 0, 0}, {2e18f, 1, 1}}, obbs, ids); }, "overlapping: half");
  expectError([&] { containing(Vec3f(0, kNaN, 0), boxes, ids); }, "containing: point.y is nan");
  expectError([&] { closestPoints(Vec3f(0, 0, 2e18f), boxes, out); }, "closestPoints: point.z");
  CircleStream circles;
  RectStream rects;
  OrientedRectStream orects;
  expectError(
      [&] {
        overlapping(Circle{{0, 0}, 3e18f}, circles, ids);
      },
      "overlapping: center +- radius");
  expectError([&] { overlapping(Rect{{0, 0}, {1, 3e18f}}, rects, ids); }, "overlapping: max.y");
  expectError(
      [&] {
        overlapping(OrientedRect{{2e18f, 0}, {1, 1}, 0}, orects, ids);
      },
      "overlapping: center.x");
  expectError([&] { containing(Vec2f(-2e18f, 0), circles, ids); }, "containing: point.x");
}

// ---- inside the range, at its edges: right answers on every path -------------------------------

// Relative error of a float result against an exact (double) value.
double relativeError(double got, double want) { return std::abs(got - want) / std::abs(want); }

// The spheres, 2e20 apart, are out of range; at the corners of the range, 2.6e18 apart
// (|d|^2 = 6.8e36, finite in float), they are apart on every path, and spheres that touch at the
// origin (reach 1e18) or miss by 1e14 (26 times the tolerance, 16 eps * 2e18 = 3.8e12) are told
// apart.
TEST_P(RangeBatch, SpheresAtTheEdgesOfTheRange) {
  expectError([] { validate(Sphere{{-1e20f, 0, 0}, 1}, "intersects"); }, "center.x is -1e+20");
  const Sphere low{{-0.75e18f, -0.75e18f, -0.75e18f}, 0.25e18f},
      high{{0.75e18f, 0.75e18f, 0.75e18f}, 0.25e18f};
  const Sphere left{{-0.5e18f, 0, 0}, 0.5e18f}, right{{0.5e18f, 0, 0}, 0.5e18f};
  const Sphere apart{{0.5e18f, 0, 0}, 0.4999e18f};  // 1e14 short of the origin
  EXPECT_FALSE(intersects(low, high));
  EXPECT_TRUE(intersects(left, right));
  EXPECT_FALSE(intersects(left, apart));
  SphereStream spheres;
  for (const Sphere& s : {high, right, apart, low}) spheres.push(s);
  Ids ids;
  overlapping(low, spheres, ids);
  EXPECT_EQ(ids, (Ids{3}));  // itself only
  overlapping(left, spheres, ids);
  EXPECT_EQ(ids, (Ids{1}));  // right touches
  BoxStream boxes;
  boxes.push({{0.8e18f, 0.8e18f, 0.8e18f}, {kMax, kMax, kMax}});
  boxes.push({{0, -kMax, -kMax}, {kMax, kMax, kMax}});
  overlapping(low, boxes, ids);
  EXPECT_EQ(ids, Ids{});
  overlapping(left, boxes, ids);
  EXPECT_EQ(ids, (Ids{1}));                         // touches the face x = 0
  containing(Vec3f(kMax, kMax, kMax), boxes, ids);  // the corner of the range is in both
  EXPECT_EQ(ids, (Ids{0, 1}));
  PointStream closest;
  closestPoints(Vec3f(-kMax, -kMax, -kMax), boxes, closest);  // clamps: exact
  ASSERT_EQ(closest.size(), 2u);
  EXPECT_EQ(closest[0], Vec3f::Constant(0.8e18f));
  EXPECT_EQ(closest[1], Vec3f(0, -kMax, -kMax));
}

// Oriented boxes turned by 30 degrees at opposite corners, 2.8e18 apart, and two large boxes
// touching at the origin: separating axis tests with scales of 3e18, on every path.
TEST_P(RangeBatch, OrientedBoxesAtTheEdgesOfTheRange) {
  const Mat3f turn = turnZ(0.523598776f);
  const Obb low{{-0.9e18f, -0.9e18f, 0}, {1e16f, 1e16f, 1e16f}, turn};
  const Obb high{{0.9e18f, 0.9e18f, 0}, {1e16f, 1e16f, 1e16f}, turn};
  const Obb left{{-0.5e18f, 0, 0}, {0.5e18f, 0.5e18f, 0.5e18f}, Mat3f::Identity()};
  const Obb right{{0.5e18f, 0, 0}, {0.5e18f, 0.5e18f, 0.5e18f}, Mat3f::Identity()};
  const Obb apart{{0.5e18f, 0, 0}, {0.4999e18f, 0.5e18f, 0.5e18f}, Mat3f::Identity()};
  EXPECT_FALSE(intersects(low, high));
  EXPECT_TRUE(intersects(left, right));
  EXPECT_FALSE(intersects(left, apart));  // 1e14 apart, tolerance 16 eps * 4e18 = 7.6e12
  EXPECT_FALSE(intersects(Aabb{{-kMax, -kMax, -kMax}, {-0.8e18f, -0.8e18f, -0.8e18f}}, high));
  EXPECT_TRUE(intersects(Aabb{{0, -kMax, -kMax}, {kMax, kMax, kMax}}, left));
  ObbStream boxes;
  for (const Obb& b : {high, right, apart, low}) boxes.push(b);
  Ids ids;
  overlapping(low, boxes, ids);
  EXPECT_EQ(ids, (Ids{3}));
  overlapping(left, boxes, ids);
  EXPECT_EQ(ids, (Ids{1}));
}

TEST_P(RangeBatch, CirclesAndOrientedRectanglesAtTheEdgesOfTheRange) {
  const Circle low{{-0.75e18f, -0.75e18f}, 0.25e18f}, high{{0.75e18f, 0.75e18f}, 0.25e18f};
  const Circle left{{-0.5e18f, 0}, 0.5e18f}, right{{0.5e18f, 0}, 0.5e18f};
  const Circle apart{{0.5e18f, 0}, 0.4999e18f};
  EXPECT_FALSE(intersects(low, high));
  EXPECT_TRUE(intersects(left, right));
  EXPECT_FALSE(intersects(left, apart));
  CircleStream circles;
  for (const Circle& c : {high, right, apart}) circles.push(c);
  Ids ids;
  overlapping(low, circles, ids);
  EXPECT_EQ(ids, Ids{});
  overlapping(left, circles, ids);
  EXPECT_EQ(ids, (Ids{1}));
  containing(Vec2f(0.75e18f, 0.75e18f), circles, ids);
  EXPECT_EQ(ids, (Ids{0}));

  const OrientedRect rlow{{-0.9e18f, -0.9e18f}, {1e16f, 1e16f}, 0.5f};
  const OrientedRect rhigh{{0.9e18f, 0.9e18f}, {1e16f, 1e16f}, 0.5f};
  const OrientedRect rleft{{-0.5e18f, 0}, {0.5e18f, 0.5e18f}, 0};
  const OrientedRect rright{{0.5e18f, 0}, {0.5e18f, 0.5e18f}, 0};
  const OrientedRect rapart{{0.5e18f, 0}, {0.4999e18f, 0.5e18f}, 0};
  EXPECT_FALSE(intersects(rlow, rhigh));
  EXPECT_TRUE(intersects(rleft, rright));
  EXPECT_FALSE(intersects(rleft, rapart));
  EXPECT_FALSE(intersects(Rect{{-kMax, -kMax}, {-0.8e18f, -0.8e18f}}, rhigh));
  OrientedRectStream rects;
  for (const OrientedRect& r : {rhigh, rright, rapart}) rects.push(r);
  overlapping(rlow, rects, ids);
  EXPECT_EQ(ids, Ids{});
  overlapping(rleft, rects, ids);
  EXPECT_EQ(ids, (Ids{1}));
  containing(Vec2f(0.9e18f, 0.9e18f), rects, ids);
  EXPECT_EQ(ids, (Ids{0}));
}

// The unit sphere raycast from x = -1e20 (t = inf on the reference, a miss on SIMD) is out
// of range; from -1e18 it hits at t = 1e18 - 1 on every path, within 2 eps relative (the rounding
// of c0 / dd / (b + f), a few operations of relative error eps / 2 each).
TEST_P(RangeBatch, SphereRaycastsFromTheEdgeOfTheRange) {
  SphereStream unit;
  unit.push({{0, 0, 0}, 1});
  const ElementHit hit = raycast(Ray{{-kMax, 0, 0}, {1, 0, 0}}, unit);
  ASSERT_TRUE(hit.hit());
  EXPECT_LE(relativeError(hit.t, double(kMax) - 1), 2 * kEps);
  EXPECT_FALSE(raycast(Ray{{-kMax, 2, 0}, {1, 0, 0}}, unit).hit());  // passes 2 from the centre
  // Corner to corner: t = |c - o| - r exactly, 3.03e18 - 2.5e17, within 4 eps (|e|^2 and the
  // quotient add a few roundings more than along an axis).
  SphereStream far;
  far.push({{0.75e18f, 0.75e18f, 0.75e18f}, 0.25e18f});
  const float k = 1 / std::sqrt(3.0f);
  const Ray diagonal{{-kMax, -kMax, -kMax}, {k, k, k}};
  const ElementHit corner = raycast(diagonal, far);
  ASSERT_TRUE(corner.hit());
  EXPECT_LE(relativeError(corner.t, 1.75e18 * std::sqrt(3.0) - 0.25e18), 4 * kEps);
  // The batch is the scalar function, bit for bit, on every path.
  const auto scalar = raycast(far[0], diagonal);
  ASSERT_TRUE(scalar);
  EXPECT_EQ(corner.t, scalar->t);
  BoxStream boxes;
  boxes.push({{0.8e18f, 0.8e18f, 0.8e18f}, {kMax, kMax, kMax}});
  const ElementHit box = raycast(diagonal, boxes);
  ASSERT_TRUE(box.hit());
  EXPECT_LE(relativeError(box.t, 1.8e18 * std::sqrt(3.0)), 4 * kEps);  // enters at the corner
}

// GJK and EPA at the edges: their areas and volumes are products of up to four lengths, which
// overflowed float (the gjkDistance near FLT_MAX / 2 gave NaN). The tolerance is GJK's own,
// kGjkTolerance times the size of the problem (here up to 4e18): 7.6e12, relative 4e-6 of the
// distances below.
TEST(Range, GjkAndEpaAtTheEdgesOfTheRange) {
  const double tolerance = 16 * kEps * 4e18;
  const Sphere low{{-0.75e18f, -0.75e18f, -0.75e18f}, 0.25e18f},
      high{{0.75e18f, 0.75e18f, 0.75e18f}, 0.25e18f};
  const GjkResult spheres = gjkDistance(low, high);
  EXPECT_FALSE(spheres.intersecting);
  EXPECT_NEAR(spheres.distance, 1.5e18 * std::sqrt(3.0) - 0.5e18, tolerance);
  // Boxes turned by 45 degrees about z: their local x is the diagonal joining the centres, so
  // their distance is the centres' distance less two half extents.
  const Mat3f turn = turnZ(0.785398163f);
  const Obb a{{-0.8e18f, -0.8e18f, 0}, {1e17f, 1e17f, 1e17f}, turn};
  const Obb b{{0.8e18f, 0.8e18f, 0}, {1e17f, 1e17f, 1e17f}, turn};
  validate(a, "a"), validate(b, "b");  // in range: 0.8e18 + 1e17 sqrt(2) = 0.94e18
  const GjkResult boxes = gjkDistance(a, b);
  EXPECT_FALSE(boxes.intersecting);
  EXPECT_NEAR(boxes.distance, 1.6e18 * std::sqrt(2.0) - 2e17, tolerance);
  EXPECT_TRUE(boxes.pointA.allFinite() && boxes.pointB.allFinite());
  // A segment as long as the range and a sphere beside its middle: the second support point is
  // 2e18 from the first one (GJK rescales its coordinates when it meets it).
  const Segment spine{{0, -kMax, 0}, {0, kMax, 0}};
  const GjkResult side = gjkDistance(spine, Sphere{{3e17f, 5e17f, 0}, 1e17f});
  EXPECT_FALSE(side.intersecting);
  EXPECT_NEAR(side.distance, 2e17, tolerance);
  // Two boxes as large as the range overlapping by 2e17 on x: depth 2e17 along +x.
  const Aabb west{{-kMax, -kMax, -kMax}, {1e17f, kMax, kMax}};
  const Aabb east{{-1e17f, -kMax, -kMax}, {kMax, kMax, kMax}};
  EXPECT_TRUE(gjkIntersect(west, east));
  const auto depth = epa(west, east);
  ASSERT_TRUE(depth);
  // EPA's own tolerance, kEpaTolerance (64 eps) times the size: 3e13, relative 1.5e-4.
  EXPECT_NEAR(depth->depth, 2e17, kEpaTolerance<float> * 4e18);
  EXPECT_NEAR(depth->normal.x(), 1, kEpaTolerance<float>);
}

// GJK and EPA are invariant, to the bit, under scaling by a power of two (which is exact): they
// scale their local coordinates to about 1 themselves. So pairs of turned boxes of size 1,
// which the GJK tests check against oracles, give exactly the scaled answers at sizes from
// 2^-60 (8.7e-19) to 2^57 (1.4e17). Before, areas and volumes (products of up to four lengths)
// underflowed at 1e-15 (distance off by 0.25%, EPA missing the overlap) and overflowed at 1e17.
TEST(Range, GjkAndEpaAreExactlyScaleInvariant) {
  const Mat3f turn = Eigen::AngleAxisf(0.5f, Vec3f(1, 2, 3).normalized()).toRotationMatrix();
  const auto scaled = [&](const Obb& b, float s) {
    return Obb{b.center * s, b.halfExtents * s, b.axes};
  };
  const Obb a{{0, 0, 0}, {1, 2, 1}, turn};
  const Obb apart{{5, 1, 0}, {1, 1, 1}, Mat3f::Identity()};
  const Obb overlapping{{1.5f, 1, 0}, {1, 1, 1}, Mat3f::Identity()};
  const GjkResult distance = gjkDistance(a, apart);
  const auto depth = epa(a, overlapping);
  ASSERT_FALSE(distance.intersecting);
  ASSERT_TRUE(depth);
  for (const int k : {-60, -50, -20, 20, 50, 57}) {
    const float s = std::ldexp(1.0f, k);
    const GjkResult d = gjkDistance(scaled(a, s), scaled(apart, s));
    EXPECT_FALSE(d.intersecting) << k;
    EXPECT_EQ(d.distance, distance.distance * s) << k;
    EXPECT_EQ(d.pointA, distance.pointA * s) << k;
    EXPECT_EQ(d.pointB, distance.pointB * s) << k;
    const auto e = epa(scaled(a, s), scaled(overlapping, s));
    ASSERT_TRUE(e) << k;
    EXPECT_EQ(e->depth, depth->depth * s) << k;
    EXPECT_EQ(e->normal, depth->normal) << k;
  }
}

// containingCircle of points at the corners of the range: the circumcircle's centre is a ratio of
// cubes of lengths (8e54 in float). Three points whose circle is known: centre (0, -2.5e17),
// radius 1.25e18; a fourth inside. Within 4 eps relative of the size (a few roundings of the
// scaled circumcentre), and every point contained.
TEST(Range, ContainingCircleAtTheEdgesOfTheRange) {
  const std::vector<Vec2f> points{{-kMax, -kMax}, {kMax, -kMax}, {0, kMax}, {1e17f, 2e17f}};
  const Circle c = containingCircle(points);
  EXPECT_LE(std::abs(c.center.x()), 4 * kEps * 1.25e18);
  EXPECT_LE(std::abs(c.center.y() + 2.5e17), 4 * kEps * 1.25e18);
  EXPECT_LE(relativeError(c.radius, 1.25e18), 4 * kEps);
  for (const Vec2f& p : points) EXPECT_TRUE(contains(c, p));
}

// closestPoints of two segments 2e18 and 2.8e18 long crossing 5e17 apart (the 2e20 ones
// gave NaN: |d1 x d2|^2 ~ L^4 overflowed): the closest points are the middles, (0, 0, 0) and
// (0, 0, 5e17). Within 4 eps * 2e18 = 9.5e11 (the coordinates' own precision, a few ulps of 1e18).
TEST(Range, SegmentClosestPointsAtTheEdgesOfTheRange) {
  const Segment x{{-kMax, 0, 0}, {kMax, 0, 0}};
  const Segment diagonal{{-kMax, -kMax, 5e17f}, {kMax, kMax, 5e17f}};
  const double tolerance = 4 * kEps * 2e18;
  for (const auto& [first, second] : {std::pair{x, diagonal}, std::pair{diagonal, x}}) {
    const SegmentClosestPoints c = closestPoints(first, second);
    EXPECT_NEAR(c.s, 0.5, 4 * kEps);
    EXPECT_NEAR(c.t, 0.5, 4 * kEps);
    EXPECT_NEAR(c.distance, 5e17, tolerance);
    EXPECT_NEAR(c.first.x(), 0, tolerance);
    EXPECT_NEAR(c.first.y(), 0, tolerance);
    EXPECT_NEAR(std::abs(c.first.z() - c.second.z()), 5e17, tolerance);
  }
}

}  // namespace
}  // namespace simdphys

// Batch forms of the 3D queries: on every path, exactly the answers of the scalar functions
// applied element by element (same indices, same booleans, bit-identical t).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "box_sets.hpp"
#include "expect_error.hpp"
#include "paths.hpp"
#include "simdphys/geometry3d/batch.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "simdphys/geometry3d/raycast.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

SphereStream randomSpheres(std::uint64_t seed, std::size_t n, float spread) {
  workloads::Random r(seed);
  SphereStream s;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3f c(r.uniform(-spread, spread), r.uniform(-spread, spread), r.uniform(-spread, spread));
    s.push({c, r.uniform(0, 3)});
  }
  return s;
}

// The oracle: the scalar function applied to every element.
template <class Test>
std::vector<std::uint32_t> each(std::size_t n, Test test) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < n; ++i)
    if (test(i)) ids.push_back(i);
  return ids;
}

template <class Stream>
ElementHit firstHit(const Ray& ray, const Stream& s, float tMax) {
  ElementHit best;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    if (auto h = raycast(s[i], ray, tMax); h && (!best.hit() || h->t < best.t)) best = {i, h->t};
  return best;
}

void expectSameHit(const ElementHit& got, const ElementHit& want) {
  ASSERT_EQ(got.hit(), want.hit());
  if (!want.hit()) return;
  EXPECT_EQ(got.index, want.index);
  EXPECT_EQ(got.t, want.t);  // the kernels mirror the scalar arithmetic: bit-identical
}

class Batch3d : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Batch3d);

TEST_P(Batch3d, SphereQueriesEqualTheScalarTests) {
  const SphereStream spheres = randomSpheres(41, 1001, 30);  // 1001: a partial last vector
  const BoxStream boxes = test::randomBoxes(42, 1003, 30, 0.1f, 3);
  workloads::Random r(43);
  std::vector<std::uint32_t> got;
  for (int q = 0; q < 200; ++q) {
    const Sphere s{{r.uniform(-35, 35), r.uniform(-35, 35), r.uniform(-35, 35)}, r.uniform(0, 6)};
    overlapping(s, spheres, got);
    ASSERT_EQ(got, each(spheres.size(), [&](auto i) { return intersects(s, spheres[i]); }));
    overlapping(s, boxes, got);
    ASSERT_EQ(got, each(boxes.size(), [&](auto i) { return intersects(s, boxes[i]); }));
    containing(s.center, boxes, got);
    ASSERT_EQ(got, each(boxes.size(), [&](auto i) { return contains(boxes[i], s.center); }));
  }
}

// Exactly touching: distances that are exact in float (3-4-5 triangles, faces at integers).
TEST_P(Batch3d, TouchingShapesCount) {
  SphereStream spheres;
  spheres.push({{3, 4, 0}, 3});     // distance 5 = 2 + 3: touches
  spheres.push({{3, 4, 0}, 2.5f});  // 0.5 short of touching
  spheres.push({{0, 0, 0}, 0});     // a point at the query's centre
  BoxStream boxes;
  boxes.push({{2, -1, -1}, {3, 1, 1}});      // face at x = 2: touches a sphere of radius 2
  boxes.push({{2.5f, 0, 0}, {2.5f, 0, 0}});  // a point outside
  boxes.push({{-1, -1, -1}, {1, 1, 1}});     // contains the centre
  const Sphere s{{0, 0, 0}, 2};
  std::vector<std::uint32_t> got;
  overlapping(s, spheres, got);
  EXPECT_EQ(got, (std::vector<std::uint32_t>{0, 2}));
  overlapping(s, boxes, got);
  EXPECT_EQ(got, (std::vector<std::uint32_t>{0, 2}));
  containing({2, 0, 0}, boxes, got);  // on box 0's face
  EXPECT_EQ(got, (std::vector<std::uint32_t>{0}));
}

TEST_P(Batch3d, ClosestPointsEqualTheScalarFunction) {
  const BoxStream boxes = test::randomBoxes(44, 333, 20, 0.0f, 4);
  PointStream points;
  for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(1e5f, -3, 7), Vec3f(-21, 22, -0.0f)}) {
    closestPoints(p, boxes, points);
    ASSERT_EQ(points.size(), boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
      ASSERT_EQ(points[i], closestPoint(boxes[i], p)) << "box " << i;  // a clamp: exact
    for (std::size_t i = points.size(); i < points.padded(); ++i)
      EXPECT_EQ(points.field(fields::Point::x)[i], 0.0f);
  }
}

TEST_P(Batch3d, RaycastsEqualTheScalarRaycast) {
  const SphereStream spheres = randomSpheres(45, 517, 40);
  const BoxStream boxes = test::randomBoxes(46, 519, 40, 0.1f, 3);
  workloads::Random r(47);
  for (int q = 0; q < 300; ++q) {
    const Ray ray{{r.uniform(-50, 50), r.uniform(-50, 50), r.uniform(-50, 50)}, r.unitDirection()};
    const float tMax = q % 3 == 0 ? r.uniform(0, 60) : std::numeric_limits<float>::infinity();
    expectSameHit(raycast(ray, boxes, tMax), firstHit(ray, boxes, tMax));
    expectSameHit(raycast(ray, spheres, tMax), firstHit(ray, spheres, tMax));
  }
}

// Axis-parallel rays with +0 and -0 components, origins on face planes and inside, ties.
TEST_P(Batch3d, RaycastHardCases) {
  BoxStream boxes;
  boxes.push({{0, 0, 0}, {1, 1, 1}});
  boxes.push({{0, 0, 0}, {1, 1, 1}});  // identical: a tie, the smaller index wins
  boxes.push({{3, 0, 0}, {3, 1, 1}});  // flat
  SphereStream spheres;
  spheres.push({{5, 0.5f, 0.5f}, 0.5f});
  spheres.push({{0.5f, 0.5f, 0.5f}, 0.25f});  // contains the inside origin below
  const Ray rays[] = {
      {{-1, 0.5f, 0.5f}, {1, 0, 0}},    // hits box 0 at t = 1
      {{-1, 0, 0.5f}, {1, 0, 0}},       // along the y = 0 face plane, +0 components
      {{-1, 1, 0.5f}, {1, -0.0f, 0}},   // along y = 1 with a -0 component
      {{0.5f, 0.5f, 0.5f}, {1, 0, 0}},  // inside: the exit
      {{-1, 2, 0.5f}, {1, 0, 0}},       // misses everything
      {{1, 0.5f, 0.5f}, {1, 0, 0}},     // starts on a face, heading out
  };
  for (const Ray& ray : rays) {
    for (float tMax : {std::numeric_limits<float>::infinity(), 1.0f, 0.25f}) {
      expectSameHit(raycast(ray, boxes, tMax), firstHit(ray, boxes, tMax));
      expectSameHit(raycast(ray, spheres, tMax), firstHit(ray, spheres, tMax));
    }
  }
  const auto tie = raycast(rays[0], boxes);
  ASSERT_TRUE(tie.hit());
  EXPECT_EQ(tie.index, 0u);
  EXPECT_EQ(tie.t, 1.0f);
  // A miss is the same ElementHit on every path and from every stream: index kNoHit, t = +inf,
  // as a default ElementHit and the mesh raycast's miss.
  TriangleStream triangles;
  triangles.push({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  for (const ElementHit miss : {raycast(rays[4], boxes), raycast(rays[4], spheres),
                                raycast(rays[4], triangles), ElementHit{}}) {
    EXPECT_FALSE(miss.hit());
    EXPECT_EQ(miss.index, kNoHit);
    EXPECT_EQ(miss.t, std::numeric_limits<float>::infinity());
  }
}

// A small heightfield as in W2: two triangles a cell, shared edges and vertices everywhere.
TriangleStream heightfield(int g) {
  TriangleStream t;
  auto vertex = [&](int i, int j) {
    float x = -10 + 20.0f * i / (g - 1), z = -10 + 20.0f * j / (g - 1);
    return Vec3f(x, float(std::sin(0.3 * x) * std::cos(0.2 * z)), z);
  };
  for (int j = 0; j + 1 < g; ++j)
    for (int i = 0; i + 1 < g; ++i) {
      t.push({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      t.push({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  return t;
}

TEST_P(Batch3d, TriangleRaycastsEqualTheScalarRaycast) {
  const TriangleStream mesh = heightfield(9);  // 128 triangles
  workloads::Random r(49);
  int hits = 0;
  for (int q = 0; q < 400; ++q) {
    const Ray ray{{r.uniform(-12, 12), r.uniform(2, 6), r.uniform(-12, 12)}, r.unitDirection()};
    const auto want = firstHit(ray, mesh, std::numeric_limits<float>::infinity());
    hits += want.hit();
    expectSameHit(raycast(ray, mesh), want);
  }
  EXPECT_GT(hits, 50);  // the rays must exercise hits, not only misses
  // Straight down through every vertex and edge midpoint of the grid: shared by 2 to 6
  // triangles, each must hit (watertight), and every path picks the same one.
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 17; ++i) {
      const Ray down{{-10 + 20.0f * i / 16, 5, -10 + 20.0f * j / 8}, {0, -1, 0}};
      const auto got = raycast(down, mesh);
      ASSERT_TRUE(got.hit()) << "leak at " << i << ", " << j;
      expectSameHit(got, firstHit(down, mesh, std::numeric_limits<float>::infinity()));
    }
}

// ---- one OBB against many ----------------------------------------------------------------------

Mat3f randomRotation(workloads::Random& r) {
  return axisAngle(r.unitDirection(), r.uniform(0, 3.14159f));
}

// Boxes of half extents in [minHalf, maxHalf] and random orientation, centres in a cube of side
// 2 * spread about `at`.
ObbStream randomObbs(std::uint64_t seed, std::size_t n, const Vec3f& at, float spread,
                     float minHalf, float maxHalf) {
  workloads::Random r(seed);
  ObbStream s;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f c = at + Vec3f(r.uniform(-spread, spread), r.uniform(-spread, spread),
                               r.uniform(-spread, spread));
    const Vec3f h(r.uniform(minHalf, maxHalf), r.uniform(minHalf, maxHalf),
                  r.uniform(minHalf, maxHalf));
    s.push({c, h, randomRotation(r)});
  }
  return s;
}

ObbStream streamOf(const std::vector<Obb>& boxes) {
  ObbStream s;
  for (const Obb& b : boxes) s.push(b);
  return s;
}

// The batch's answer must be the scalar's, element by element: the same index set.
std::vector<std::uint32_t> expectScalarAnswer(const Obb& box, const ObbStream& boxes) {
  std::vector<std::uint32_t> got;
  const std::size_t count = overlapping(box, boxes, got);
  EXPECT_EQ(count, got.size());
  EXPECT_EQ(got, each(boxes.size(), [&](auto i) { return intersects(box, boxes[i]); }));
  return got;
}

Obb cube(const Vec3f& center, float half, const Mat3f& axes = Mat3f::Identity()) {
  return {center, Vec3f::Constant(half), axes};
}

class ObbBatch : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(ObbBatch);

// Queries of several sizes among boxes of sizes 0.05 to 2 within 6 of them: a good fraction of
// the pairs intersect, many only just (deciding on edge axes). 1001 boxes: a partial last vector.
TEST_P(ObbBatch, RandomBoxesEqualTheScalarTest) {
  const ObbStream boxes = randomObbs(51, 1001, Vec3f::Zero(), 6, 0.05f, 2);
  workloads::Random r(52);
  std::size_t hits = 0;
  for (int q = 0; q < 60; ++q) {
    const Obb box{{r.uniform(-3, 3), r.uniform(-3, 3), r.uniform(-3, 3)},
                  {r.uniform(0, 3), r.uniform(0, 3), r.uniform(0.01f, 3)},
                  randomRotation(r)};
    hits += expectScalarAnswer(box, boxes).size();
  }
  // Both answers must be common for the comparison to mean something: 5% to 95% of the pairs.
  EXPECT_GT(hits, 60 * 1001 / 20);
  EXPECT_LT(hits, 60 * 1001 * 19 / 20);
}

// Boxes right at the tolerance: each placed, along a random direction, at the last float offset
// where the scalar says "intersects" and at the next one (found by bisection), so every lane is
// decided by rounding. The batch must round the same way. A few boxes are also moved by 1e5,
// where the offsets are a few ulp of the coordinates.
TEST_P(ObbBatch, BoxesAtTheToleranceEqualTheScalarTest) {
  workloads::Random r(53);
  for (const Vec3f& base : {Vec3f(0, 0, 0), Vec3f(1e5f, -1e5f, 1e5f)}) {
    const float size = base.isZero() ? 1.0f : 1e-2f;
    const Obb box{base, Vec3f(0.7f, 1.0f, 0.3f) * size, randomRotation(r)};
    std::vector<Obb> near;
    int touching = 0;
    for (int n = 0; n < 100; ++n) {
      Obb other{base, Vec3f(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1)) * size,
                randomRotation(r)};
      const Vec3f dir = r.unitDirection();
      const auto at = [&](float t) {
        Obb o = other;
        o.center = base + t * dir;
        return o;
      };
      // Apart at 5 size: the two boxes reach at most 1.8 + 1.3 size from their centres, and at 1e5
      // rounding the centre moves it by at most 0.7 size.
      float lo = 0, hi = 5 * size;  // intersecting at lo, apart at hi
      for (float mid = (lo + hi) / 2; mid != lo && mid != hi; mid = (lo + hi) / 2)
        (intersects(box, at(mid)) ? lo : hi) = mid;
      near.push_back(at(lo)), near.push_back(at(hi));
      touching += intersects(box, at(lo)) && !intersects(box, at(hi));
    }
    EXPECT_EQ(touching, 100);  // every pair bracketed the change of answer
    expectScalarAnswer(box, streamOf(near));
  }
}

// Exactly parallel edges (identical axes: all nine edge axes skipped; a turn about z: the three
// z-pairs skipped) and nearly parallel ones (turned by 1e-2 to 1e-8 about a general axis, the
// short cross products of intersect.hpp's crossAxis). Expected answers worked by hand: unit cubes
// at x = 2 + g are separated by g on the query's x axis (g > 0) or overlap (g <= 0, touching at 0;
// a tilt by e moves a corner by at most about 1.7 e, under |g|), and so are the 45-degree cubes at
// x = 1 + sqrt2 + g whose vertical edge faces the query's face x = 1.
TEST_P(ObbBatch, ParallelAndNearlyParallelEdges) {
  const Obb unit = cube({0, 0, 0}, 1);
  const float s2 = std::sqrt(2.0f);
  const Mat3f turn45 = axisAngle(Vec3f(0, 0, 1), 0.7853982f);
  for (const float e : {0.0f, 1e-8f, 1e-6f, 1e-4f, 1e-2f}) {
    SCOPED_TRACE(e);
    const Mat3f tilt = e == 0 ? Mat3f::Identity() : axisAngle(Vec3f(0.3f, -0.5f, 0.8f), e);
    std::vector<Obb> boxes;
    std::vector<std::uint32_t> want;
    for (const float g : {-0.1f, 0.0f, 0.1f}) {
      if (g <= 0) want.push_back(std::uint32_t(boxes.size()));
      boxes.push_back(cube({2 + g, 0, 0}, 1, tilt));
      if (g < 0) want.push_back(std::uint32_t(boxes.size()));  // the rotated corner: g = 0 unsure
      boxes.push_back(cube({1 + s2 + g, 0.25f, -0.5f}, 1, tilt * turn45));
    }
    boxes.push_back(cube({0.5f, 0.3f, 0.2f}, 1, tilt));  // deep overlap
    want.push_back(std::uint32_t(boxes.size() - 1));
    std::vector<std::uint32_t> got = expectScalarAnswer(unit, streamOf(boxes));
    got.erase(std::remove(got.begin(), got.end(), 3u), got.end());  // 45 degrees at g = 0
    EXPECT_EQ(got, want);
  }
}

// Touching exactly (faces, edges, corners at exact binary coordinates), and a point or a segment
// (zero extents) on the surface, inside and outside. Worked by hand: the query is [-1, 1]^3.
TEST_P(ObbBatch, TouchingAndZeroSizeBoxes) {
  const Obb unit = cube({0, 0, 0}, 1);
  const std::vector<Obb> boxes = {
      cube({2, 0, 0}, 1),                         // 0: face to face
      cube({2, 2, 0}, 1),                         // 1: edge to edge
      cube({2, -2, 2}, 1),                        // 2: corner to corner
      cube({2.0078125f, 0, 0}, 1),                // 3: apart by 2^-7
      cube({1, 1, 1}, 0),                         // 4: a point on the corner
      cube({0.25f, 0, 0}, 0),                     // 5: a point inside
      cube({1.5f, 0, 0}, 0),                      // 6: a point outside
      {{1, 0, 0}, {0, 0, 3}, Mat3f::Identity()},  // 7: a segment across the face
      {{3, 0, 0}, {0, 0, 1.5f}, axisAngle(Vec3f(0, 1, 0), 0.7853982f)},  // 8: segment ends at 1.94
      cube({0, 0, 0}, 1),                                                // 9: the same box
      cube({0, 0, 0}, 0.5f, axisAngle(Vec3f(1, 1, 1), 0.5f)),            // 10: inside, turned
  };
  EXPECT_EQ(expectScalarAnswer(unit, streamOf(boxes)),
            (std::vector<std::uint32_t>{0, 1, 2, 4, 5, 7, 9, 10}));
  // A zero-size query, the point (1, 1, 1): on the surface of boxes 0, 1 and 9, equal to box 4;
  // box 2 spans y in [-3, -1], box 7 lies in y = 0, box 10 reaches only 0.87 from the origin.
  EXPECT_EQ(expectScalarAnswer(cube({1, 1, 1}, 0), streamOf(boxes)),
            (std::vector<std::uint32_t>{0, 1, 4, 9}));
}

// At 1e5, boxes of 2^-6 (float's ulp there is 2^-7): touching cubes intersect, cubes one ulp apart
// do not, on every axis, and turned boxes agree with the scalar test.
TEST_P(ObbBatch, LargeCoordinatesSmallBoxes) {
  const float s = 0.015625f, u = 0.0078125f;
  const Vec3f base(1e5f, 1e5f, -1e5f);  // exactly representable
  std::vector<Obb> boxes;
  for (int k = 0; k < 3; ++k)
    for (const float sign : {-1.0f, 1.0f}) {
      Vec3f step = Vec3f::Zero();
      step[k] = sign * s;
      boxes.push_back(cube(base + step, s / 2));                 // touching
      boxes.push_back(cube(base + step + step / s * u, s / 2));  // one ulp apart
    }
  std::vector<std::uint32_t> want;
  for (std::uint32_t i = 0; i < 12; i += 2) want.push_back(i);
  EXPECT_EQ(expectScalarAnswer(cube(base, s / 2), streamOf(boxes)), want);
  workloads::Random r(54);
  const ObbStream turned = randomObbs(55, 300, base, 0.02f, 0.001f, 0.01f);
  for (int q = 0; q < 20; ++q)
    expectScalarAnswer({base, Vec3f::Constant(r.uniform(0.001f, 0.01f)), randomRotation(r)},
                       turned);
}

// Streams of every length from 0 to 40 of boxes that all intersect the query: the answer is every
// index, and none of the padding (a point at the origin, inside the query: it would intersect if a
// kernel read it as a box).
TEST_P(ObbBatch, PaddingIsInertAndEmptyStreamsAnswerNothing) {
  ObbStream boxes;
  std::vector<std::uint32_t> all, got;
  for (std::uint32_t n = 0; n <= 40; ++n) {
    EXPECT_EQ(overlapping(cube({0, 0, 0}, 1), boxes, got), n);
    EXPECT_EQ(got, all);
    boxes.push(cube({1.5f, 0, 0}, 1));
    all.push_back(n);
  }
}

TEST(ObbBatchErrors, BadBoxesAreRejectedWithWhereAndWhat) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  ObbStream boxes;
  boxes.push(cube({0, 0, 0}, 1));
  std::vector<std::uint32_t> out;
  test::expectError([&] { overlapping(cube({nan, 0, 0}, 1), boxes, out); }, "center.x is nan");
  test::expectError([&] { overlapping(cube({0, 0, 0}, -1), boxes, out); }, "halfExtents");
  Mat3f skewed = Mat3f::Identity();
  skewed(0, 1) = 0.1f;
  test::expectError([&] { overlapping(cube({0, 0, 0}, 1, skewed), boxes, out); }, "orthonormal");
  test::expectError(
      [&] {
        boxes.push(cube({0, 0, 0}, 1, -Mat3f::Identity()));
      },
      "ObbStream::push: element 1: axes are not orthonormal and right-handed");
  test::expectError(
      [&] {
        boxes.push({{0, 0, 0}, {1, nan, 1}, Mat3f::Identity()});
      },
      "ObbStream::push: element 1: halfExtents.y is nan");
  test::expectError(
      [&] {
        boxes.set(1, cube({0, 0, 0}, 1));
      },
      "ObbStream::set: element 1 is out of range (size 1)");
  test::expectError(
      [&] {
        boxes.set(0, cube({0, 0, 0}, 1, skewed));
      },
      "ObbStream::set: element 0: axes are not orthonormal");
  EXPECT_EQ(boxes.size(), 1u);  // nothing rejected was stored
  EXPECT_EQ(boxes[0].axes, Mat3f::Identity());
}

// intersects(a, b) and intersects(b, a) agree without reordering (intersect.hpp): on random pairs,
// and on pairs bisected down to adjacent floats at the change of answer, where the raw arithmetic
// of the two orders would round differently if it were not symmetric. In float and double.
template <class T>
void expectSymmetric(std::uint64_t seed) {
  workloads::Random r(seed);
  int boundaries = 0;
  for (int n = 0; n < 2000; ++n) {
    const auto obb = [&] {
      return ObbT<T>{Vec3f(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2)).cast<T>(),
                     Vec3f(r.uniform(0, 1.5f), r.uniform(0, 1.5f), r.uniform(0, 1.5f)).cast<T>(),
                     randomRotation(r).cast<T>()};
    };
    const ObbT<T> a = obb();
    ObbT<T> b = obb();
    ASSERT_EQ(intersects(a, b), intersects(b, a));
    const Vec3<T> dir = r.unitDirection().cast<T>();
    const auto at = [&](T t) {
      b.center = a.center + t * dir;
      return b;
    };
    T lo = 0, hi = 8;
    for (T mid = (lo + hi) / 2; mid != lo && mid != hi; mid = (lo + hi) / 2)
      (intersects(a, at(mid)) ? lo : hi) = mid;
    for (const T t : {lo, hi}) ASSERT_EQ(intersects(a, at(t)), intersects(at(t), a)) << t;
    boundaries += intersects(a, at(lo)) != intersects(a, at(hi));
  }
  EXPECT_EQ(boundaries, 2000);  // every bisection ended on the change of answer
}

TEST(ObbObbSymmetry, BothOrdersAgreeIncludingAtTheTolerance) {
  expectSymmetric<float>(56);
  expectSymmetric<double>(57);
}

TEST(Batch3dErrors, RejectBadQueries) {
  const BoxStream boxes = test::randomBoxes(48, 10, 5, 0.1f, 1);
  std::vector<std::uint32_t> out;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(overlapping(Sphere{{nan, 0, 0}, 1}, boxes, out), Error);
  EXPECT_THROW(overlapping(Sphere{{0, 0, 0}, -1}, boxes, out), Error);
  EXPECT_THROW(containing({0, nan, 0}, boxes, out), Error);
  EXPECT_THROW(raycast(Ray{{0, 0, 0}, {1, 1, 0}}, boxes), Error);  // not unit
  TriangleStream triangles;
  EXPECT_THROW(triangles.push({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}), Error);  // collinear
}

}  // namespace
}  // namespace simdphys

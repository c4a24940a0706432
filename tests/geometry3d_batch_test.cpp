// Batch forms of the 3D queries: on every path, exactly the answers of the scalar functions
// applied element by element (same indices, same booleans, bit-identical t).
#include <gtest/gtest.h>

#include <cmath>

#include "box_sets.hpp"
#include "paths.hpp"
#include "simdphys/geometry3d/batch.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "simdphys/geometry3d/raycast.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

SphereStream randomSpheres(std::uint64_t seed, std::size_t n, float spread) {
  scenes::Random r(seed);
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
std::optional<StreamHit> firstHit(const Ray& ray, const Stream& s, float tMax) {
  std::optional<StreamHit> best;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    if (auto h = raycast(s[i], ray, tMax); h && (!best || h->t < best->t)) best = {i, h->t};
  return best;
}

void expectSameHit(const std::optional<StreamHit>& got, const std::optional<StreamHit>& want) {
  ASSERT_EQ(got.has_value(), want.has_value());
  if (!want) return;
  EXPECT_EQ(got->index, want->index);
  EXPECT_EQ(got->t, want->t);  // the kernels mirror the scalar arithmetic: bit-identical
}

class Batch3d : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Batch3d);

TEST_P(Batch3d, SphereQueriesEqualTheScalarTests) {
  const SphereStream spheres = randomSpheres(41, 1001, 30);  // 1001: a partial last vector
  const BoxStream boxes = test::randomBoxes(42, 1003, 30, 0.1f, 3);
  scenes::Random r(43);
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
    for (std::size_t i = points.size(); i < points.padded(); ++i) EXPECT_EQ(points.x()[i], 0.0f);
  }
}

TEST_P(Batch3d, RaycastsEqualTheScalarRaycast) {
  const SphereStream spheres = randomSpheres(45, 517, 40);
  const BoxStream boxes = test::randomBoxes(46, 519, 40, 0.1f, 3);
  scenes::Random r(47);
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
  ASSERT_TRUE(tie.has_value());
  EXPECT_EQ(tie->index, 0u);
  EXPECT_EQ(tie->t, 1.0f);
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
  scenes::Random r(49);
  int hits = 0;
  for (int q = 0; q < 400; ++q) {
    const Ray ray{{r.uniform(-12, 12), r.uniform(2, 6), r.uniform(-12, 12)}, r.unitDirection()};
    const auto want = firstHit(ray, mesh, std::numeric_limits<float>::infinity());
    hits += want.has_value();
    expectSameHit(raycast(ray, mesh), want);
  }
  EXPECT_GT(hits, 50);  // the rays must exercise hits, not only misses
  // Straight down through every vertex and edge midpoint of the grid: shared by 2 to 6
  // triangles, each must hit (watertight), and every path picks the same one.
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 17; ++i) {
      const Ray down{{-10 + 20.0f * i / 16, 5, -10 + 20.0f * j / 8}, {0, -1, 0}};
      const auto got = raycast(down, mesh);
      ASSERT_TRUE(got.has_value()) << "leak at " << i << ", " << j;
      expectSameHit(got, firstHit(down, mesh, std::numeric_limits<float>::infinity()));
    }
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

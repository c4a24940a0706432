// Rays against a mesh's BVH, on every path: closest and any hit equal to brute force over the
// triangles (bit for bit: the tree tests each triangle with the scalar watertight test's exact
// arithmetic, so no tolerance is needed), watertightness at the heightfield's shared vertices and
// edges, and W2's figures.
#include <gtest/gtest.h>

#include <cmath>

#include "expect_error.hpp"
#include "mesh_oracles.hpp"
#include "paths.hpp"
#include "rays.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

void expectSame(const ElementHit& found, const ElementHit& expected, const std::string& what) {
  EXPECT_EQ(found.index, expected.index) << what;
  if (expected.hit()) {
    EXPECT_EQ(found.t, expected.t) << what;  // exact: same arithmetic
  }
}

// The closest hits of `rays`, one at a time and as a stream, against brute force.
void checkAgainstBruteForce(const Mesh& mesh, const std::vector<Ray>& rays, float tMax) {
  const MeshBvh bvh(mesh);
  RayStream stream;
  for (const Ray& r : rays) stream.push(r, tMax);
  std::vector<ElementHit> streamed(rays.size());
  bvh.raycast(stream, streamed);
  std::vector<std::uint8_t> occluded(rays.size());
  bvh.occluded(stream, occluded);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const ElementHit expected = test::bruteRaycast(mesh, rays[i], tMax);
    hits += expected.hit();
    const std::string what = "ray " + std::to_string(i);
    expectSame(bvh.raycast(rays[i], tMax), expected, what);
    expectSame(streamed[i], expected, what + " (stream)");
    EXPECT_EQ(bvh.occluded(rays[i], tMax), expected.hit()) << what;
    EXPECT_EQ(occluded[i] != 0, expected.hit()) << what << " (stream)";
  }
  // The sets must exercise both outcomes, or the comparison proves little.
  EXPECT_GT(hits, rays.size() / 10);
  EXPECT_LT(hits, rays.size());
}

class MeshRays : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(MeshRays);

TEST_P(MeshRays, HeightfieldSubsetEqualsBruteForce) {
  const Mesh mesh = scenes::makeHeightfield(33);  // 2,048 triangles
  std::vector<Ray> rays;
  const RayStream camera = scenes::makeCoherentRays(64, 48);
  for (std::size_t i = 0; i < camera.size(); ++i) rays.push_back(camera[i]);
  const RayStream random = scenes::makeIncoherentRays(3000);
  for (std::size_t i = 0; i < random.size(); ++i) rays.push_back(random[i]);
  checkAgainstBruteForce(mesh, rays, std::numeric_limits<float>::infinity());
}

TEST_P(MeshRays, RandomSoupEqualsBruteForce) {
  const Mesh soup = test::randomSoup(41, 3000, 40, 4);
  checkAgainstBruteForce(soup, test::randomRays(42, 3000, 50),
                         std::numeric_limits<float>::infinity());
  // A finite tMax cuts hits off: the closed bound [0, tMax] on both sides.
  checkAgainstBruteForce(soup, test::randomRays(43, 2000, 50), 30.0f);
}

// Many triangles hit at the same t: a fan around a vertex, and coincident copies of one
// triangle, whose tie is decided by the smaller id whatever the tree's order.
TEST_P(MeshRays, TiesGoToTheSmallerId) {
  Mesh m;
  m.vertices.push_back({0, 0, 0});
  constexpr int kFan = 24;
  for (int k = 0; k < kFan; ++k) {
    const double a = 2 * 3.141592653589793 * k / kFan;
    m.vertices.push_back({float(std::cos(a)), 0.0f, float(std::sin(a))});
  }
  for (std::uint32_t k = 0; k < kFan; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % kFan});
  for (int copy = 0; copy < 20; ++copy) m.triangles.push_back({1, 3, 5});
  const MeshBvh bvh(m);
  // Through the fan's centre: every fan triangle is hit at t = 2 exactly.
  const ElementHit centre = bvh.raycast({{0, 2, 0}, {0, -1, 0}});
  EXPECT_EQ(centre.index, 0u);
  EXPECT_EQ(centre.t, 2.0f);
  // Inside the copied triangle (and fan triangles 1..4 beneath it, coplanar): the smallest id.
  const Vec3f inside = (m.vertices[1] + m.vertices[3] + m.vertices[5]) / 3;
  const Ray down{inside + Vec3f(0, 2, 0), {0, -1, 0}};
  expectSame(bvh.raycast(down), test::bruteRaycast(m, down), "copies");
}

// Watertightness: rays aimed exactly at the heightfield's vertices and at points on its shared
// edges, from above, must hit (the surface is a graph over the square, so a ray descending into
// its interior crosses it; no expectation comes from the code under test). Vertical rays pass
// exactly through the vertex or edge point; oblique ones through its rounding.
TEST_P(MeshRays, RaysAtSharedVerticesAndEdgesNeverMiss) {
  constexpr std::uint32_t g = 33;
  const Mesh mesh = scenes::makeHeightfield(g);
  const MeshBvh bvh(mesh);
  scenes::Random r(44);
  std::size_t tested = 0;
  for (std::uint32_t j = 1; j + 1 < g; ++j)
    for (std::uint32_t i = 1; i + 1 < g; ++i) {
      const Vec3f v = mesh.vertices[j * g + i];
      const Vec3f right = mesh.vertices[j * g + i + 1],
                  diagonal = mesh.vertices[(j + 1) * g + i + 1];
      const Vec3f targets[] = {v, (v + right) / 2, (v + diagonal) / 2};
      for (const Vec3f& target : targets) {
        const Ray vertical{{target.x(), 50, target.z()}, {0, -1, 0}};
        const Vec3f from(target.x() + r.uniform(-10, 10), 50, target.z() + r.uniform(-10, 10));
        const Ray oblique{from, target - from};  // not unit: t is in units of it
        for (const Ray& ray : {vertical, oblique}) {
          const ElementHit h = bvh.raycast(ray);
          ASSERT_TRUE(h.hit()) << "missed " << target.transpose() << " from "
                               << ray.origin.transpose();
          expectSame(h, test::bruteRaycast(mesh, ray), "aimed ray");
          ++tested;
        }
      }
    }
  EXPECT_EQ(tested, std::size_t(6 * (g - 2) * (g - 2)));
}

// W2 at full size (G = 513) on this path: the figures of WORKLOADS.md, and every ray against the
// double-precision grid walk (every 7th ray, to keep the test short).
// W2's inputs, tree and double-precision reference hits (of every 7th ray) depend on no path:
// built once per process (ctest runs each path's case in its own).
struct W2Set {
  RayStream rays;
  scenes::RaysReference figures;
  std::vector<std::size_t> sampled;  // indices of the sampled rays
  std::vector<scenes::ReferenceHit> reference;
};
struct W2 {
  Mesh mesh = scenes::makeHeightfield();
  MeshBvh bvh{mesh};
  std::vector<W2Set> sets;
};
const W2& w2() {
  static const W2 w = [] {
    W2 out;
    for (auto [rays, figures] :
         {std::pair{scenes::makeCoherentRays(), scenes::kCoherentReference},
          std::pair{scenes::makeIncoherentRays(), scenes::kIncoherentReference}}) {
      W2Set set{std::move(rays), figures, {}, {}};
      RayStream sample;
      for (std::size_t i = 0; i < set.rays.size(); i += 7)
        sample.push(set.rays[i]), set.sampled.push_back(i);
      set.reference = scenes::referenceHits(out.mesh, scenes::kRaysGrid, sample);
      out.sets.push_back(std::move(set));
    }
    return out;
  }();
  return w;
}

TEST_P(MeshRays, W2FiguresAndDoubleReference) {
  for (const W2Set& s : w2().sets) {
    std::vector<ElementHit> hits(s.rays.size());
    w2().bvh.raycast(s.rays, hits);
    const scenes::RaysReference found = scenes::summarise(hits);
    EXPECT_EQ(found.hits, s.figures.hits);
    // The figure has 8 significant digits.
    EXPECT_NEAR(found.sumT, s.figures.sumT, scenes::kSumTTolerance * s.figures.sumT);
    std::vector<ElementHit> sampleHits;
    for (std::size_t i : s.sampled) sampleHits.push_back(hits[i]);
    const auto c = scenes::compareWithReference(sampleHits, s.reference);
    // W2: rays may differ from the double reference only where its hit is within 1e-5 of an edge.
    EXPECT_EQ(c.differ, 0u);
    // Same triangle: t within a few float roundings of the double t (float's eps is 1.2e-7; the
    // watertight t carries a division and sums of products of differences, and t ~ 100 is the
    // difference of coordinates ~ 100: 1e-5 relative bounds it with room).
    EXPECT_LT(c.maxRelativeT, 1e-5);
  }
}

TEST(MeshRayErrors, BadRaysAreRejected) {
  const MeshBvh bvh(scenes::makeHeightfield(5));
  test::expectError(
      [&] {
        bvh.raycast({{0, 1, 0}, {0, 0, 0}});
      },
      "MeshBvh::raycast: the direction is zero");
  test::expectError([&] { bvh.raycast({{0, NAN, 0}, {0, 1, 0}}); }, "origin");
  test::expectError([&] { bvh.occluded({{0, 1, 0}, {0, 1, 0}}, -1); }, "tMax");
  RayStream s;
  s.push({{0, 1, 0}, {0, 1, 0}});
  test::expectError([&] { s.push({{0, 1, 0}, {0, INFINITY, 0}}); }, "RayStream::push: element 1");
  std::vector<ElementHit> out(2);
  test::expectError([&] { bvh.raycast(s, out); }, "2 hits for 1 rays");
}

}  // namespace
}  // namespace simdphys

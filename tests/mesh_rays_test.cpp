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

// The closest hits of `rays`, one at a time and as a stream, against brute force, on every path
// (brute force, which depends on no path, is computed once).
void checkAgainstBruteForce(const Mesh& mesh, const std::vector<Ray>& rays, float tMax) {
  RayStream stream;
  std::vector<ElementHit> expected(rays.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    stream.push(rays[i], tMax);
    expected[i] = test::bruteRaycast(mesh, rays[i], tMax);
    hits += expected[i].hit();
  }
  // The sets must exercise both outcomes, or the comparison proves little.
  EXPECT_GT(hits, rays.size() / 10);
  EXPECT_LT(hits, rays.size());
  test::forEveryPath([&] {
    const MeshBvh bvh(mesh);
    std::vector<ElementHit> streamed(rays.size());
    bvh.raycast(stream, streamed);
    std::vector<std::uint8_t> occluded(rays.size());
    bvh.occluded(stream, occluded);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const std::string what = "ray " + std::to_string(i);
      expectSame(bvh.raycast(rays[i], tMax), expected[i], what);
      expectSame(streamed[i], expected[i], what + " (stream)");
      EXPECT_EQ(bvh.occluded(rays[i], tMax), expected[i].hit()) << what;
      EXPECT_EQ(occluded[i] != 0, expected[i].hit()) << what << " (stream)";
    }
  });
}

TEST(MeshRays, HeightfieldSubsetEqualsBruteForceOnEveryPath) {
  const Mesh mesh = workloads::makeHeightfield(33);  // 2,048 triangles
  std::vector<Ray> rays;
  const RayStream camera = workloads::makeCoherentRays(64, 48);
  for (std::size_t i = 0; i < camera.size(); ++i) rays.push_back(camera[i]);
  const RayStream random = workloads::makeIncoherentRays(3000);
  for (std::size_t i = 0; i < random.size(); ++i) rays.push_back(random[i]);
  checkAgainstBruteForce(mesh, rays, std::numeric_limits<float>::infinity());
}

TEST(MeshRays, RandomSoupEqualsBruteForceOnEveryPath) {
  const Mesh soup = test::randomSoup(41, 3000, 40, 4);
  checkAgainstBruteForce(soup, test::randomRays(42, 3000, 50),
                         std::numeric_limits<float>::infinity());
  // A finite tMax cuts hits off: the closed bound [0, tMax] on both sides.
  checkAgainstBruteForce(soup, test::randomRays(43, 2000, 50), 30.0f);
}

class MeshRaysOnPath : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(MeshRaysOnPath);

// Many triangles hit at the same t: a fan around a vertex, and coincident copies of one
// triangle, whose tie is decided by the smaller id whatever the tree's order.
TEST_P(MeshRaysOnPath, TiesGoToTheSmallerId) {
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
TEST(MeshRays, RaysAtSharedVerticesAndEdgesNeverMissOnEveryPath) {
  constexpr std::uint32_t g = 33;
  const Mesh mesh = workloads::makeHeightfield(g);
  workloads::Random r(44);
  std::vector<Ray> rays;
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
        rays.push_back(vertical), rays.push_back(oblique);
      }
    }
  EXPECT_EQ(rays.size(), std::size_t(6 * (g - 2) * (g - 2)));
  std::vector<ElementHit> expected;
  for (const Ray& ray : rays) expected.push_back(test::bruteRaycast(mesh, ray));
  test::forEveryPath([&] {
    const MeshBvh bvh(mesh);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const ElementHit h = bvh.raycast(rays[i]);
      ASSERT_TRUE(h.hit()) << "missed ray " << i << " from " << rays[i].origin.transpose();
      expectSame(h, expected[i], "aimed ray");
    }
  });
}

// W2 at full size (G = 513) on every path: the figures of WORKLOADS.md, and every 7th ray against
// the double-precision grid walk (to keep the test short). The inputs, the tree and the reference
// hits depend on no path, so they are built once and every path is run in this one process.
TEST(MeshRays, W2FiguresAndDoubleReferenceOnEveryPath) {
  const Mesh mesh = workloads::makeHeightfield();
  const MeshBvh bvh(mesh);
  for (auto [rays, figures] :
       {std::pair{workloads::makeCoherentRays(), workloads::kCoherentReference},
        std::pair{workloads::makeIncoherentRays(), workloads::kIncoherentReference}}) {
    RayStream sample;
    std::vector<std::size_t> sampled;
    for (std::size_t i = 0; i < rays.size(); i += 7) sample.push(rays[i]), sampled.push_back(i);
    const std::vector<workloads::ReferenceHit> reference =
        workloads::referenceHits(mesh, workloads::kRaysGrid, sample);
    test::forEveryPath([&] {
      std::vector<ElementHit> hits(rays.size());
      bvh.raycast(rays, hits);
      const workloads::RaysReference found = workloads::summarise(hits);
      EXPECT_EQ(found.hits, figures.hits);
      // The figure has 8 significant digits.
      EXPECT_NEAR(found.sumT, figures.sumT, workloads::kSumTTolerance * figures.sumT);
      std::vector<ElementHit> sampleHits;
      for (std::size_t i : sampled) sampleHits.push_back(hits[i]);
      const auto c = workloads::compareWithReference(sampleHits, reference);
      // W2: rays may differ from the double reference only where its hit is within 1e-5 of an
      // edge.
      EXPECT_EQ(c.differ, 0u);
      // Same triangle: t within a few float roundings of the double t (float's eps is 1.2e-7; the
      // watertight t carries a division and sums of products of differences, and t ~ 100 is the
      // difference of coordinates ~ 100: 1e-5 relative bounds it with room).
      EXPECT_LT(c.maxRelativeT, 1e-5);
    });
  }
}

TEST(MeshRayErrors, BadRaysAreRejected) {
  const MeshBvh bvh(workloads::makeHeightfield(5));
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

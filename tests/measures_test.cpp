// Physical measures (measures.hpp): depths and stretches against closed forms, and the monitor
// of a workload's scene file giving the figures the workload's own measures give.
#include "simdphys/measures.hpp"

#include <gtest/gtest.h>

#include "simdphys/scene_file.hpp"
#include "workloads/cloth.hpp"
#include "workloads/pyramid.hpp"

namespace simdphys {
namespace {

const std::filesystem::path kScenes = SIMDPHYS_SOURCE_DIR "/scenes";

// Depths are computed in double from float inputs that are exact here (binary fractions), so
// the tolerance is a few double roundings.
constexpr double kTol = 1e-12;

TEST(Measures, DepthInsideSolidsHasItsClosedForms) {
  const Plane ground{{0, 1, 0}, 0};
  EXPECT_NEAR(depthInside(ground, {3, -0.25f, 1}), 0.25, kTol);
  EXPECT_EQ(depthInside(ground, {3, 0.25f, 1}), 0);
  const Sphere ball{{1, 0, 0}, 2};
  EXPECT_NEAR(depthInside(ball, {1.5f, 0, 0}), 1.5, kTol);
  EXPECT_EQ(depthInside(ball, {4, 0, 0}), 0);
  const Aabb box{{0, 0, 0}, {4, 2, 8}};
  EXPECT_NEAR(depthInside(box, {1, 1.75f, 4}), 0.25, kTol);  // nearest face: y = 2
  EXPECT_EQ(depthInside(box, {5, 1, 1}), 0);
  // A box turned a quarter about +z: its local x (half 3) lies along world y.
  const Obb turned{{0, 0, 0}, {3, 1, 1}, rotationZ(std::numbers::pi / 2).cast<float>()};
  EXPECT_NEAR(depthInside(turned, {0, 2.5f, 0}), 0.5, 1e-6);  // the axes are rounded to float
  EXPECT_EQ(depthInside(turned, {2.5f, 0, 0}), 0);
}

TEST(Measures, StretchIsRelativeWithANearestRankPercentile) {
  // 100 springs of rest 1 along x, spring k stretched to 1 + k / 100; the first joins a pinned
  // particle.
  std::vector<Vec3f> p;
  std::vector<Spring> springs;
  for (int k = 0; k < 100; ++k) {
    p.push_back({0, float(k) * 10, 0});
    p.push_back({1 + float(k) / 100, float(k) * 10, 0});
    springs.push_back({std::uint32_t(2 * k), std::uint32_t(2 * k + 1), 1.0f});
  }
  std::vector<float> invMass(p.size(), 1);
  invMass[1] = 0;
  const Stretch s = stretchOf(springs, p, invMass);
  EXPECT_NEAR(s.mean, 0.495, 1e-6);  // mean of k / 100 over k < 100; float positions: 1e-6
  EXPECT_NEAR(s.p99, 0.98, 1e-6);    // the 99th smallest of 100
  EXPECT_NEAR(s.max, 0.99, 1e-6);
  EXPECT_NEAR(s.maxAwayFromPins, 0.99, 1e-6);
  invMass[199] = 0;  // now the largest touches a pin
  EXPECT_NEAR(stretchOf(springs, p, invMass).maxAwayFromPins, 0.98, 1e-6);
}

TEST(Measures, ClothSceneMeasuresAsW3Does) {
  SceneFile scene = loadScene(kScenes / "w3_cloth.json");
  const workloads::ClothWorkload w = workloads::makeClothWorkload(128);
  WorldMonitor monitor(scene.world);
  const Cloth& cloth = scene.world.cloth(scene.cloths[0]);
  double deepest = 0;
  for (int frame = 0; frame < 40; ++frame) {  // 0.67 s: the cloth reaches the sphere
    scene.world.step();
    monitor.observe(scene.world);
    deepest =
        std::max(deepest, workloads::spherePenetration(workloads::kClothSphere, cloth.positions()));
  }
  const WorldMeasures m = monitor.measure(scene.world);
  ASSERT_EQ(m.cloths.size(), 1u);
  const workloads::ClothStretch expected = workloads::clothStretch(w, cloth.positions());
  // The same springs, rest lengths and arithmetic: equal, not close.
  EXPECT_EQ(m.cloths[0].springs,
            workloads::clothSpringCount(128, workloads::SpringKind::kStructural));
  EXPECT_EQ(m.cloths[0].stretch.mean, expected.mean);
  EXPECT_EQ(m.cloths[0].stretch.p99, expected.p99);
  EXPECT_EQ(m.cloths[0].stretch.max, expected.max);
  EXPECT_EQ(m.cloths[0].stretch.maxAwayFromPins, expected.maxAwayFromPins);
  EXPECT_EQ(m.cloths[0].deepestPenetration, deepest);
  EXPECT_TRUE(m.cloths[0].finite);
}

TEST(Measures, PyramidSceneMeasuresAsW5Does) {
  SceneFile scene = loadScene(kScenes / "w5_pyramid_b10.json");
  const std::vector<Vec3f> start = workloads::pyramidCenters(10);
  WorldMonitor monitor(scene.world);
  float deepest = 0;
  for (int frame = 0; frame < 30; ++frame) {
    scene.world.step();
    monitor.observe(scene.world);
    deepest = std::max(deepest, scene.world.bodies().deepestPenetration());
  }
  std::vector<Vec3f> end;
  for (const Handle h : scene.bodies) end.push_back(scene.world.bodies().position(h));
  const workloads::PyramidMeasures expected = workloads::measurePyramid(start, end);
  const WorldMeasures m = monitor.measure(scene.world);
  EXPECT_EQ(m.bodies.count, start.size());
  EXPECT_EQ(m.bodies.maxDisplacement, expected.maxDisplacement);
  EXPECT_EQ(m.bodies.standing, expected.standing);
  EXPECT_EQ(m.bodies.deepestPenetration, double(deepest));
  EXPECT_GT(m.bodies.deepestPenetration, 0);  // the boxes settle into contact
}

TEST(Measures, ParticlesInsideAndMeanHeightCountEveryParticle) {
  World world;
  world.obstacles().add(Aabb{{-1, -1, -1}, {1, 1, 1}});
  const Handle h = world.addParticles();
  ParticleSystem& s = world.particles(h);
  s.add({0, 0.5f, 0});  // inside the box
  s.add({0, 3, 0});     // above it
  s.add({0, 1.5f, 5});  // beside it
  const WorldMeasures m = WorldMonitor(world).measure(world);
  ASSERT_EQ(m.particles.size(), 1u);
  EXPECT_EQ(m.particles[0].count, 3u);
  EXPECT_EQ(m.particles[0].inside, 1u);
  EXPECT_NEAR(m.particles[0].meanHeight, 5.0 / 3, kTol);
  EXPECT_TRUE(m.particles[0].finite);
}

}  // namespace
}  // namespace simdphys

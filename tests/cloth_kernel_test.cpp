// The cloth step's kernels (simd/cloth.cpp) and plain-loop baseline (simd/cloth_autovec.cpp)
// against the float reference (src/reference/cloth/step-inl.hpp), and the grid's kernels against
// the general network's: cloths of odd sizes (rows padded, colours that end mid-vector), both
// models, with and without damping and tethers, draped over every kind of obstacle cloth meets.
// The kernels mirror the reference operation for operation, so positions and velocities must
// agree bit for bit, at any thread count.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "simdphys/world.hpp"
#include "testing/pairs.hpp"  // ScopedPlainLoops: the baseline in place of the kernel
#include "tests/paths.hpp"

namespace simdphys {
namespace {

// An nx x nz sheet at y = 1.6 over [-0.6, 0.6]^2, pinned at two corners, a little tilted so no
// two springs have the same length.
ClothGrid sheet(std::size_t nx, std::size_t nz, const SpringKindSettings& kind) {
  ClothGrid g;
  g.nx = nx, g.nz = nz;
  for (std::size_t j = 0; j < nz; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const float u = float(i) / float(nx - 1), v = float(j) / float(nz - 1);
      g.positions.emplace_back(1.2f * u - 0.6f, 1.6f + 0.05f * u * v, 1.2f * v - 0.6f);
      g.invMass.push_back((i == 0 || i == nx - 1) && j == 0 ? 0.0f : 1.0f + 0.5f * u);
    }
  g.structural = kind;
  g.shear = {kind.stiffness == kRigid ? kRigid : 0.5f * kind.stiffness, kind.damping};
  g.bend = {kind.stiffness == kRigid ? 2000.0f : 0.1f * kind.stiffness, 0.5f * kind.damping};
  return g;
}

// Every obstacle kind cloth meets: the sphere it drapes over, a ground plane, a box and a tilted
// box under its edges, and a bumpy mesh under a corner.
void addObstacles(Obstacles& o) {
  o.add(std::make_shared<const MeshBvh>(
      heightfieldMesh(7, 7, -0.7, 0.0, -0.7, 0.0,
                      [](double x, double z) { return 1.5 + 0.1 * x + 0.04 * std::sin(9 * z); })));
  o.add(Sphere{Vec3f(0.05f, 1.1f, 0.1f), 0.35f});
  o.add(Plane{Vec3f(0, 1, 0), -0.8f});
  o.add(Aabb{Vec3f(0.3f, 0.7f, -0.7f), Vec3f(0.7f, 1.45f, -0.2f)});
  const Mat3f axes =
      Eigen::AngleAxisf(0.4f, Vec3f(0.3f, 0.9f, 0.1f).normalized()).toRotationMatrix();
  o.add(Obb{Vec3f(-0.5f, 1.1f, 0.4f), Vec3f(0.2f, 0.3f, 0.15f), axes});
}

struct Case {
  const char* name;
  ClothModel model;
  SpringKindSettings kind;
  bool tethers;
  float penalty = 0;  // N/m: penalty springs at the obstacles
};
const Case kCases[] = {
    {"xpbd rigid", ClothModel::kXpbd, {kRigid, 0}, true},
    {"xpbd soft damped", ClothModel::kXpbd, {5000, 20}, false},
    {"mass-spring", ClothModel::kMassSpring, {3000, 0}, true},
    {"mass-spring damped", ClothModel::kMassSpring, {3000, 5}, false},
    {"mass-spring penalty springs", ClothModel::kMassSpring, {3000, 0}, true, 2000},
};

struct State {
  std::vector<std::uint32_t> bits;
};

// The bits of every position and velocity after `steps` steps of the cloth in a world.
State run(Cloth cloth, int steps, int threads = 0, int substeps = 4) {
  ClothSettings s = cloth.settings();
  s.substeps = substeps;
  cloth.setSettings(s);
  World world(WorldSettings{1.0f / 60, 1, threads});
  addObstacles(world.obstacles());
  const Handle h = world.addCloth(cloth);
  for (int k = 0; k < steps; ++k) world.step();
  State st;
  const Cloth& c = world.cloth(h);
  for (std::uint32_t i = 0; i < c.size(); ++i)
    for (const Vec3f& v : {c.position(i), c.velocity(i)})
      for (int k = 0; k < 3; ++k) st.bits.push_back(std::bit_cast<std::uint32_t>(v[k]));
  return st;
}

ClothSettings settingsOf(const Case& c) {
  ClothSettings s;
  s.model = c.model, s.tethers = c.tethers, s.damping = 0.2f, s.penalty = c.penalty;
  return s;
}

Cloth gridCloth(const Case& c, std::size_t nx, std::size_t nz) {
  return Cloth::grid(sheet(nx, nz, c.kind), settingsOf(c));
}

// The same springs in the same batches, as a general network.
Cloth networkCloth(const Case& c, std::size_t nx, std::size_t nz) {
  const ClothGrid g = sheet(nx, nz, c.kind);
  const Cloth grid = Cloth::grid(g, settingsOf(c));
  return Cloth(g.positions, g.invMass, grid.springs(), settingsOf(c), grid.batchOf());
}

constexpr int kSteps = 12;  // 0.2 s: the sheet falls onto the obstacles and slides on them

class ClothKernel : public test::OnEveryPath {};

TEST_P(ClothKernel, GridAndNetworkMatchTheReferenceBitForBit) {
  // 21 x 13: rows padded to 32 slots, each colour's runs ending mid-vector at every width.
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    State want;
    {
      const ScopedPath reference("reference");
      want = run(networkCloth(c, 21, 13), kSteps);
    }
    EXPECT_EQ(run(gridCloth(c, 21, 13), kSteps).bits, want.bits) << "grid";
    EXPECT_EQ(run(networkCloth(c, 21, 13), kSteps).bits, want.bits) << "network";
  }
}

TEST_P(ClothKernel, PlainLoopMatchesTheReferenceBitForBit) {
  if (referencePathActive()) GTEST_SKIP() << "the reference path runs no kernel";
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    State want;
    {
      const ScopedPath reference("reference");
      want = run(gridCloth(c, 21, 13), kSteps);
    }
    const test::ScopedPlainLoops plain;
    EXPECT_EQ(run(gridCloth(c, 21, 13), kSteps).bits, want.bits) << "grid";
    EXPECT_EQ(run(networkCloth(c, 21, 13), kSteps).bits, want.bits) << "network";
  }
}

TEST_P(ClothKernel, SameStateAtOneAndTwoThreads) {
  // 96 x 96 particles: past the size below which a cloth steps on one thread, so its passes are
  // shared out; one step of one substep (each pass ends at a barrier, which a loaded machine makes
  // slow).
  // XPBD on the grid's passes, the damped mass-spring model on the network's batches.
  EXPECT_EQ(run(gridCloth(kCases[0], 96, 96), 1, 1, 1).bits,
            run(gridCloth(kCases[0], 96, 96), 1, 2, 1).bits);
  EXPECT_EQ(run(networkCloth(kCases[3], 96, 96), 1, 1, 1).bits,
            run(networkCloth(kCases[3], 96, 96), 1, 2, 1).bits);
}

SIMDPHYS_ON_EVERY_PATH(ClothKernel);

}  // namespace
}  // namespace simdphys

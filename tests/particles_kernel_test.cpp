// The particle step's SIMD kernel and its plain-loop baseline (simd/particles.cpp) against the
// float reference (src/reference/particles/step-inl.hpp): on every path, worlds of random and of
// hard particles (all four integrators, every obstacle kind, starts inside, pinned lanes, grazing,
// edge and corner hits, speeds that bounce several times and reach the bounce limit, forces and
// drag) stepped side by side with the same world on the reference path. The kernel mirrors the
// reference operation for operation, so positions and velocities must agree bit for bit and the
// counters exactly. And the state after 20 steps is the same at 1 and 2 threads.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "simdphys/world.hpp"
#include "testing/pairs.hpp"  // detail::setPlainLoops: the baseline in place of the kernel
#include "tests/paths.hpp"

namespace simdphys {
namespace {

// A rotation from a random unit quaternion, orthonormal to float rounding.
Mat3f randomAxes(std::mt19937& rng) {
  std::normal_distribution<float> g;
  Eigen::Quaternionf q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

// Obstacles of every kind around the origin: a ground plane, a tilted plane far below, spheres,
// AABBs (one thin: 0.05) and OBBs, some overlapping so that contacts land in corners; 4 + extra
// bounded ones.
void addObstacles(Obstacles& o, std::mt19937& rng, int extra) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  o.add(Plane{Vec3f(0, 1, 0), 2.0f});  // y = -2
  o.add(Plane{Vec3f(0.6f, 0.8f, 0), 6.0f});
  o.add(Sphere{Vec3f(0.5f, -1.0f, 0.25f), 0.75f});
  o.add(Aabb{Vec3f(-1, -1, -1), Vec3f(0, 0, 0)});
  o.add(Aabb{Vec3f(0.5f, -2, -1), Vec3f(0.55f, 1, 1)});  // a 0.05 wall
  o.add(Obb{Vec3f(-1.5f, -1.2f, 1.0f), Vec3f(0.6f, 0.3f, 0.9f), randomAxes(rng)});
  for (int k = 0; k < extra; ++k) {
    const Vec3f c(2 * u(rng), u(rng) - 0.5f, 2 * u(rng));
    const Vec3f h(0.1f + 0.4f * std::abs(u(rng)), 0.1f + 0.4f * std::abs(u(rng)),
                  0.1f + 0.4f * std::abs(u(rng)));
    switch (k % 3) {
      case 0:
        o.add(Sphere{c, h.x()});
        break;
      case 1:
        o.add(Aabb{c - h, c + h});
        break;
      default:
        o.add(Obb{c, h, randomAxes(rng)});
        break;
    }
  }
}

// A bumpy sheet of 8 x 8 quads over [-2.5, 2.5]^2 around y = 0.3, tilted, in steps of 0.15 from
// one vertex to the next: grazed, crossed along its shared edges and hit from both sides by the
// random particles.
MeshObstacle bumpySheet() {
  return std::make_shared<const MeshBvh>(
      heightfieldMesh(9, 9, -2.5, 2.5, -2.5, 2.5, [](double x, double z) {
        const int i = int(std::lround((x + 2.5) / 0.625)), k = int(std::lround((z + 2.5) / 0.625));
        return 0.3 + 0.2 * x + 0.15 * ((i * 7 + k * 3) % 4);
      }));
}

// Random particles in and around the obstacles, some fast (several bounces per step), some pinned,
// some with a force.
void addRandomParticles(ParticleSystem& s, std::mt19937& rng, int n) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    const Vec3f x(2.5f * u(rng), 2.0f * u(rng) - 0.5f, 2.5f * u(rng));
    const float speed = i % 4 == 0 ? 400.0f : i % 4 == 1 ? 20.0f : 2.0f;
    const Vec3f v = speed * Vec3f(u(rng), u(rng), u(rng));
    const float w = i % 11 == 0 ? 0.0f : 0.5f + std::abs(u(rng));
    const Handle h = s.add(x, v, w);
    if (i % 3 == 0) s.setForce(h, 30.0f * Vec3f(u(rng), u(rng), u(rng)));
  }
}

// Exact cases against the unit box [0, 1]^3, the sphere of radius 1 at (3, 0.5, 0.5) and an OBB
// turned 45 degrees about z at (0.5, 0.5, 3): grazing a face, hitting an edge and a corner exactly,
// starting at a centre, on a surface, inside, at rest.
void addHardObstacles(Obstacles& o) {
  o.add(Aabb{Vec3f(0, 0, 0), Vec3f(1, 1, 1)});
  o.add(Sphere{Vec3f(3, 0.5f, 0.5f), 1.0f});
  const float c = std::sqrt(0.5f);
  Mat3f axes;
  axes << c, -c, 0, c, c, 0, 0, 0, 1;
  o.add(Obb{Vec3f(0.5f, 0.5f, 3), Vec3f(0.5f, 0.5f, 0.5f), axes});
  o.add(Plane{Vec3f(0, 1, 0), 5.0f});
}

void addHardParticles(ParticleSystem& s) {
  const float fast = 1000.0f;
  const std::vector<std::pair<Vec3f, Vec3f>> cases = {
      {{-1, 1, 0.5f}, {fast, 0, 0}},       // along the top face's plane
      {{-1, 2, 0.5f}, {fast, -fast, 0}},   // exactly at the edge (0, 1, z)
      {{2, 2, 2}, {-fast, -fast, -fast}},  // exactly at the corner (1, 1, 1)
      {{-1, -1, -1}, {fast, fast, fast}},  // through the corner (0, 0, 0) and the box
      {{0.5f, 0.5f, 0.5f}, {0, 0, 0}},     // the box's centre: ties to the min x face
      {{0.2f, 0.5f, 0.5f}, {1, 0, 0}},     // inside, near a face
      {{3, 0.5f, 0.5f}, {0, 0, 0}},        // the sphere's centre: out along +y
      {{3, 1.5f, 0.5f}, {1, 0, 0}},        // on the sphere, tangent
      {{3, 1.5f, 0.5f}, {0, -1, 0}},       // on the sphere, entering
      {{3, -5, 0.5f}, {0, fast, 0}},       // through the sphere's axis from below
      {{0.5f, 0.5f, 3}, {0, 0, 0}},        // the OBB's centre
      {{0.5f, 0.5f + std::sqrt(0.5f), 5}, {0, 0, -fast}},  // onto the OBB's top edge, exactly
      {{0.5f, 2, 3}, {0, -fast, 0}},                       // onto the OBB's edge
      {{0.5f, -4.999f, 0}, {0, 0, 0}},                     // resting just above the ground
      {{0.5f, -5, 0}, {0, 0, 0}},                          // on the ground
      {{0.5f, -6, 0}, {0, 0, 0}},                          // under the ground
      {{-3, -4.9f, 0.5f}, {fast, -fast, 0}},               // skimming the ground into the box
  };
  for (const auto& [x, v] : cases) s.add(x, v);
  // Resting and sliding on the ground and on the box's top, touching or a few skins above.
  for (int k = 0; k < 8; ++k) {
    s.add(Vec3f(-3 + 0.3f * float(k), -5 + 0.0005f + 0.001f * float(k), 2),
          Vec3f(0.5f * float(k), 0, 0));
    s.add(Vec3f(0.5f, 1 + 0.0004f * float(k), 0.5f), Vec3f(0.1f * float(k), -0.2f, 0.05f));
  }
  s.add(Vec3f(0.5f, 0.5f, 0.5f), Vec3f(fast, 0, 0), 0.0f);  // pinned inside: untouched
  // Pushed past the supported range in its first step (1e36 m/s^2), and one a step later: kept.
  s.setForce(s.add(Vec3f(4, 4, 4), Vec3f(0, 0, 0), 1e18f), Vec3f(1e18f, 0, 0));
  s.setForce(s.add(Vec3f(4, 5, 4), Vec3f(0, 0, 0), 45.0f), Vec3f(0, 0, 1e18f));  // 7.5e17 m/s
}

struct Case {
  std::string name;
  ParticleSettings settings;
  bool hard;
  bool many = false;  // 60 bounded obstacles more: found through the obstacles' tree
  bool mesh = false;  // and a triangle mesh: tested lane by lane by the reference's test
};

std::vector<Case> cases() {
  std::vector<Case> out;
  const Integrator integrators[] = {Integrator::kExplicitEuler, Integrator::kSemiImplicitEuler,
                                    Integrator::kVelocityVerlet, Integrator::kPositionVerlet};
  for (const Integrator in : integrators) {
    for (int variant = 0; variant < 3; ++variant) {
      ParticleSettings s;
      s.integrator = in;
      if (variant == 1) s.drag = 0.3f, s.friction = 0.4f, s.restitution = 0.9f, s.damping = 0.97f;
      if (variant == 2) s.maxBounces = 1, s.restitution = 1.0f, s.restitutionThreshold = 0.0f;
      out.push_back({std::string(toString(in)) + "/" + std::to_string(variant), s, variant == 0});
    }
  }
  return out;
}

// A world and its one particle system.
struct Scene {
  World world;
  Handle system;
};

Scene makeScene(const Case& c, int threads, int particles, std::uint32_t seed) {
  Scene s{World(WorldSettings{1.0f / 60.0f, c.hard ? 1 : 2, threads}), {}};
  std::mt19937 rng(seed);
  s.system = s.world.addParticles(c.settings);
  ParticleSystem& p = s.world.particles(s.system);
  if (c.hard) {
    addHardObstacles(s.world.obstacles());
    addHardParticles(p);
  }
  // At most kFewObstacles bounded ones, each tested by every vector; or many, through the tree.
  addObstacles(s.world.obstacles(), rng, c.many ? 60 : c.hard ? 1 : 4);
  if (c.mesh) s.world.obstacles().add(bumpySheet());
  std::size_t bounded = 0;
  for (const ObstacleShape& o : s.world.obstacles().shapes())
    bounded += !std::holds_alternative<Plane>(o);
  if (c.many) {
    EXPECT_GT(bounded, Obstacles::kFewObstacles);
  } else if (!c.mesh) {
    EXPECT_LE(bounded, Obstacles::kFewObstacles);
  }
  addRandomParticles(p, rng, particles);
  return s;
}

void expectSameState(const ParticleSystem& a, const ParticleSystem& b) {
  ASSERT_EQ(a.size(), b.size());
  const std::span<const float> fa[] = {a.x(), a.y(), a.z(), a.vx(), a.vy(), a.vz()};
  const std::span<const float> fb[] = {b.x(), b.y(), b.z(), b.vx(), b.vy(), b.vz()};
  int reported = 0;
  for (int f = 0; f < 6; ++f)
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::bit_cast<std::uint32_t>(fa[f][i]) != std::bit_cast<std::uint32_t>(fb[f][i]) &&
          reported++ < 10)
        ADD_FAILURE() << "field " << f << " of particle " << i << ": " << fa[f][i] << " against "
                      << fb[f][i] << " on the reference";
}

void expectSameCounts(const StepProfile& a, const StepProfile& b) {
  EXPECT_EQ(a.contacts, b.contacts);
  EXPECT_EQ(a.pushedOut, b.pushedOut);
  EXPECT_EQ(a.bounceLimited, b.bounceLimited);
  EXPECT_EQ(a.outOfRange, b.outOfRange);
}

// Steps a world on the active path and its twin on the reference, comparing after every step;
// returns the counters summed over the steps (on the reference).
StepProfile compareWithReference(const Case& c, int steps, int particles) {
  Scene kernel = makeScene(c, 1, particles, 7);
  Scene reference = makeScene(c, 1, particles, 7);
  StepProfile total;
  for (int step = 0; step < steps; ++step) {
    SCOPED_TRACE("step " + std::to_string(step));
    kernel.world.step();
    {
      const ScopedPath onReference("reference");
      reference.world.step();
    }
    expectSameState(kernel.world.particles(kernel.system),
                    reference.world.particles(reference.system));
    expectSameCounts(kernel.world.profile(), reference.world.profile());
    total.contacts += reference.world.profile().contacts;
    total.pushedOut += reference.world.profile().pushedOut;
    total.bounceLimited += reference.world.profile().bounceLimited;
    total.outOfRange += reference.world.profile().outOfRange;
    if (::testing::Test::HasFailure()) break;
  }
  return total;
}

class ParticleKernel : public test::OnEveryPath {};

TEST_P(ParticleKernel, MatchesTheReferenceBitForBit) {
  StepProfile all;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const StepProfile t = compareWithReference(c, 4, 600);
    all.contacts += t.contacts, all.pushedOut += t.pushedOut, all.bounceLimited += t.bounceLimited;
    all.outOfRange += t.outOfRange;
    if (HasFailure()) return;
  }
  // The inputs reach every branch that counts: in the 4 hard cases' 4 steps, one wild particle
  // is held every step and the other from the second on (7 a case).
  EXPECT_GT(all.contacts, 1000u);
  EXPECT_GT(all.pushedOut, 100u);
  EXPECT_GT(all.bounceLimited, 10u);
  EXPECT_EQ(all.outOfRange, 4u * 7u);
}

TEST_P(ParticleKernel, PlainLoopMatchesTheReferenceBitForBit) {
  if (referencePathActive()) GTEST_SKIP() << "the reference path runs no kernel";
  detail::setPlainLoops(true);
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    compareWithReference(c, 3, 200);
    if (HasFailure()) break;
  }
  detail::setPlainLoops(false);
}

// Many obstacles: the kernel takes the rows near each vector's paths from the obstacles' tree,
// the reference those near each particle's; the same rows meet each particle, so the bits agree.
TEST_P(ParticleKernel, ManyObstaclesThroughTheTreeMatchTheReference) {
  std::vector<Case> many;
  for (const int k : {0, 2, 7, 11}) {  // explicit Euler hard and limited, velocity and position
    many.push_back(cases()[k]);        // Verlet with drag and friction, and limited
    many.back().many = true;
  }
  StepProfile all;
  for (const bool plain : {false, true}) {
    if (plain && referencePathActive()) break;
    detail::setPlainLoops(plain);
    for (const Case& c : many) {
      SCOPED_TRACE(c.name + (plain ? " (plain loop)" : ""));
      const StepProfile t = compareWithReference(c, 4, 600);
      all.contacts += t.contacts, all.pushedOut += t.pushedOut;
      all.bounceLimited += t.bounceLimited;
      if (HasFailure()) break;
    }
    detail::setPlainLoops(false);
  }
  EXPECT_GT(all.contacts, 1000u);
  EXPECT_GT(all.pushedOut, 100u);
  EXPECT_GT(all.bounceLimited, 10u);
}

// A step skips its first push-out when the last one left every particle outside (particles.hpp):
// an exact shortcut, so a world made to look for them every step (a position set before each)
// ends with the same bits and counters.
TEST_P(ParticleKernel, SkippingTheFirstPushOutChangesNoBit) {
  for (const int k : {0, 4, 7, 10}) {
    Case c = cases()[k];
    c.many = k == 7;
    SCOPED_TRACE(c.name);
    Scene skipping = makeScene(c, 1, 600, 5), looking = makeScene(c, 1, 600, 5);
    ParticleSystem& p = looking.world.particles(looking.system);
    for (int step = 0; step < 30; ++step) {
      p.setPosition(p.handle(0), p.position(p.handle(0)));  // marks the system unknown
      skipping.world.step(), looking.world.step();
      expectSameState(skipping.world.particles(skipping.system), p);
      expectSameCounts(skipping.world.profile(), looking.world.profile());
      if (HasFailure()) return;
    }
  }
}

// A mesh among the obstacles: its triangles are tested lane by lane by the reference's test from
// within the kernel, with few obstacles and with many.
TEST_P(ParticleKernel, MeshesMatchTheReference) {
  StepProfile all;
  for (const int k : {0, 1, 5, 7}) {
    Case c = cases()[k];
    c.mesh = true;
    c.many = k == 7;
    SCOPED_TRACE(c.name);
    const StepProfile t = compareWithReference(c, 4, 600);
    all.contacts += t.contacts, all.pushedOut += t.pushedOut;
    if (HasFailure()) return;
  }
  EXPECT_GT(all.contacts, 1000u);
}

// A world with no obstacles and one with particles only past the first vector's tail: the kernel
// never reads past the padded streams and leaves the pinned padding as it is.
TEST_P(ParticleKernel, TailsAndEmptyObstacles) {
  for (int n : {1, 15, 17, 4095, 4097}) {
    SCOPED_TRACE(n);
    const auto build = [&](Scene& s) {
      s.system = s.world.addParticles();
      ParticleSystem& p = s.world.particles(s.system);
      for (int i = 0; i < n; ++i) p.add(Vec3f(float(i), 1, 0), Vec3f(0, float(i % 5), 1));
    };
    Scene kernel, reference;
    build(kernel), build(reference);
    kernel.world.step();
    {
      const ScopedPath onReference("reference");
      reference.world.step();
    }
    expectSameState(kernel.world.particles(kernel.system),
                    reference.world.particles(reference.system));
  }
}

// The streams' bits, hashed (FNV-1a).
std::uint64_t stateHash(const ParticleSystem& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (const std::span<const float> f : {s.x(), s.y(), s.z(), s.vx(), s.vy(), s.vz()})
    for (const float x : f) h = (h ^ std::bit_cast<std::uint32_t>(x)) * 1099511628211ull;
  return h;
}

TEST_P(ParticleKernel, SameStateAtOneAndTwoThreads) {
  // Velocity Verlet with drag and friction, with few obstacles, and with many and a mesh (the
  // kernel's calls into the library from both threads).
  for (const bool calls : {false, true}) {
    Case c = cases()[7];
    c.many = c.mesh = calls;
    SCOPED_TRACE(calls ? "many obstacles and a mesh" : "few obstacles");
    std::uint64_t hashes[2];
    StepProfile profiles[2];
    for (int threads : {1, 2}) {
      Scene s = makeScene(c, threads, 3 * 4096 + 77, 11);  // four partitions, the last one short
      // Fewer steps with the calls: their obstacles are 16 times as many, and the tree's queries
      // and the mesh's rays run from both threads from the first step on.
      for (int step = 0; step < (calls ? 5 : 20); ++step) s.world.step();
      hashes[threads - 1] = stateHash(s.world.particles(s.system));
      profiles[threads - 1] = s.world.profile();
    }
    EXPECT_EQ(hashes[0], hashes[1]);
    expectSameCounts(profiles[0], profiles[1]);
  }
}

SIMDPHYS_ON_EVERY_PATH(ParticleKernel);

}  // namespace
}  // namespace simdphys

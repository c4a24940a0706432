// The world (world.hpp) as a user drives it: particle systems and obstacles behind generational
// handles, dense streams read in place, adding and removing between steps, the profile, and bad
// input rejected with an error naming what and where, the world unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "expect_error.hpp"
#include "simdphys/world.hpp"

namespace simdphys {
namespace {

using test::expectError;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(World, AnEmptyWorldStepsAndProfilesNothing) {
  World world;
  world.step();
  EXPECT_EQ(world.profile().particles.elements, 0u);
  EXPECT_EQ(world.profile().particles.seconds, 0.0);  // the stage did not run
  EXPECT_EQ(world.particleSystemCount(), 0u);
}

TEST(World, StreamsAreDenseSpansAndHandlesFollowTheirParticles) {
  World world;
  const Handle s = world.addParticles();
  ParticleSystem& ps = world.particles(s);
  std::vector<Handle> h;
  for (int i = 0; i < 5; ++i) h.push_back(ps.add({float(i), 10, 0}));
  ps.remove(h[1]);  // the last (4) moves into index 1
  ASSERT_EQ(ps.size(), 4u);
  EXPECT_EQ(ps.x()[1], 4.0f);
  EXPECT_EQ(ps.index(h[4]), 1u);
  EXPECT_EQ(ps.position(h[4]), Vec3f(4, 10, 0));
  EXPECT_FALSE(ps.contains(h[1]));
  // A new particle may reuse the slot; the old handle stays stale.
  const Handle again = ps.add({9, 9, 9});
  EXPECT_EQ(again.slot, h[1].slot);
  EXPECT_NE(again.generation, h[1].generation);
  expectError([&] { ps.position(h[1]); }, "is stale");
  EXPECT_EQ(ps.position(again), Vec3f(9, 9, 9));
  // The spans read the streams in place: what a step writes is what they show.
  const float* before = ps.y().data();
  world.step();
  EXPECT_EQ(ps.y().data(), before);
  EXPECT_LT(ps.y()[0], 10.0f);
}

TEST(World, RemovingAParticleMidRunLeavesTheOthersOnTheirPaths) {
  const auto run = [](bool removeOne) {
    World world;
    world.obstacles().add(Plane{{0, 1, 0}, 0});
    const Handle s = world.addParticles({.restitution = 0.8f});
    std::vector<Handle> h;
    for (int i = 0; i < 40; ++i)
      h.push_back(world.particles(s).add({0.1f * i, 1.0f + 0.05f * i, 0}));
    for (int step = 0; step < 120; ++step) {
      if (removeOne && step == 30) world.particles(s).remove(h[7]);
      world.step();
    }
    std::vector<Vec3f> out;
    for (int i = 0; i < 40; ++i)
      if (i != 7) out.push_back(world.particles(s).position(h[i]));
    return out;
  };
  EXPECT_EQ(run(true), run(false));  // particles are independent: bitwise the same
}

TEST(World, ObstaclesAndSystemsHaveHandlesToo) {
  World world;
  const Handle a = world.obstacles().add(Sphere{{0, 0, 0}, 1});
  const Handle b = world.obstacles().add(Aabb{{2, 2, 2}, {3, 3, 3}});
  world.obstacles().remove(a);
  EXPECT_EQ(world.obstacles().size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Aabb>(world.obstacles()[b]));
  expectError(
      [&] { world.obstacles().remove(a); },
      "Obstacles::remove: the handle (slot 0, generation 1) is stale: its obstacle was removed");
  const Handle s = world.addParticles(), t = world.addParticles();
  world.particles(t).add({0, 0, 0});
  world.removeParticles(s);
  EXPECT_EQ(world.particleSystemCount(), 1u);
  EXPECT_EQ(world.particles(t).size(), 1u);
  expectError([&] { world.particles(s); },
              "World::particles: the handle (slot 0, generation 1) is stale: its particle system");
  expectError([&] { world.particles(Handle{7, 1}); }, "out of range");
}

TEST(World, BadInputIsAnErrorThatNamesItAndChangesNothing) {
  World world;
  const Handle s = world.addParticles();
  ParticleSystem& ps = world.particles(s);
  const Handle p = ps.add({1, 2, 3}, {0, 1, 0});
  expectError([&] { ps.add({kNan, 0, 0}); }, "ParticleSystem::add: element 1: position.x is nan");
  expectError([&] { ps.add({0, 0, 0}, {0, kInf, 0}); }, "velocity.y is inf, not finite");
  expectError([&] { ps.add({0, 0, 0}, {0, 0, 0}, -1); }, "invMass is -1");
  expectError([&] { ps.setPosition(p, {0, 0, 2e18f}); }, "position.z is 2e+18, outside");
  expectError([&] { ps.setForce(p, {kNan, 0, 0}); }, "setForce: element 0: force.x is nan");
  EXPECT_EQ(ps.size(), 1u);
  EXPECT_EQ(ps.position(p), Vec3f(1, 2, 3));
  EXPECT_EQ(ps.velocity(p), Vec3f(0, 1, 0));
  EXPECT_FALSE(ps.hasForces());

  expectError([] { World w({.timeStep = 0}); }, "World: timeStep is 0");
  expectError([] { World w({.timeStep = -0.01f}); }, "timeStep is -0.01");
  expectError([] { World w({.substeps = 0}); }, "substeps is 0");
  expectError([&] { world.setSettings({.timeStep = kNan}); },
              "World::setSettings: timeStep is nan");
  EXPECT_EQ(world.settings().timeStep, 1.0f / 60);

  expectError([&] { world.addParticles({.damping = 0}); }, "damping is 0");
  expectError([&] { world.addParticles({.restitution = 1.5f}); }, "restitution is 1.5");
  expectError([&] { world.addParticles({.gravity = {0, kNan, 0}}); }, "gravity.y is nan");
  expectError([&] { ps.setSettings({.friction = -1}); },
              "ParticleSystem::setSettings: friction is -1");
  EXPECT_EQ(world.particleSystemCount(), 1u);
  EXPECT_EQ(ps.settings().friction, 0.0f);

  expectError([&] { world.obstacles().add(Plane{{0, 2, 0}, 0}); }, "Obstacles::add: obstacle 0");
  expectError([&] { world.obstacles().add(Sphere{{0, 0, 0}, -1}); }, "radius");
  EXPECT_TRUE(world.obstacles().empty());
  ps.remove(p);
  expectError([&] { ps.remove(p); },
              "ParticleSystem::remove: the handle (slot 0, generation 1) is stale: its particle "
              "was removed");
  expectError([&] { ps.index(Handle{}); }, "out of range");
}

TEST(World, TheProfileCountsWhatTheParticlesMet) {
  World world;
  world.obstacles().add(Plane{{0, 1, 0}, 0});
  const Handle s = world.addParticles();
  world.particles(s).add({0, 0.01f, 0}, {0, -5, 0});  // hits the plane this step
  world.particles(s).add({0, 5, 0});                  // falls freely
  world.particles(s).add({0, -1, 0});  // starts inside: pushed out to the skin, falls back on it
  world.step();
  const StepProfile& p = world.profile();
  EXPECT_EQ(p.particles.elements, 3u);
  EXPECT_EQ(p.pushedOut, 1u);
  EXPECT_EQ(p.contacts, 2u);  // the first's bounce; the third's resting contact after the push
  EXPECT_EQ(p.bounceLimited, 0u);
  EXPECT_GT(p.particles.seconds, 0.0);
  EXPECT_GE(p.seconds, p.particles.seconds);
}

// A step looks for particles inside an obstacle first only when something may have put one
// there since the last step (which leaves none inside): a particle set into an obstacle, one
// added, an obstacle added over particles. Each is pushed out the next step.
TEST(World, ParticlesPutInsideBetweenStepsArePushedOut) {
  World world;
  world.obstacles().add(Plane{{0, 1, 0}, 0});
  const Handle s = world.addParticles();
  ParticleSystem& p = world.particles(s);
  const Handle a = p.add({0, 1, 0}), b = p.add({5, 1, 0});
  for (int step = 0; step < 120; ++step) world.step();  // both at rest on the plane
  EXPECT_EQ(world.profile().pushedOut, 0u);
  p.setPosition(a, {0, -0.5f, 0});
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 1u);
  EXPECT_GT(p.position(a).y(), 0.0f);
  world.obstacles().add(Sphere{{5, 0, 0}, 0.5f});  // over b
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 1u);
  EXPECT_GE((p.position(b) - Vec3f(5, 0, 0)).norm(), 0.5f);
  p.add({-3, -1, 0});  // added inside the plane's half-space
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 1u);
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 0u);
}

// In-range inputs can still drive a particle past the supported range: a force of 1e18 N on an
// inverse mass of 1e18 is 1e36 m/s^2, 1e34 m/s after one 1/60 s step. That step is not taken: the
// particle keeps its position and velocity to the bit, the profile counts it, and the others step.
TEST(World, AStepPastTheSupportedRangeIsNotTakenAndIsCounted) {
  World world;
  const Handle s = world.addParticles();
  ParticleSystem& p = world.particles(s);
  const Handle wild = p.add({1, 2, 3}, {4, 5, 6}, 1e18f);
  p.setForce(wild, {1e18f, 0, 0});
  const Handle calm = p.add({0, 10, 0});
  for (int step = 0; step < 3; ++step) {
    world.step();
    EXPECT_EQ(world.profile().outOfRange, 1u);
    EXPECT_EQ(p.position(wild), Vec3f(1, 2, 3));
    EXPECT_EQ(p.velocity(wild), Vec3f(4, 5, 6));
  }
  EXPECT_LT(p.position(calm).y(), 10.0f);  // fell
  for (const std::span<const float> f : {p.x(), p.y(), p.z(), p.vx(), p.vy(), p.vz()})
    for (const float x : f) EXPECT_TRUE(std::isfinite(x));
}

}  // namespace
}  // namespace simdphys

// W4 (workloads/particles.hpp): the inputs WORKLOADS.md specifies, and a small run of it on the
// active path that keeps every particle out of the obstacles and ends where the physics allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "particles.hpp"
#include "testing/particles.hpp"

namespace simdphys {
namespace {

TEST(ParticleWorkload, InputsAreTheSpecs) {
  const workloads::ParticleWorkload w = workloads::makeParticleWorkload(2'000);
  const ParticleSystem& s = w.world.particles(w.particles);
  ASSERT_EQ(s.size(), 2'000u);
  // The first two particles' x, y, z: SplitMix64 from seed 4 and WORKLOADS.md's float uniform,
  // computed outside the library (Python, each operation rounded to float).
  const Vec3f spec[] = {{-0x1.5ef24p+0f, 0x1.6d91f8p+4f, 0x1.cbab8p+2f},
                        {-0x1.50edp-3f, 0x1.9c881p+3f, 0x1.bbff7p+0f}};
  for (std::uint32_t i = 0; i < 2; ++i) {
    EXPECT_EQ(s.position(s.handle(i)), spec[i]) << "particle " << i;
    EXPECT_EQ(s.velocity(s.handle(i)), Vec3f::Zero()) << "particle " << i;
  }
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    ASSERT_TRUE(s.x()[i] >= -10 && s.x()[i] < 10 && s.z()[i] >= -10 && s.z()[i] < 10) << i;
    ASSERT_TRUE(s.y()[i] >= 5 && s.y()[i] < 25) << i;
    ASSERT_EQ(s.invMass()[i], 1.0f) << i;
  }
  const ParticleSettings& p = s.settings();
  EXPECT_EQ(p.gravity, Vec3f(0, -9.82f, 0));
  EXPECT_EQ(p.restitution, 0.7f);
  EXPECT_EQ(p.damping, 0.95f);
  EXPECT_EQ(p.friction, 0.0f);
  EXPECT_EQ(p.integrator, ParticleSettings{}.integrator);
  EXPECT_EQ(w.world.settings().timeStep, 1.0f / 60.0f);
  EXPECT_EQ(w.world.settings().substeps, 1);
  // The ground, then the ramp: 0.35 rad about +z maps the box's x axis to (cos, sin, 0).
  ASSERT_EQ(w.world.obstacles().size(), 2u);
  const Obb ground = std::get<Obb>(w.world.obstacles().shapes()[0]);
  const Obb ramp = std::get<Obb>(w.world.obstacles().shapes()[1]);
  EXPECT_EQ(ground.center, Vec3f(0, -1, 0));
  EXPECT_EQ(ground.halfExtents, Vec3f(20, 1, 20));
  EXPECT_EQ(ground.axes, Mat3f::Identity());
  EXPECT_EQ(ramp.center, Vec3f(0, 2, 0));
  EXPECT_EQ(ramp.halfExtents, Vec3f(6, 0.25f, 6));
  EXPECT_EQ(ramp.axes.col(0), Vec3f(float(std::cos(0.35)), float(std::sin(0.35)), 0));
  EXPECT_EQ(ramp.axes.col(1), Vec3f(-float(std::sin(0.35)), float(std::cos(0.35)), 0));
  EXPECT_EQ(ramp.axes.col(2), Vec3f(0, 0, 1));
}

// How far a particle falls from rest in `frames` steps when it meets nothing: the integrator's
// own recurrence with the per-step damping, in double.
double freeFall(const ParticleSettings& s, float dt, int frames) {
  Vec3d x = Vec3d::Zero(), v = Vec3d::Zero();
  const Vec3d g = s.gravity.cast<double>();
  for (int f = 0; f < frames; ++f) {
    v *= double(s.damping);
    reference::integrate<double>(s.integrator, x, v, double(dt), [&](const Vec3d&) { return g; });
  }
  return -x.y();
}

TEST(ParticleWorkload, SmallRunStaysOutAndSettles) {
  workloads::ParticleWorkload w = workloads::makeParticleWorkload(2'000);
  const ParticleSystem& s = w.world.particles(w.particles);
  const std::vector<float> y0(s.y().begin(), s.y().end());
  const std::vector<float> x0(s.x().begin(), s.x().end()), z0(s.z().begin(), s.z().end());
  for (int f = 0; f < workloads::kParticleFrames; ++f) w.world.step();

  const ParticleSettings& p = s.settings();
  const float dt = w.world.settings().timeStep;
  const double fall = freeFall(p, dt, workloads::kParticleFrames);
  // The ramp's highest point: its top face's corner on the +x side.
  const Obb ramp = workloads::particleRamp();
  const double rampTop = (ramp.center + ramp.axes * ramp.halfExtents).y();
  // No particle falls faster than the damped recurrence's limit g dt / (1 - damping) (3.3 m/s),
  // so none rebounds higher than (restitution * that)^2 / 2g (0.27 m) above what it hit.
  const double vMax = -p.gravity.y() * dt / (1 - p.damping);
  const double rebound = std::pow(p.restitution * vMax, 2) / (2 * -p.gravity.y());
  ASSERT_GT(fall, 10);  // 14.9 m: about half the particles are still falling at the end
  ASSERT_LT(rebound, 0.3);

  // The ramp's shadow on the ground (x and z half widths): particles fall straight down until
  // they meet something, so one outside it meets the ground only.
  const Vec3f shadow = ramp.axes.cwiseAbs() * ramp.halfExtents;
  const auto overRamp = [&](float x, float z) {
    return std::abs(x - ramp.center.x()) <= shadow.x() &&
           std::abs(z - ramp.center.z()) <= shadow.z();
  };

  // Bounds on the mean final height: a particle whose free fall ends above everything it could
  // meet (the ground's top, y = 0, or the ramp's top over the ramp) met nothing and ends there;
  // any other lies on or above the ground and no higher than a rebound above what it met.
  double sum = 0, low = 0, high = 0;
  std::size_t unobstructed = 0;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const Vec3f x(s.x()[i], s.y()[i], s.z()[i]);
    ASSERT_FALSE(w.world.obstacles().inside(x)) << "particle " << i << " at " << x.transpose();
    ASSERT_GE(x.y(), -p.skin) << "particle " << i << " below the ground";
    sum += x.y();
    const double free = double(y0[i]) - fall;
    const double top = overRamp(x0[i], z0[i]) ? rampTop : 0;
    if (free > top) {
      // 600 float roundings of coordinates below 32 (half an ulp, 1e-6, each) at most.
      EXPECT_NEAR(x.y(), free, 1e-3) << "particle " << i;
      EXPECT_EQ(x.x(), x0[i]) << "particle " << i;
      EXPECT_EQ(x.z(), z0[i]) << "particle " << i;
      ++unobstructed;
      low += free, high += free;
    } else {
      high += top + rebound;
    }
  }
  const double n = double(s.size());
  // About 43%: the 29% that start above 14.9 + 4.3 m, and the 14% beside the ramp above 14.9 m.
  EXPECT_GT(unobstructed, s.size() / 4);
  EXPECT_GE(sum / n, low / n);
  EXPECT_LE(sum / n, high / n);
}

}  // namespace
}  // namespace simdphys

// Springs and cloth (cloth.hpp) by their physics: a single spring against its closed form, XPBD's
// convergence, pins, the sphere and a thin box against a fast cloth, W3 at the defaults, the hard
// cases, picking, and bad input. The kernels' agreement with the reference is cloth_kernel_test.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "simdphys/world.hpp"
#include "testing/cloth.hpp"
#include "tests/expect_error.hpp"
#include "tests/paths.hpp"
#include "workloads/cloth.hpp"

namespace simdphys {
namespace {

using test::expectError;

// A particle of mass m on a spring of stiffness k and damping c to a pinned one, along x, no
// gravity, released from rest at x0 from the spring's rest length 1.
struct Oscillator {
  World world;
  Handle cloth;
  Oscillator(ClothModel model, float k, float c, float m, float x0, float dt) {
    world.setSettings({dt, 1, 0});
    ClothSettings s;
    s.model = model, s.gravity = Vec3f::Zero(), s.substeps = 1, s.tethers = false;
    const Vec3f p[] = {{0, 0, 0}, {1 + x0, 0, 0}};
    const float w[] = {0, 1 / m};
    const Spring springs[] = {{0, 1, 1, k, c}};
    cloth = world.addCloth(Cloth(p, w, springs, s));
  }
  double x() { return world.cloth(cloth).position(1).x() - 1.0; }
  double v() { return world.cloth(cloth).velocity(1).x(); }
};

// Zero crossings of x, linearly interpolated: their times.
std::vector<double> crossings(Oscillator& o, double dt, int steps) {
  std::vector<double> times;
  double last = o.x();
  for (int s = 1; s <= steps; ++s) {
    o.world.step();
    const double x = o.x();
    if ((last > 0) != (x > 0)) times.push_back(dt * (s - 1 + last / (last - x)));
    last = x;
  }
  return times;
}

TEST(Spring, PeriodMatchesTheClosedForm) {
  // omega = sqrt(k / m) = 10 rad/s, h = 1/600 s: semi-implicit Euler's period is
  // 2 asin(omega h / 2) / omega... off by (omega h)^2 / 24 = 1.2e-5 relative; the interpolated
  // crossings add some 1e-5 s. Tolerance: 1e-4 relative, ten times both.
  const double dt = 1.0 / 600, period = 2 * std::numbers::pi / 10;
  Oscillator o(ClothModel::kMassSpring, 100, 0, 1, 0.1f, float(dt));
  const std::vector<double> t = crossings(o, dt, 6000);
  ASSERT_GE(t.size(), 20u);
  const double measured = 2 * (t.back() - t.front()) / double(t.size() - 1);
  EXPECT_NEAR(measured / period, 1.0, 1e-4);
}

TEST(Spring, DampedDecayMatchesTheClosedForm) {
  // c = 0.4 N s/m, m = 1: the peaks of |x| decay as exp(-c t / 2m), a rate of 0.2 /s. The
  // integrator's damping is first order, off by O(omega h) = 1.7% of the rate; sampling the peaks
  // every step misses them by (omega h)^2 / 2 = 1.4e-4 of their height. Tolerance: 3% of the rate.
  const double dt = 1.0 / 600;
  Oscillator o(ClothModel::kMassSpring, 100, 0.4f, 1, 0.1f, float(dt));
  std::vector<std::pair<double, double>> peaks;  // time, |x|
  double a = std::abs(o.x()), b = a;
  for (int s = 1; s <= 6000; ++s) {  // 10 s
    o.world.step();
    const double c = std::abs(o.x());
    if (b > a && b >= c) peaks.push_back({dt * (s - 1), b});
    a = b, b = c;
  }
  ASSERT_GE(peaks.size(), 30u);
  const auto& [t0, x0] = peaks[1];
  const auto& [t1, x1] = peaks.back();
  EXPECT_NEAR(std::log(x0 / x1) / (t1 - t0), 0.2, 0.2 * 0.03);
}

TEST(Spring, UndampedEnergyStaysBounded) {
  // Semi-implicit Euler is symplectic: the energy oscillates by O(omega h) = 1.7% and does not
  // drift. 10,000 steps of 1/600 s (26.5 periods of 0.63 s): bounded within 2%.
  Oscillator o(ClothModel::kMassSpring, 100, 0, 1, 0.1f, 1.0f / 600);
  const double e0 = 0.5 * 100 * 0.01;
  double lo = e0, hi = e0;
  for (int s = 0; s < 10000; ++s) {
    o.world.step();
    const double e = 0.5 * o.v() * o.v() + 0.5 * 100 * o.x() * o.x();
    lo = std::min(lo, e), hi = std::max(hi, e);
  }
  EXPECT_GT(lo, 0.98 * e0);
  EXPECT_LT(hi, 1.02 * e0);
}

// W3's cloth, n = 32, without the sphere: hanging from its corners.
double hangingStretch(int substeps, bool tethers) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(32);
  World world;
  ClothSettings s;
  s.substeps = substeps, s.tethers = tethers;
  const Handle h = world.addCloth(Cloth::grid(workloads::clothGrid(w), s));
  for (int f = 0; f < 60; ++f) world.step();
  return workloads::clothStretch(w, world.cloth(h).positions()).mean;
}

TEST(Xpbd, StretchFallsAsSubstepsGrow) {
  double last = HUGE_VAL;
  for (const int substeps : {1, 2, 4, 8, 16, 32}) {
    const double stretch = hangingStretch(substeps, false);
    EXPECT_LT(stretch, last) << substeps << " substeps";
    last = stretch;
  }
  EXPECT_LT(last, 0.01) << "32 substeps: within 1% of the rest lengths";
}

TEST(Xpbd, TethersCutTheStretch) { EXPECT_LT(hangingStretch(4, true), hangingStretch(4, false)); }

class Cloths : public test::OnEveryPath {};

TEST_P(Cloths, PinnedParticlesNeverMove) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(24);
  World world;
  world.obstacles().add(workloads::kClothSphere);
  for (const ClothModel model : {ClothModel::kXpbd, ClothModel::kMassSpring}) {
    ClothGrid g = workloads::clothGrid(w);
    g.structural = g.shear = g.bend = {2000, 1};
    ClothSettings s;
    s.model = model;
    const Handle h = world.addCloth(Cloth::grid(g, s));
    for (int f = 0; f < 30; ++f) world.step();
    for (const std::uint32_t pin : {0u, 23u})
      EXPECT_EQ(world.cloth(h).position(pin), w.positions[pin]);
    EXPECT_EQ(world.cloth(h).velocity(0), Vec3f::Zero());
    world.removeCloth(h);
  }
}

// A 24 x 24 corner of W3's cloth (1.15 m wide) dropped onto W3's sphere for 2 s, on every path:
// never deeper in the true sphere than rounding (the margin, 0.01, is kept outside it).
TEST_P(Cloths, NothingEntersTheSphere) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(24);
  World world;
  world.obstacles().add(workloads::kClothSphere);
  const Handle h = world.addCloth(Cloth::grid(workloads::clothGrid(w)));
  double deepest = 0;
  for (int f = 0; f < 120; ++f) {
    world.step();
    deepest = std::max(
        deepest, workloads::spherePenetration(workloads::kClothSphere, world.cloth(h).positions()));
  }
  // Rounding: 1e-6 of the radius.
  EXPECT_LE(deepest, 1e-6);
}

// W3 at n = 48 (a seventh of the cost of the default), the defaults, 300 frames, on the active
// path (every path steps as the reference does, bit for bit: cloth_kernel_test): the targets of
// the benchmark at n = 128: Bullet's mean stretch at 30 iterations (0.0164), no deeper in the
// sphere than rounding at any frame, finite.
TEST(Cloth, W3HoldsAtTheDefaults) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(48);
  World world(WorldSettings{workloads::kClothFrameTime, 1, 0});
  world.obstacles().add(workloads::kClothSphere);
  const Handle h = world.addCloth(Cloth::grid(workloads::clothGrid(w)));
  double deepest = 0;
  for (int f = 0; f < workloads::kClothFrames; ++f) {
    world.step();
    deepest = std::max(
        deepest, workloads::spherePenetration(workloads::kClothSphere, world.cloth(h).positions()));
  }
  const std::vector<Vec3f> x = world.cloth(h).positions();
  ASSERT_TRUE(workloads::allFinite(x));
  EXPECT_LT(workloads::clothStretch(w, x).mean, 0.0164);
  EXPECT_LE(deepest, 1e-6);  // rounding: 1e-6 of the radius
}

TEST_P(Cloths, AFastClothDoesNotPassThroughAThinBox) {
  // A 16 x 16 sheet falling at 40 m/s onto a box 0.01 thick: each substep moves it 0.067, seven
  // times the box's thickness, so only the path test stops it.
  const workloads::ClothWorkload w = workloads::makeClothWorkload(16);
  World world;
  world.obstacles().add(Aabb{Vec3f(-2, 0.995f, -2), Vec3f(2, 1.005f, 2)});
  ClothGrid g = workloads::clothGrid(w);
  std::fill(g.invMass.begin(), g.invMass.end(), 1.0f);  // nothing pinned
  const Handle h = world.addCloth(Cloth::grid(g));
  for (std::uint32_t i = 0; i < 256; ++i) world.cloth(h).setVelocity(i, Vec3f(0, -40, 0));
  for (int f = 0; f < 30; ++f) world.step();
  for (const Vec3f& p : world.cloth(h).positions()) EXPECT_GT(p.y(), 1.005f);
}

TEST_P(Cloths, AFastClothDoesNotPassThroughAMesh) {
  // The thin box's case with a two-sided sheet of 8 triangles: the cloth stays above it, within
  // the margin's rounding (1e-6).
  const workloads::ClothWorkload w = workloads::makeClothWorkload(16);
  World world;
  world.obstacles().add(std::make_shared<const MeshBvh>(
      heightfieldMesh(3, 3, -2, 2, -2, 2, [](double, double) { return 1.0; })));
  ClothGrid g = workloads::clothGrid(w);
  std::fill(g.invMass.begin(), g.invMass.end(), 1.0f);
  const Handle h = world.addCloth(Cloth::grid(g));
  for (std::uint32_t i = 0; i < 256; ++i) world.cloth(h).setVelocity(i, Vec3f(0, -40, 0));
  for (int f = 0; f < 30; ++f) world.step();
  for (const Vec3f& p : world.cloth(h).positions()) EXPECT_GT(p.y(), 1.0f - 1e-6f);
}

TEST(Cloth, HardCasesStayFinite) {
  World world;
  world.obstacles().add(Plane{Vec3f(0, 1, 0), 0});
  // A chain of 100 rigid links, horizontal, pinned at one end, with heavy masses hanging from
  // light ones (mass 1000 every tenth link, 1 elsewhere), a zero-rest-length spring at its end.
  std::vector<Vec3f> p;
  std::vector<float> w;
  std::vector<Spring> springs;
  for (std::uint32_t i = 0; i <= 100; ++i) {
    p.emplace_back(0.1f * float(i), 20, 0);
    w.push_back(i == 0 ? 0.0f : i % 10 == 0 ? 1e-3f : 1.0f);
    if (i > 0) springs.push_back({i - 1, i, 0.1f});
  }
  p.emplace_back(10.0f, 20, 0.5f), w.push_back(1);
  springs.push_back({100, 101, 0, 1e4f, 10});
  const Handle chain = world.addCloth(Cloth(p, w, springs));
  // Very stiff springs at a large step: XPBD holds; mass-spring substeps itself.
  const workloads::ClothWorkload cw = workloads::makeClothWorkload(12);
  ClothGrid g = workloads::clothGrid(cw);
  g.structural = g.shear = g.bend = {1e7f, 0};
  ClothSettings massSpring;
  massSpring.model = ClothModel::kMassSpring;
  const Handle stiff = world.addCloth(Cloth::grid(g, massSpring));
  // A cloth folded onto itself (its far half above its near half, 1e-3 apart): no self-collision
  // is modelled, so the halves pass through each other; it must stay finite.
  std::vector<Vec3f> folded = cw.positions;
  for (std::size_t j = 6; j < 12; ++j)
    for (std::size_t i = 0; i < 12; ++i) {
      Vec3f& q = folded[j * 12 + i];
      q = folded[(11 - j) * 12 + i] + Vec3f(0, 1e-3f, 0);
    }
  const Handle fold = world.addCloth(Cloth(folded, cw.invMass, workloads::clothSprings(cw)));
  world.setSettings({0.05f, 1, 0});
  for (int f = 0; f < 40; ++f) world.step();  // 2 s
  for (const Handle h : {chain, stiff, fold})
    EXPECT_TRUE(workloads::allFinite(world.cloth(h).positions()));
  // The tethers hold the chain's reach: no particle beyond its rest distance along the chain
  // from the pin (1e-5 relative: the tether's projection and the float rest lengths round by a
  // few ulps), none below the plane. The links between the heavy and the light particles are not
  // held: XPBD needs some 50 substeps for a mass ratio of 1000 (docs/softbody.md).
  const std::vector<Vec3f> x = world.cloth(chain).positions();
  for (std::size_t i = 1; i <= 100; ++i)
    EXPECT_LE((x[i] - x[0]).norm(), 0.1f * float(i) * (1 + 1e-5f)) << i;
  for (const Vec3f& q : x) EXPECT_GE(q.y(), 0.0f);
}

TEST(Cloth, AChainOf100LinksHangsAtItsLength) {
  // 100 rigid links of 0.1 m and mass 1, released horizontal from a pin: after 3 s of swinging, at
  // the defaults, every link within 1% of its length.
  std::vector<Vec3f> p;
  std::vector<float> w;
  std::vector<Spring> springs;
  for (std::uint32_t i = 0; i <= 100; ++i) {
    p.emplace_back(0.1f * float(i), 20, 0), w.push_back(i == 0 ? 0.0f : 1.0f);
    if (i > 0) springs.push_back({i - 1, i, 0.1f});
  }
  World world;
  const Handle h = world.addCloth(Cloth(p, w, springs));
  for (int f = 0; f < 180; ++f) world.step();
  const std::vector<Vec3f> x = world.cloth(h).positions();
  double worst = 0;
  for (std::size_t i = 1; i <= 100; ++i)
    worst = std::max(worst, double((x[i] - x[i - 1]).norm()) / 0.1 - 1);
  EXPECT_LT(worst, 0.01);
}

SIMDPHYS_ON_EVERY_PATH(Cloths);

TEST(Cloth, PenaltySpringsHoldAParticleAtTheClosedFormDepth) {
  // A particle of mass 1 on the plane y = 0, held by a penalty spring k = 1e4 N/m within the
  // margin 0.01: at rest k d = m g, so it sits d = 9.82e-4 below the margin, at y = 0.01 - d.
  // Damped (5 /s) for 5 s, its motion decays by exp(-25): the rest height within 1e-6 (float
  // positions near 0.01 round to 1e-9; the damping's residue is below 1e-7).
  World world;
  world.obstacles().add(Plane{Vec3f(0, 1, 0), 0});
  ClothSettings s;
  s.model = ClothModel::kMassSpring, s.penalty = 1e4f, s.damping = 5, s.tethers = false;
  const Vec3f p[] = {{0, 0.02f, 0}};
  const float w[] = {1};
  const Handle h = world.addCloth(Cloth(p, w, {}, s));
  for (int f = 0; f < 300; ++f) world.step();
  EXPECT_NEAR(world.cloth(h).position(0).y(), 0.01 - 9.82e-4, 1e-6);
  // Penalty springs are forces: XPBD refuses them.
  s.model = ClothModel::kXpbd;
  expectError([&] { Cloth(p, w, {}, s); }, "penalty is 10000, needs ClothModel::kMassSpring");
}

TEST(Cloth, MassSpringSubstepsItselfOrRefuses) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(8);
  ClothGrid g = workloads::clothGrid(w);
  g.structural = g.shear = g.bend = {1e5f, 0};
  ClothSettings s;
  s.model = ClothModel::kMassSpring, s.substeps = 1;
  World world;
  const Handle h = world.addCloth(Cloth::grid(g, s));
  world.step();  // raised to the stability bound: no explosion
  for (int f = 0; f < 60; ++f) world.step();
  EXPECT_LT(workloads::clothStretch(w, world.cloth(h).positions()).max, 0.5);
  // Stiffer than kMaxSubsteps can hold at this step: refused, nothing moved.
  g.structural = {1e12f, 0};
  const Handle rigid = world.addCloth(Cloth::grid(g, s));
  const std::vector<Vec3f> before = world.cloth(h).positions();
  expectError([&] { world.step(); }, "more than ClothSettings::kMaxSubsteps");
  EXPECT_EQ(world.cloth(h).positions(), before);
  world.removeCloth(rigid);
  g.structural = {kRigid, 0};
  world.addCloth(Cloth::grid(g, s));
  expectError([&] { world.step(); }, "cannot step a rigid spring");
}

TEST(Cloth, PicksTheNearestParticleAlongARay) {
  const workloads::ClothWorkload w = workloads::makeClothWorkload(16);
  const Cloth c = Cloth::grid(workloads::clothGrid(w));
  // Straight down onto particle (5, 7) from above.
  const Vec3f target = w.positions[7 * 16 + 5];
  const auto hit = c.pick(Ray{target + Vec3f(0, 3, 0), Vec3f(0, -1, 0)}, 0.01f);
  ASSERT_TRUE(hit);
  EXPECT_EQ(*hit, 7u * 16 + 5);
  EXPECT_FALSE(c.pick(Ray{target + Vec3f(0, 3, 0), Vec3f(0, 1, 0)}, 0.01f));
  EXPECT_TRUE((c.bounds().min.array() <= target.array()).all() &&
              (target.array() <= c.bounds().max.array()).all());
}

TEST(Cloth, BadInputIsRefusedWithAClearError) {
  const Vec3f p[] = {{0, 0, 0}, {1, 0, 0}};
  const float w[] = {1, 1};
  const auto make = [&](Spring s) { return [=] { Cloth(p, w, std::span<const Spring>(&s, 1)); }; };
  expectError(make({0, 0, 1}), "spring 0: b is 0, joins the particle to itself");
  expectError(make({0, 2, 1}), "spring 0: b is 2, is not a particle index");
  expectError(make({0, 1, -1}), "spring 0: rest is -1");
  expectError(make({0, 1, 1, -5}), "spring 0: stiffness is -5");
  expectError(make({0, 1, NAN}), "spring 0: rest is nan, not finite");
  expectError(make({0, 1, 1, 10, -1}), "spring 0: damping is -1");
  const float nanMass[] = {1, NAN};
  expectError([&] { Cloth(p, nanMass, {}); }, "particle 1: invMass is nan");
  const Vec3f far[] = {{0, 0, 0}, {2e18f, 0, 0}};
  expectError([&] { Cloth(far, w, {}); }, "particle 1: position.x is 2e+18");
  const Spring twice[] = {{0, 1, 1}, {1, 0, 1}};
  const std::uint32_t same[] = {0, 0};
  expectError([&] { Cloth(p, w, twice, {}, same); }, "has two springs in batch 0");
  ClothSettings s;
  s.substeps = 0;
  expectError([&] { Cloth(p, w, {}, s); }, "substeps is 0");
  s = {}, s.margin = 0;
  expectError([&] { Cloth(p, w, {}, s); }, "margin is 0");
  // A bad value set on a cloth in a world: refused, the world unchanged.
  World world;
  const Handle h = world.addCloth(Cloth(p, w, {}));
  expectError([&] { world.cloth(h).setPosition(1, Vec3f(NAN, 0, 0)); }, "position.x is nan");
  expectError([&] { world.cloth(h).setVelocity(2, Vec3f::Zero()); }, "particle is 2");
  EXPECT_EQ(world.cloth(h).position(1), p[1]);
}

}  // namespace
}  // namespace simdphys

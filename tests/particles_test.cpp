// Particles (particles.hpp): the four integrators against closed forms (the double reference, the
// same integrate() the world runs), and a world's particles against the physics they model: free
// flight, bounces in the ratio of the restitution squared, friction on a ramp, no tunnelling at
// 1,000 m/s through faces, edges and corners, particles starting inside obstacles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "paths.hpp"
#include "simdphys/world.hpp"
#include "testing/particles.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

constexpr Integrator kIntegrators[] = {Integrator::kExplicitEuler, Integrator::kSemiImplicitEuler,
                                       Integrator::kVelocityVerlet, Integrator::kPositionVerlet};

// ---- integrators, in double, against closed forms -------------------------------------------

// The velocity an integrator starts from for the motion x(t), v(t): its state's meaning
// (particles.hpp). Position Verlet keeps the mean velocity over the last step, (x(0) - x(-dt)) /
// dt.
template <class X, class V>
Vec3d startVelocity(Integrator integrator, X x, V v, double dt) {
  if (integrator == Integrator::kPositionVerlet) return (x(0.0) - x(-dt)) / dt;
  return v(0.0);
}

TEST(Integrators, ProjectileIsExactForVerletAndOffByHalfATDtForEuler) {
  const Vec3d x0(1, 2, 3), v0(4, 5, -6), g(0, -9.82, 0);
  const auto x = [&](double t) { return Vec3d(x0 + v0 * t + 0.5 * g * t * t); };
  const auto v = [&](double t) { return Vec3d(v0 + g * t); };
  const double dt = 1.0 / 64;  // a power of two: n dt is exact
  const int n = 640;           // 10 s
  const double t = n * dt;
  for (Integrator integrator : kIntegrators) {
    SCOPED_TRACE(toString(integrator));
    Vec3d p = x0, u = startVelocity(integrator, x, v, dt);
    for (int i = 0; i < n; ++i)
      reference::integrate<double>(integrator, p, u, dt, [&](const Vec3d&) { return g; });
    // The Euler forms' error is exactly -+ g t dt / 2 (sums of n (n -+ 1) / 2 steps of g dt^2);
    // the Verlet forms are exact. Rounding: n steps of a few operations on values up to |x| ~ 500:
    // 640 * 4 * 2^-53 * 500 < 1e-9.
    Vec3d expected = x(t);
    if (integrator == Integrator::kExplicitEuler) expected -= 0.5 * g * t * dt;
    if (integrator == Integrator::kSemiImplicitEuler) expected += 0.5 * g * t * dt;
    EXPECT_LT((p - expected).norm(), 1e-9) << p.transpose() << " vs " << expected.transpose();
  }
}

// The harmonic oscillator x'' = -w^2 x, x(0) = 1, v(0) = 0, period 1 s.
constexpr double kOmega = 2 * std::numbers::pi;
Vec3d spring(const Vec3d& x) { return -kOmega * kOmega * x; }
double energy(const Vec3d& x, const Vec3d& v) {
  return 0.5 * v.squaredNorm() + 0.5 * kOmega * kOmega * x.squaredNorm();
}

TEST(Integrators, OscillatorEnergyStaysBoundedOverTenThousandPeriodsForTheSymplecticOnes) {
  const double dt = 1.0 / 100;
  const auto x = [](double t) { return Vec3d(std::cos(kOmega * t), 0, 0); };
  const auto v = [](double t) { return Vec3d(-kOmega * std::sin(kOmega * t), 0, 0); };
  for (Integrator integrator :
       {Integrator::kSemiImplicitEuler, Integrator::kVelocityVerlet, Integrator::kPositionVerlet}) {
    SCOPED_TRACE(toString(integrator));
    Vec3d p = x(0), u = startVelocity(integrator, x, v, dt);
    const double e0 = energy(x(0), v(0));
    double worst = 0;
    for (int i = 0; i < 10'000 * 100; ++i) {
      reference::integrate<double>(integrator, p, u, dt, spring);
      worst = std::max(worst, std::abs(energy(p, u) / e0 - 1));
    }
    // A symplectic method conserves a modified energy H + O(w dt) exactly, so the true energy
    // only oscillates: by up to w dt / 2 (0.031) relative for the first-order velocities (the
    // Euler form's, and position Verlet's mean over a step), (w dt)^2 / 8 (5e-4) for velocity
    // Verlet. The bound w dt (twice the first) would be broken by any secular drift.
    const double bound = integrator == Integrator::kVelocityVerlet ? 1e-3 : kOmega * dt;
    EXPECT_LT(worst, bound);
  }
}

TEST(Integrators, ExplicitEulerGainsEnergyByOnePlusWDtSquaredEachStep) {
  // x' = x + v dt, v' = v - w^2 x dt multiplies the energy by exactly 1 + (w dt)^2.
  const double dt = 1.0 / 100;
  Vec3d p(1, 0, 0), u(0, 0, 0);
  for (int i = 0; i < 100; ++i)
    reference::integrate<double>(Integrator::kExplicitEuler, p, u, dt, spring);
  const double expected = std::pow(1 + kOmega * kOmega * dt * dt, 100);  // 1.48: it grows
  EXPECT_NEAR(energy(p, u) / energy({1, 0, 0}, {0, 0, 0}), expected, 1e-12 * expected);
}

// The position error at t = 0.3 s (not a whole period, where the first-order phase errors cancel)
// at dt and dt / 2: their ratio is 2^order.
double stateError(Integrator integrator, double dt) {
  const auto x = [](double t) { return Vec3d(std::cos(kOmega * t), 0, 0); };
  const auto v = [](double t) { return Vec3d(-kOmega * std::sin(kOmega * t), 0, 0); };
  Vec3d p = x(0), u = startVelocity(integrator, x, v, dt);
  const int n = int(std::lround(0.3 / dt));
  for (int i = 0; i < n; ++i) reference::integrate<double>(integrator, p, u, dt, spring);
  return (p - x(n * dt)).norm();
}

TEST(Integrators, OrderOfConvergenceIsOneForEulerAndTwoForVerlet) {
  for (Integrator integrator : kIntegrators) {
    SCOPED_TRACE(toString(integrator));
    const double order =
        std::log2(stateError(integrator, 1.0 / 1000) / stateError(integrator, 1.0 / 2000));
    const double expected =
        integrator == Integrator::kExplicitEuler || integrator == Integrator::kSemiImplicitEuler
            ? 1.0
            : 2.0;
    // At w dt = 0.006 the next term of the error is 0.6% of the leading one, so the measured
    // order is within 0.05 of the asymptotic one.
    EXPECT_NEAR(order, expected, 0.05);
  }
}

// ---- a world's particles ----------------------------------------------------------------------

class Particles : public OnEveryPath {};

Obb rampBox() {  // W4's ramp
  Obb ramp{{0, 2, 0}, {6, 0.25f, 6}};
  ramp.axes = Eigen::AngleAxisf(0.35f, Vec3f::UnitZ()).toRotationMatrix();
  return ramp;
}

TEST_P(Particles, FreeFlightFollowsTheProjectile) {
  World world({.timeStep = 1.0f / 64});
  const Handle s = world.addParticles({.integrator = Integrator::kVelocityVerlet});
  const Handle p = world.particles(s).add({1, 2, 3}, {4, 5, -6});
  for (int i = 0; i < 64; ++i) world.step();
  const Vec3d expected = Vec3d(1, 2, 3) + Vec3d(4, 5, -6) + 0.5 * Vec3d(0, -9.82, 0);
  // 64 float steps of a few roundings each on |x| < 8 (ulp 1e-6): within 64 * 4 * 1e-6.
  EXPECT_LT((world.particles(s).position(p).cast<double>() - expected).norm(), 3e-4);
  EXPECT_EQ(world.profile().contacts, 0u);
  EXPECT_EQ(world.profile().particles.elements, 1u);
}

TEST_P(Particles, ForcesActThroughTheInverseMassAndDragReachesTerminalVelocity) {
  World world({.timeStep = 1.0f / 64});
  const Handle s = world.addParticles({.gravity = Vec3f::Zero()});
  const Handle heavy = world.particles(s).add({0, 0, 0}, Vec3f::Zero(), 0.25f);  // 4 kg
  world.particles(s).setForce(heavy, {8, 0, 0});                                 // 2 m/s^2
  for (int i = 0; i < 64; ++i) world.step();
  // Velocity Verlet is exact for a constant force: x = a t^2 / 2 = 1 m, v = 2 m/s, to the
  // rounding of 64 float steps (ulp 1e-7 at these magnitudes).
  EXPECT_NEAR(world.particles(s).position(heavy).x(), 1.0f, 1e-5);
  EXPECT_NEAR(world.particles(s).velocity(heavy).x(), 2.0f, 1e-5);

  World falling({.timeStep = 1.0f / 64});
  const Handle t = falling.addParticles({.drag = 0.5f});
  const Handle p = falling.particles(t).add({0, 0, 0}, Vec3f::Zero(), 0.5f);  // 2 kg
  for (int i = 0; i < 64 * 30; ++i) falling.step();
  // m g = drag v: v = 2 * 9.82 / 0.5 = 39.28 m/s, approached as exp(-t drag / m) (time constant
  // 4 s; after 30 s within e^-7.5 = 6e-4 of it), the drag taken at the step's start velocity.
  EXPECT_NEAR(falling.particles(t).velocity(p).y(), -39.28f, 39.28f * 1e-3);
}

// Apex heights of a particle dropped from 10 m onto the plane y = 0.
std::vector<double> apexes(float restitution) {
  World world({.timeStep = 1.0f / 240});
  world.obstacles().add(Plane{{0, 1, 0}, 0});
  const Handle s = world.addParticles({.restitution = restitution});
  const Handle p = world.particles(s).add({0, 10, 0});
  std::vector<double> peaks;
  float last = 10, before = 10;
  for (int i = 0; i < 240 * 8; ++i) {
    world.step();
    const float y = world.particles(s).position(p).y();
    if (before < last && last > y && last > 0.5f) peaks.push_back(last);
    before = last, last = y;
    EXPECT_GE(y, 0.0f);
  }
  return peaks;
}

TEST_P(Particles, BounceHeightsFallByTheRestitutionSquared) {
  const std::vector<double> peaks = apexes(0.7f);
  ASSERT_GE(peaks.size(), 3u);
  for (std::size_t k = 0; k + 1 < 3; ++k) {
    // Apex sampled every dt = 1/240 s: off by at most g (dt / 2)^2 / 2 = 2e-5 m of ~4.9 m; the
    // impact found along each step's chord rather than its parabola moves its time by
    // ~ g dt^2 / v, its speed by ~1e-4 relative; the 1 mm skin is 2e-4 of the heights. 0.5%
    // covers these with room; a wrong restitution (0.7 rather than 0.49) is 40% off.
    EXPECT_NEAR(peaks[k + 1] / peaks[k], 0.49, 0.49 * 0.005) << k;
  }
}

TEST_P(Particles, RestsOnTheRampWhenFrictionHoldsAndSlidesAsCoulombSaysWhenNot) {
  const Obb ramp = rampBox();
  const Vec3f up = ramp.axes.col(1), down = -ramp.axes.col(0);  // the slope goes down towards -x
  for (const float mu : {0.5f, 0.2f}) {
    SCOPED_TRACE(mu);
    World world;
    world.obstacles().add(ramp);
    const Handle s = world.addParticles({.restitution = 0, .friction = mu});
    const Vec3f start = ramp.center + up * (ramp.halfExtents.y() + 1e-3f);
    const Handle p = world.particles(s).add(start);
    for (int i = 0; i < 60; ++i) world.step();  // 1 s
    const double along = (world.particles(s).position(p) - start).dot(down);
    const double a = 9.82 * (std::max(0.0, std::sin(0.35) - mu * std::cos(0.35)));
    // mu = 0.5 > tan 0.35 = 0.365: static; mu = 0.2: a = g (sin - mu cos) = 1.52 m/s^2, 0.76 m
    // in 1 s. The resting contact integrates Coulomb's constant acceleration exactly (velocity
    // Verlet), so only the rounding of 60 float steps on |x| < 8 (ulp 1e-6) is left: 1e-4.
    EXPECT_NEAR(along, 0.5 * a, 1e-4);
    EXPECT_FALSE(world.obstacles().inside(world.particles(s).position(p)));
  }
}

// A thin plate, 0.05 thick, and particles at 1,000 m/s (16.7 m a step) aimed at its faces, edges
// and corners from every side: none may pass through or end inside.
TEST_P(Particles, NothingTunnelsAtAThousandMetresASecond) {
  for (const bool rotated : {false, true}) {
    World world;
    Obb plate{{0, 0, 0}, {1, 0.025f, 1}};
    if (rotated)
      plate.axes = Eigen::AngleAxisf(0.6f, Vec3f(1, 2, 3).normalized()).toRotationMatrix();
    world.obstacles().add(plate);
    const Handle s = world.addParticles({.gravity = Vec3f::Zero(), .restitution = 1});
    std::vector<Vec3f> local;  // aim points on the plate: faces, edges, corners
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; y += 2)
        for (int z = -1; z <= 1; ++z) local.emplace_back(0.999f * x, 0.025f * y, 0.999f * z);
    for (int x = -1; x <= 1; x += 2)
      for (int z = -1; z <= 1; z += 2)
        local.emplace_back(x, 0.025f, z), local.emplace_back(x, -0.025f, 0);
    std::vector<Vec3f> starts;
    for (const Vec3f& aim : local)
      for (const Vec3f& from : {Vec3f(0, 1, 0), Vec3f(0, -1, 0), Vec3f(1, 1, 0), Vec3f(-1, 1, 1),
                                Vec3f(1, -1, -1), Vec3f(0.3f, 1, 0.1f)}) {
        const Vec3f target = plate.center + plate.axes * aim;
        const Vec3f start = target + plate.axes * from.normalized() * 5.0f;
        starts.push_back(start);
        world.particles(s).add(start, (target - start).normalized() * 1000.0f);
      }
    for (int step = 0; step < 3; ++step) {
      world.step();
      for (std::uint32_t i = 0; i < world.particles(s).size(); ++i) {
        const Vec3f p = world.particles(s).position(world.particles(s).handle(i));
        const Vec3f q = plate.axes.transpose() * (p - plate.center);
        const Vec3f q0 = plate.axes.transpose() * (starts[i] - plate.center);
        EXPECT_FALSE(world.obstacles().inside(p)) << i;
        // Through the plate means: now in its shadow (within its footprint), on the other side.
        // Paths along a side face (aimed at its edges) pass within rounding of it on either
        // side: the footprint is shrunk by 1e-5, ten times the rounding of the plate's frame
        // at |q| ~ 5 (5 * 2^-24 * a few operations).
        const bool footprint = std::abs(q.x()) < 1 - 1e-5f && std::abs(q.z()) < 1 - 1e-5f;
        EXPECT_FALSE(footprint && q.y() * q0.y() < 0) << "particle " << i << " tunnelled";
      }
    }
    EXPECT_EQ(world.profile().pushedOut, 0u);
  }
}

TEST_P(Particles, AHitExactlyOnAnEdgeTakesTheLowestAxisFace) {
  World world;
  world.obstacles().add(Aabb{{-1, -1, -1}, {1, 1, 1}});
  const Handle s = world.addParticles({.gravity = Vec3f::Zero(), .restitution = 1});
  // Along (-1, -1, 0) through the edge x = 1, y = 1 exactly: both slabs are entered at once.
  const Handle p = world.particles(s).add({3, 3, 0}, {-120, -120, 0});
  world.step();
  const Vec3f v = world.particles(s).velocity(p);
  // The x face (the lower axis) reflects x; y keeps going: documented in world.md.
  EXPECT_EQ(v, Vec3f(120, -120, 0));
  EXPECT_FALSE(world.obstacles().inside(world.particles(s).position(p)));
}

TEST_P(Particles, AParticleStartingInsideIsPushedOutTheShortestWayAndCounted) {
  World world;
  world.obstacles().add(Obb{{0, 0, 0}, {1, 0.5f, 2}});
  world.obstacles().add(Sphere{{10, 0, 0}, 1});
  const Handle s = world.addParticles({.gravity = Vec3f::Zero()});
  const Handle a = world.particles(s).add({0.2f, 0.3f, 0.1f});  // nearest face: +y
  const Handle b =
      world.particles(s).add({10, 0.5f, 0}, {0, -2, 0});  // out along +y, v into it dropped
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 2u);
  const Vec3f pa = world.particles(s).position(a), pb = world.particles(s).position(b);
  EXPECT_FLOAT_EQ(pa.x(), 0.2f);
  EXPECT_NEAR(pa.y(), 0.5 + 1e-3, 1e-6);  // the face plus the skin, to float rounding
  EXPECT_NEAR(pb.y(), 1 + 1e-3, 1e-6);
  EXPECT_EQ(world.particles(s).velocity(b), Vec3f::Zero());
  world.step();
  EXPECT_EQ(world.profile().pushedOut, 0u);  // counted once: it stays out
}

TEST_P(Particles, SlowImpactsDoNotBounceAndPinnedParticlesDoNotMove) {
  World world;
  world.obstacles().add(Plane{{0, 1, 0}, 0});
  const Handle s = world.addParticles({.restitution = 1});
  const Handle slow = world.particles(s).add({0, 0.002f, 0}, {0, -0.5f, 0});
  const Handle pinned = world.particles(s).add({5, 5, 5}, {1, 1, 1}, 0.0f);
  world.step();
  // 0.5 m/s < the 1 m/s threshold: no bounce, the particle stays on the surface.
  EXPECT_LE(world.particles(s).velocity(slow).y(), 0.0f);
  EXPECT_GE(world.particles(s).position(slow).y(), 0.0f);
  EXPECT_EQ(world.particles(s).position(pinned), Vec3f(5, 5, 5));
  // Landing slowly from 3 cm (0.77 m/s) it comes to rest on the surface, not where a step
  // began: within the two skins a resting contact allows.
  const Handle landing = world.particles(s).add({1, 0.03f, 0});
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_GE(world.particles(s).position(landing).y(), 0.0f);
  EXPECT_LE(world.particles(s).position(landing).y(), 2e-3f);
  EXPECT_LE(world.particles(s).position(slow).y(), 2e-3f);
}

TEST_P(Particles, SubstepsAreShorterSteps) {
  const auto run = [](float timeStep, int substeps, int steps) {
    World world({.timeStep = timeStep, .substeps = substeps});
    world.obstacles().add(rampBox());
    const Handle s = world.addParticles({.restitution = 0.6f, .friction = 0.3f});
    for (int i = 0; i < 50; ++i) world.particles(s).add({-5.0f + 0.2f * i, 6, 0.1f * i});
    for (int i = 0; i < steps; ++i) world.step();
    return std::vector<float>(world.particles(s).y().begin(), world.particles(s).y().end());
  };
  // 1/16 s in 4 substeps is 1/64 s four times: the same operations (powers of two: exact dt).
  EXPECT_EQ(run(1.0f / 16, 4, 30), run(1.0f / 64, 1, 120));
}

SIMDPHYS_ON_EVERY_PATH(Particles);

}  // namespace
}  // namespace simdphys

namespace simdphys {
namespace {

// A quad of two triangles in the plane y = 0, a two-sided surface.
MeshObstacle floorMesh() {
  Mesh mesh;
  mesh.vertices = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
  mesh.triangles = {{{0, 2, 1}}, {{0, 3, 2}}};
  return std::make_shared<const MeshBvh>(mesh);
}

TEST_P(Particles, MeshesAreTwoSidedSurfacesNothingCrosses) {
  World world;
  world.obstacles().add(floorMesh());
  const Handle s = world.addParticles({.gravity = Vec3f::Zero(), .restitution = 1});
  // From above and below at 1,000 m/s, through a triangle's inside and exactly along the shared
  // diagonal x = z (the watertight test lets nothing through the crack).
  const Handle above = world.particles(s).add({1, 3, -2}, {0, -1000, 0});
  const Handle below = world.particles(s).add({-1, -3, 2}, {0, 1000, 0});
  const Handle diagonal = world.particles(s).add({2, 3, 2}, {0, -1000, 0});
  for (int i = 0; i < 3; ++i) {
    world.step();
    EXPECT_GT(world.particles(s).position(above).y(), 0.0f);
    EXPECT_LT(world.particles(s).position(below).y(), 0.0f);
    EXPECT_GT(world.particles(s).position(diagonal).y(), 0.0f);
  }
  EXPECT_EQ(world.particles(s).velocity(above), Vec3f(0, 1000, 0));  // restitution 1
}

// More than kFewObstacles bounded obstacles go through the tree: the same answers as testing
// every obstacle (the reference's set without the tree), bit for bit.
TEST_P(Particles, ManyObstaclesAreFoundThroughTheTreeWithTheSameAnswers) {
  World world;
  world.obstacles().add(Plane{{0, 1, 0}, 0});
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < 10; ++k)
      world.obstacles().add(Sphere{{2.0f * i - 9, 1, 2.0f * k - 9}, 0.6f + 0.03f * ((i + k) % 5)});
  world.obstacles().add(floorMesh());
  world.obstacles().add(rampBox());
  const Handle s = world.addParticles({.restitution = 0.8f, .friction = 0.2f});
  for (int i = 0; i < 400; ++i)
    world.particles(s).add({-10.0f + 0.05f * i, 4.0f + 0.01f * (i % 37), -9.5f + 0.047f * i},
                           {0.3f * (i % 7) - 1, -2, 0.2f * (i % 5) - 0.4f});
  std::vector<Vec3f> x, v;
  for (std::uint32_t i = 0; i < 400; ++i)
    x.push_back(world.particles(s).position(world.particles(s).handle(i))),
        v.push_back(world.particles(s).velocity(world.particles(s).handle(i)));
  core::ParticleCounts counts;
  std::uint64_t contacts = 0;
  for (int n = 0; n < 30; ++n) {
    counts += test::stepEveryObstacle(x, v, world.particles(s), world);  // before the world moves
    world.step();
    contacts += world.profile().contacts;
  }
  ASSERT_NE(world.obstacles().tree(), nullptr);
  for (std::uint32_t i = 0; i < 400; ++i) {
    const Handle h = world.particles(s).handle(i);
    EXPECT_EQ(world.particles(s).position(h), x[i]) << i;
    EXPECT_EQ(world.particles(s).velocity(h), v[i]) << i;
  }
  EXPECT_EQ(contacts, counts.contacts);
  EXPECT_GT(counts.contacts, 400u);  // the case is not empty
}

}  // namespace
}  // namespace simdphys

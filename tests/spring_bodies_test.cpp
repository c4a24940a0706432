// Joints and spring bodies (spring_bodies.hpp) by what they build and how it moves: the
// jelly cube's springs and its breathing against the closed form, a cube at rest on a plane, a
// rigid cube thrown spinning, ball joints and hinges, a chain, a soft distance joint as a spring,
// and bad input. The springs' own physics and kernels are cloth_test and cloth_kernel_test.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "simdphys/spring_bodies.hpp"
#include "simdphys/world.hpp"
#include "tests/expect_error.hpp"
#include "tests/paths.hpp"

namespace simdphys {
namespace {

using test::expectError;

// The largest |l / l0 - 1| over the springs of positive rest length.
double worstStretch(std::span<const Spring> springs, const std::vector<Vec3f>& x) {
  double worst = 0;
  for (const Spring& s : springs)
    if (s.rest > 0)
      worst = std::max(worst, std::abs(double((x[s.b] - x[s.a]).norm()) / s.rest - 1));
  return worst;
}

// Times at which a sampled signal crosses zero (linearly interpolated), samples dt apart.
std::vector<double> zeroCrossings(const std::vector<double>& signal, double dt) {
  std::vector<double> times;
  for (std::size_t i = 1; i < signal.size(); ++i)
    if ((signal[i - 1] > 0) != (signal[i] > 0))
      times.push_back(dt * (double(i - 1) + signal[i - 1] / (signal[i - 1] - signal[i])));
  return times;
}

// The period of a sampled oscillation from its first and last zero crossings.
double period(const std::vector<double>& signal, double dt) {
  const std::vector<double> t = zeroCrossings(signal, dt);
  EXPECT_GE(t.size(), 10u);
  return t.size() < 2 ? 0 : 2 * (t.back() - t.front()) / double(t.size() - 1);
}

Vec3f centroid(const std::vector<Vec3f>& x, std::size_t first, std::size_t count) {
  Vec3f sum = Vec3f::Zero();
  for (std::size_t i = first; i < first + count; ++i) sum += x[i];
  return sum / float(count);
}

ClothSettings noGravity(ClothModel model, int substeps) {
  ClothSettings s;
  s.model = model, s.gravity = Vec3f::Zero(), s.substeps = substeps, s.tethers = false;
  return s;
}

TEST(SpringBodies, JellyCubeIsEightCornersAndTwentyEightSprings) {
  SpringBodyBuilder b;
  b.addParticle(Vec3f(9, 9, 9), 1);  // the cube's indices follow it
  const Vec3f centre(1, 2, 3);
  const float edge = 0.5f;
  ASSERT_EQ(b.jellyCube(centre, edge, 8, 100, 0.5f), 1u);
  ASSERT_EQ(b.size(), 9u);
  ASSERT_EQ(b.springs().size(), 28u);
  for (int c = 0; c < 8; ++c) {
    // Exact: centre +- 0.25 is a float.
    const Vec3f corner =
        centre + 0.25f * Vec3f(float(c & 1 ? 1 : -1), float(c & 2 ? 1 : -1), float(c & 4 ? 1 : -1));
    EXPECT_EQ(b.positions()[1 + c], corner) << c;
    EXPECT_EQ(b.invMasses()[1 + c], 8.0f);
  }
  // Every pair of corners once; 12 edges, 12 face diagonals, 4 body diagonals. The rest lengths
  // are exact distances rounded once to float: within half an ulp, 6e-8 relative; 1e-7 allowed.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> pairs;
  int edges = 0, faces = 0, bodies = 0;
  for (const Spring& s : b.springs()) {
    ++pairs[{std::min(s.a, s.b), std::max(s.a, s.b)}];
    EXPECT_EQ(s.stiffness, 100.0f);
    EXPECT_EQ(s.damping, 0.5f);
    const double r = s.rest / double(edge);
    edges += std::abs(r - 1) < 1e-7;
    faces += std::abs(r - std::sqrt(2.0)) < 1e-7 * std::sqrt(2.0);
    bodies += std::abs(r - std::sqrt(3.0)) < 1e-7 * std::sqrt(3.0);
  }
  EXPECT_EQ(pairs.size(), 28u);
  EXPECT_EQ(pairs.begin()->first, std::make_pair(1u, 2u));
  EXPECT_EQ(pairs.rbegin()->first, std::make_pair(7u, 8u));
  EXPECT_EQ(edges, 12);
  EXPECT_EQ(faces, 12);
  EXPECT_EQ(bodies, 4);
  const Cloth cloth = b.build();
  EXPECT_EQ(cloth.size(), 9u);
  EXPECT_EQ(cloth.springs().size(), 28u);
}

TEST(SpringBodies, ChainIsEvenlySpacedLinksAndJointsAreSprings) {
  SpringBodyBuilder b;
  const std::uint32_t pin = b.addParticle(Vec3f(0, 2, 0), 0);
  ASSERT_EQ(b.chain(Vec3f(0, 2, 0), Vec3f(1, 2, 0), 4, 2, 50, 0.25f), 1u);
  ASSERT_EQ(b.size(), 6u);
  ASSERT_EQ(b.springs().size(), 4u);
  for (std::uint32_t i = 0; i < 5; ++i) {
    EXPECT_EQ(b.positions()[1 + i], Vec3f(0.25f * float(i), 2, 0)) << i;  // exact: quarters
    EXPECT_EQ(b.invMasses()[1 + i], 2.0f);
  }
  for (std::uint32_t k = 0; k < 4; ++k) {
    const Spring& s = b.springs()[k];
    EXPECT_EQ(s.a, 1 + k);
    EXPECT_EQ(s.b, 2 + k);
    EXPECT_EQ(s.rest, 0.25f);
    EXPECT_EQ(s.stiffness, 50.0f);
    EXPECT_EQ(s.damping, 0.25f);
  }
  // A rigid distance joint at the built distance, a ball joint of rest 0, a hinge of two.
  EXPECT_EQ(b.distanceJoint(pin, 5), 4u);
  EXPECT_EQ(b.springs()[4].rest, 1.0f);
  EXPECT_EQ(b.springs()[4].stiffness, kRigid);
  EXPECT_EQ(b.ballJoint(pin, 1), 5u);
  EXPECT_EQ(b.springs()[5].rest, 0.0f);
  EXPECT_EQ(b.springs()[5].stiffness, kRigid);
  EXPECT_EQ(b.hinge(pin, 1, 2, 3), 6u);
  ASSERT_EQ(b.springs().size(), 8u);
  EXPECT_EQ(b.springs()[7].a, 2u);
  EXPECT_EQ(b.springs()[7].b, 3u);
  EXPECT_EQ(b.springs()[7].rest, 0.0f);
  b.setInvMass(1, 0);
  EXPECT_EQ(b.build().invMass(1), 0.0f);
}

// The strain of a cube of edge 0.5 breathing: its body diagonal 0-7 over its rest length, minus 1.
double breathing(const Cloth& c) {
  return double((c.position(7) - c.position(0)).norm()) / (0.5 * std::sqrt(3.0)) - 1;
}

class SpringBodyJoints : public test::OnEveryPath {};

// Squeezed uniformly about its centre and released, the jelly cube breathes: it stays a scaled
// cube (symmetry), every spring strained alike, and the radial forces on a corner sum to 8 k
// times its radial displacement (edges sqrt3 k e a, face diagonals 2 sqrt3 k e a, the body
// diagonal sqrt3 k e a, against a displacement sqrt3 e a / 2). So it is an oscillator of
// stiffness 8 k and damping 8 c per corner: period 2 pi sqrt(m / 8 k), peaks decaying at 4 c / m.
TEST_P(SpringBodyJoints, SoftJellyCubeBreathesAtTheClosedForm) {
  const float m = 0.125f, k = 10;
  const double omega = std::sqrt(8 * k / m);  // 25.3 rad/s
  for (const float c : {0.0f, 0.02f}) {
    SpringBodyBuilder b;
    b.jellyCube(Vec3f::Zero(), 0.5f, 1 / m, k, c);
    World world(WorldSettings{1.0f / 1200, 1, 0});
    const Handle h = world.addCloth(b.build(noGravity(ClothModel::kMassSpring, 1)));
    for (std::uint32_t i = 0; i < 8; ++i) world.cloth(h).setPosition(i, 0.9f * b.positions()[i]);
    std::vector<double> signal{breathing(world.cloth(h))};
    for (int s = 0; s < 2400; ++s) {  // 2 s, 8 periods
      world.step();
      signal.push_back(breathing(world.cloth(h)));
    }
    const double dt = 1.0 / 1200;
    if (c == 0) {
      // Semi-implicit Euler's period, 2 pi h / (2 asin(omega h / 2)), is short by
      // (omega h)^2 / 24 = 1.9e-5 relative (h = 1/1200 s); the interpolated crossings add a few
      // 1e-6. Tolerance: 1e-4, five times the first.
      EXPECT_NEAR(period(signal, dt) / (2 * std::numbers::pi / omega), 1.0, 1e-4);
      continue;
    }
    // Decay of the peaks of |signal| over 1.9 s (a factor 3.3): 4 c / m = 0.64 /s. The integrator's
    // damping is first order in the step, off by about the decay in a step, 4 c h / m = 5e-4 of
    // the rate; the peaks sampled every step are low by up to (omega h)^2 / 2 = 2.2e-4 of their
    // height, 2e-4 of the log of their ratio. Tolerance: 3e-3 of the rate, four times the sum.
    std::vector<std::pair<double, double>> peaks;
    for (std::size_t i = 1; i + 1 < signal.size(); ++i)
      if (std::abs(signal[i]) > std::abs(signal[i - 1]) &&
          std::abs(signal[i]) >= std::abs(signal[i + 1]))
        peaks.push_back({dt * double(i), std::abs(signal[i])});
    ASSERT_GE(peaks.size(), 10u);
    const auto& [t0, a0] = peaks[1];
    const auto& [t1, a1] = peaks.back();
    EXPECT_NEAR(std::log(a0 / a1) / (t1 - t0), 4 * c / m, 3e-3 * 4 * c / m);
  }
}

// A jelly cube dropped tilted onto the plane y = 0 tumbles onto a face and comes to rest there,
// never below the plane's margin: stiff (XPBD, kRigid) and soft (mass-spring, damped).
TEST_P(SpringBodyJoints, JellyCubeComesToRestOnAPlane) {
  for (const ClothModel model : {ClothModel::kXpbd, ClothModel::kMassSpring}) {
    SCOPED_TRACE(toString(model));
    const bool soft = model == ClothModel::kMassSpring;
    const float k = soft ? 200.0f : kRigid, m = 0.125f, edge = 0.5f;
    SpringBodyBuilder b;
    b.jellyCube(Vec3f::Zero(), edge, 1 / m, k, soft ? 1.0f : 0.0f);
    ClothSettings s;
    s.model = model;
    World world;
    world.obstacles().add(Plane{Vec3f(0, 1, 0), 0});
    const Handle h = world.addCloth(b.build(s));
    const Mat3f tilt = Eigen::AngleAxisf(0.35f, Vec3f(0, 0, 1)).toRotationMatrix();
    for (std::uint32_t i = 0; i < 8; ++i)
      world.cloth(h).setPosition(i, tilt * b.positions()[i] + Vec3f(0, 1, 0));
    float lowest = HUGE_VALF;
    for (int f = 0; f < 180; ++f) {  // 3 s
      world.step();
      for (const Vec3f& p : world.cloth(h).positions()) lowest = std::min(lowest, p.y());
    }
    // The obstacles are met last in each substep: every particle is kept at the margin (0.01)
    // or above, to the rounding of y = 0.01 (1e-9); 1e-7 allowed.
    EXPECT_GE(lowest, s.margin - 1e-7f);
    // At rest: every speed below 1 cm/s (gravity alone adds 1.6 cm/s a substep, so a resting
    // particle is one the plane stops every substep).
    const Cloth& c = world.cloth(h);
    for (std::uint32_t i = 0; i < 8; ++i) EXPECT_LT(c.velocity(i).norm(), 0.01f) << i;
    // On a face: four corners at the margin (to 1e-6: the projection's rounding) and four one
    // edge above, less the sag. Rigid: the springs hold to XPBD's residual, about the drop
    // gravity adds in a substep to each of the two layers, 2 g h^2 = 5.5e-5 m (h = 1/600 s);
    // 1e-4 allowed. Soft: each of the top four (weight m g = 1.2 N) stands on its vertical edge,
    // two face diagonals and a body diagonal, of vertical stiffness k (1 + 2 / 2 + 1 / 3) =
    // 2.33 k: a sag of m g / 2.33 k = 2.6 mm if the bottom face kept its shape, a little more as
    // it spreads on the plane (friction 0.3). 2 to 5 mm allowed.
    std::vector<float> y;
    for (const Vec3f& p : c.positions()) y.push_back(p.y());
    std::sort(y.begin(), y.end());
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(y[i], s.margin, 1e-6f) << i;
    for (int i = 4; i < 8; ++i) {
      const float sag = s.margin + edge - y[i];
      if (soft) {
        EXPECT_GT(sag, 2e-3f) << i;
        EXPECT_LT(sag, 5e-3f) << i;
      } else {
        EXPECT_NEAR(sag, 0, 1e-4f) << i;
      }
    }
    // Rigid: every spring at its rest length to the same residual, 1e-4 m of 0.5 m.
    if (!soft) {
      EXPECT_LT(worstStretch(b.springs(), c.positions()), 2e-4);
    }
  }
}

// A rigid cube (kRigid, XPBD) thrown spinning in free fall keeps its shape, and its centre flies
// as a free particle does: the springs are internal forces.
TEST_P(SpringBodyJoints, RigidCubeThrownSpinningKeepsItsShape) {
  SpringBodyBuilder b;
  b.jellyCube(Vec3f(0, 2, 0), 0.5f, 8, kRigid);
  ClothSettings s;
  s.tethers = false;
  World world;
  const Handle h = world.addCloth(b.build(s));
  const Vec3f v0(1, 2, 0), spin(2, 5, 1);  // m/s, rad/s
  for (std::uint32_t i = 0; i < 8; ++i)
    world.cloth(h).setVelocity(i, v0 + spin.cross(b.positions()[i] - Vec3f(0, 2, 0)));
  double worst = 0;
  for (int f = 0; f < 60; ++f) {  // 1 s, 0.9 turns
    world.step();
    worst = std::max(worst, worstStretch(b.springs(), world.cloth(h).positions()));
  }
  // Each substep's prediction moves a corner (r = 0.43 m) along its tangent, stretching its
  // springs by up to (|spin| h)^2 / 2 = 4e-5 relative (h = 1/600 s); the pass over the springs
  // takes out all but some 1e-6. Allowed: 1e-5, a quarter of what the pass has to remove.
  EXPECT_LT(worst, 1e-5);
  // The centre: x0 + v0 t + g h^2 n (n + 1) / 2 after n = 600 substeps of h = 1/600 s
  // (semi-implicit Euler's free fall), to rounding: each substep's change of velocity, what moved
  // x off its prediction over h, carries x's rounding, 1.2e-7 m near 2 m, over h: 7e-5 m/s at
  // random, which adds up over the n substeps to some 7e-5 h sqrt(n^3 / 3) = 1e-3 m at a
  // particle, 3.5e-4 m at the mean of 8. 1e-3 allowed.
  const Vec3f expected = Vec3f(0, 2, 0) + v0 + 0.5f * (601.0f / 600) * s.gravity;
  EXPECT_LT((centroid(world.cloth(h).positions(), 0, 8) - expected).norm(), 1e-3f);
}

// A rigid cube of edge 0.5 hung by its corner 0 from a pinned particle by a ball joint, or by its
// edge 0-4 from two pinned particles by a hinge (along z). Pushed along z at its far corners
// (x = 0.5), it swings under gravity.
struct HungCube {
  SpringBodyBuilder b;
  World world;
  Handle h;
  std::uint32_t cube = 0;
  explicit HungCube(bool hinge) {
    const std::uint32_t pin0 = b.addParticle(Vec3f(0, 1, 0), 0);
    const std::uint32_t pin1 = b.addParticle(Vec3f(0, 1, 0.5f), 0);
    cube = b.jellyCube(Vec3f(0.25f, 1.25f, 0.25f), 0.5f, 8, kRigid);  // corner 0 at pin0
    if (hinge) {
      b.hinge(pin0, cube, pin1, cube + 4);
    } else {
      b.ballJoint(pin0, cube);
    }
    h = world.addCloth(b.build());
    for (std::uint32_t c = 0; c < 8; ++c)
      if (c & 1) world.cloth(h).setVelocity(cube + c, Vec3f(0, 0, 1));
  }
  const Cloth& cloth() const { return world.cloth(h); }
};

TEST_P(SpringBodyJoints, BallJointHoldsTheParticlesTogetherAndTurnsFreely) {
  HungCube hung(false);
  const std::uint32_t corner = hung.cube;
  double apart = 0, stretch = 0, zMoved = 0;
  for (int f = 0; f < 60; ++f) {  // 1 s
    hung.world.step();
    const std::vector<Vec3f> x = hung.cloth().positions();
    apart = std::max(apart, double((x[corner] - x[0]).norm()));
    stretch = std::max(stretch, worstStretch(hung.b.springs(), x));
    for (std::uint32_t i = 0; i < 10; ++i)
      zMoved = std::max(zMoved, double(std::abs(x[i].z() - hung.b.positions()[i].z())));
  }
  // The joint's residual after each substep's pass: the corner is pulled by gravity and the
  // swing, some g h^2 + v^2 h^2 / r = 1e-4 m a substep (v about 3 m/s, r 0.7 m, h = 1/600 s),
  // mostly removed by the pass. Allowed: 1 mm, on a 0.5 m cube.
  EXPECT_LT(apart, 1e-3);
  EXPECT_LT(stretch, 2e-3);
  // Free to turn about the pivot: the push along z turns the cube out of its plane by tens of
  // cm (a hinge holds it within 1 mm: below).
  EXPECT_GT(zMoved, 0.1);
}

// A soft ball joint holds a hanging particle (1 kg) below its pin by its weight over the
// stiffness, m g / k = 0.0982 m, once damped to rest, in either model.
TEST_P(SpringBodyJoints, SoftBallJointSagsByWeightOverStiffness) {
  for (const ClothModel model : {ClothModel::kXpbd, ClothModel::kMassSpring}) {
    SCOPED_TRACE(toString(model));
    SpringBodyBuilder b;
    const std::uint32_t pin = b.addParticle(Vec3f(0, 1, 0), 0);
    b.ballJoint(pin, b.addParticle(Vec3f(0, 1, 0), 1), 100, 5);
    ClothSettings s;
    s.model = model;
    s.tethers = false;  // a tether would hold the particle within the joint's rest length, 0
    World world;
    const Handle h = world.addCloth(b.build(s));
    for (int f = 0; f < 180; ++f) world.step();  // 3 s
    // Damping ratio c / 2 sqrt(k m) = 0.25: after 3 s the swing about the rest point has decayed
    // as exp(-c t / 2m) = 5.5e-4 of the 0.098 m sag, 5e-5 m; XPBD's own numerical damping only
    // adds to that. The static point is exact in both models (a linear spring's equilibrium).
    // Tolerance: 2e-4 m.
    const Vec3f x = world.cloth(h).position(1);
    EXPECT_NEAR(x.y(), 1 - 9.82 / 100, 2e-4);
    EXPECT_EQ(x.x(), 0.0f);
    EXPECT_EQ(x.z(), 0.0f);
  }
}

TEST_P(SpringBodyJoints, HingeTurnsOnlyAboutItsAxis) {
  HungCube hung(true);
  const std::vector<Vec3f> x0(hung.b.positions().begin(), hung.b.positions().end());
  // Distance to the hinge axis, the line x = 0, y = 1 along z.
  const auto axisDistance = [](const Vec3f& p) { return std::hypot(p.x(), p.y() - 1); };
  double apart = 0, offAxis = 0, zMoved = 0, lowest = HUGE_VAL;
  for (int f = 0; f < 60; ++f) {  // 1 s
    hung.world.step();
    const std::vector<Vec3f> x = hung.cloth().positions();
    apart = std::max(
        apart, double(std::max((x[hung.cube] - x[0]).norm(), (x[hung.cube + 4] - x[1]).norm())));
    for (std::uint32_t i = 0; i < 10; ++i) {
      offAxis = std::max(offAxis, double(std::abs(axisDistance(x[i]) - axisDistance(x0[i]))));
      zMoved = std::max(zMoved, double(std::abs(x[i].z() - x0[i].z())));
    }
    lowest = std::min(lowest, double(centroid(x, hung.cube, 8).y()));
  }
  // It swings: the centre, 0.35 m from the axis at 45 degrees above it, passes below it (1 - 0.3).
  EXPECT_LT(lowest, 0.7);
  // The pivots hold to the joint's residual, as the ball joint's: 1 mm. Every particle keeps its
  // distance to the axis and its place along it (the push along z is taken up by the pivots
  // within a substep, z moving some v h = 1.7 mm before the pass): 2 mm allowed.
  EXPECT_LT(apart, 1e-3);
  EXPECT_LT(offAxis, 2e-3);
  EXPECT_LT(zMoved, 2e-3);
}

TEST_P(SpringBodyJoints, ChainHangsAtItsLength) {
  // 20 rigid links of 0.1 m hung from a pin, released 0.1 rad off the vertical: it swings.
  SpringBodyBuilder b;
  const std::uint32_t first = b.chain(Vec3f(0, 3, 0), Vec3f(0.2f, 1, 0), 20, 1);
  b.setInvMass(first, 0);
  World world;
  const Handle h = world.addCloth(b.build());
  float leftmost = HUGE_VALF;
  double worst = 0;
  for (int f = 0; f < 120; ++f) {  // 2 s
    world.step();
    const std::vector<Vec3f> x = world.cloth(h).positions();
    leftmost = std::min(leftmost, x[first + 20].x());
    worst = std::max(worst, worstStretch(b.springs(), x));
  }
  EXPECT_EQ(world.cloth(h).position(first), Vec3f(0, 3, 0));
  // It swung through the vertical to the other side.
  EXPECT_LT(leftmost, -0.1f);
  // The top link carries the 20 particles below it; one pass of the springs a substep leaves
  // about the drop gravity adds in a substep at each, 20 g h^2 = 5.5e-4 m (h = 1/600 s): 0.55%
  // of a link at the defaults. 1% allowed, in every frame.
  EXPECT_LT(worst, 0.01);
}

// A soft distance joint from a pin to a particle of mass 1 kg: a spring of k = 100 N/m, period
// 2 pi sqrt(m / k) = 0.63 s, in either model.
TEST_P(SpringBodyJoints, SoftDistanceJointIsASpring) {
  for (const ClothModel model : {ClothModel::kXpbd, ClothModel::kMassSpring}) {
    SCOPED_TRACE(toString(model));
    SpringBodyBuilder b;
    const std::uint32_t pin = b.addParticle(Vec3f::Zero(), 0);
    b.distanceJoint(pin, b.addParticle(Vec3f(1, 0, 0), 1), 100);
    World world;
    const Handle h = world.addCloth(b.build(noGravity(model, 10)));
    world.cloth(h).setPosition(1, Vec3f(1.1f, 0, 0));
    std::vector<double> x{0.1};
    for (int f = 0; f < 300; ++f) {  // 5 s, 8 periods
      world.step();
      x.push_back(world.cloth(h).position(1).x() - 1.0);
    }
    // Per substep (h = 1/600 s): semi-implicit Euler's period is short by (omega h)^2 / 24 =
    // 1.2e-5; XPBD on a single distance constraint is implicit Euler (the projection solves
    // m (x' - x~) / h^2 = -k C(x') exactly), long by (omega h)^2 / 3 = 9e-5. The crossings are
    // interpolated over frames of 1/60 s, a sixth of a radian of the swing: the sine's curvature
    // moves each alike, by the same amount at the first and last. Tolerance: 5e-4, five times
    // XPBD's.
    EXPECT_NEAR(period(x, 1.0 / 60) / (2 * std::numbers::pi / 10), 1.0, 5e-4);
  }
}

SIMDPHYS_ON_EVERY_PATH(SpringBodyJoints);

TEST(SpringBodies, BadInputIsRefusedWithAClearErrorAndTheBuilderUnchanged) {
  SpringBodyBuilder b;
  b.addParticle(Vec3f::Zero(), 1);
  b.addParticle(Vec3f(1, 0, 0), 1);
  b.addSpring(0, 1);
  const auto unchanged = [&] {
    EXPECT_EQ(b.size(), 2u);
    EXPECT_EQ(b.springs().size(), 1u);
    EXPECT_EQ(b.invMasses()[1], 1.0f);
  };
  expectError([&] { b.addParticle(Vec3f(NAN, 0, 0), 1); },
              "SpringBodyBuilder::addParticle: position.x is nan");
  expectError([&] { b.addParticle(Vec3f::Zero(), -1); },
              "SpringBodyBuilder::addParticle: invMass is -1, must be >= 0");
  expectError([&] { b.setInvMass(2, 0); },
              "SpringBodyBuilder::setInvMass: particle is 2, is not a particle index");
  expectError([&] { b.setInvMass(1, NAN); }, "SpringBodyBuilder::setInvMass: invMass is nan");
  expectError([&] { b.addSpring(0, 2); },
              "SpringBodyBuilder::addSpring: b is 2, is not a particle index");
  expectError([&] { b.addSpring(1, 1); },
              "SpringBodyBuilder::addSpring: b is 1, joins the particle to itself");
  expectError([&] { b.addSpring(0, 1, -5); },
              "SpringBodyBuilder::addSpring: stiffness is -5, must be > 0");
  expectError([&] { b.addSpring(0, 1, 0); }, "SpringBodyBuilder::addSpring: stiffness is 0");
  expectError([&] { b.addSpring(0, 1, NAN); }, "SpringBodyBuilder::addSpring: stiffness is nan");
  expectError([&] { b.addSpring(0, 1, 10, -1); },
              "SpringBodyBuilder::addSpring: damping is -1, must be >= 0");
  expectError([&] { b.distanceJoint(7, 1); },
              "SpringBodyBuilder::distanceJoint: a is 7, is not a particle index");
  expectError([&] { b.distanceJoint(0, 1, 10, NAN); },
              "SpringBodyBuilder::distanceJoint: damping is nan");
  expectError([&] { b.ballJoint(0, 0); },
              "SpringBodyBuilder::ballJoint: b is 0, joins the particle to itself");
  expectError([&] { b.hinge(0, 1, 0, 5); },
              "SpringBodyBuilder::hinge: b1 is 5, is not a particle index");
  expectError([&] { b.ballJoint(0, 1, -1); },
              "SpringBodyBuilder::ballJoint: stiffness is -1, must be > 0");
  expectError([&] { b.hinge(1, 0, 0, 1, 10, NAN); }, "SpringBodyBuilder::hinge: damping is nan");
  expectError([&] { b.hinge(0, 1, 0, 1); },
              "SpringBodyBuilder::hinge: a1 is 0, is a0: a hinge needs two pivots");
  expectError([&] { b.chain(Vec3f::Zero(), Vec3f(1, 0, 0), 0, 1); },
              "SpringBodyBuilder::chain: links is 0, must be >= 1");
  expectError([&] { b.chain(Vec3f::Zero(), Vec3f(0, INFINITY, 0), 3, 1); },
              "SpringBodyBuilder::chain: end.y is inf, not finite");
  expectError([&] { b.chain(Vec3f::Zero(), Vec3f(1, 0, 0), 3, -2); },
              "SpringBodyBuilder::chain: invMassPerParticle is -2");
  expectError([&] { b.jellyCube(Vec3f::Zero(), 0, 1); },
              "SpringBodyBuilder::jellyCube: edge is 0, must be > 0");
  expectError([&] { b.jellyCube(Vec3f::Zero(), -1, 1); },
              "SpringBodyBuilder::jellyCube: edge is -1");
  expectError([&] { b.jellyCube(Vec3f(9e17f, 0, 0), 4e17f, 1); },
              "SpringBodyBuilder::jellyCube: centre +- edge / 2 reaches");
  expectError([&] { b.jellyCube(Vec3f::Zero(), 1, 1, 10, -3); },
              "SpringBodyBuilder::jellyCube: damping is -3");
  unchanged();
  // Springs longer than the supported range of coordinates.
  SpringBodyBuilder far;
  far.addParticle(Vec3f(-9e17f, 0, 0), 1);
  far.addParticle(Vec3f(9e17f, 0, 0), 1);
  expectError([&] { far.addSpring(0, 1); },
              "SpringBodyBuilder::addSpring: the distance from a to b is 1.8e+18, outside");
  expectError([&] { far.chain(Vec3f(-9e17f, 0, 0), Vec3f(9e17f, 0, 0), 1, 1); },
              "SpringBodyBuilder::chain: the length of a link is 1.8e+18, outside");
  expectError([&] { far.jellyCube(Vec3f::Zero(), 8e17f, 1); },
              "SpringBodyBuilder::jellyCube: the body diagonal edge sqrt(3) is 1.38");
  EXPECT_EQ(far.size(), 2u);
  EXPECT_TRUE(far.springs().empty());
  // The settings are checked by the Cloth built.
  ClothSettings s;
  s.substeps = 0;
  expectError([&] { b.build(s); }, "substeps is 0");
  unchanged();
}

}  // namespace
}  // namespace simdphys

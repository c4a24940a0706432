// Tests of include/simdphys/rigid/manifold.hpp: the contact manifolds of sphere-sphere,
// sphere-box, box-box, sphere-plane and box-plane.
//
// Expected values come from closed forms worked out below by hand, and for random box pairs from
// the oracles of tests/gjk_oracles.hpp in double: the 15-axis separating-axis test (satOracle),
// EPA's penetration depth and normal and GJK's distance, never from the code under test. Every
// manifold is also checked point by point (surfaceErrors): A's surface point (point -
// separation / 2 * normal) lies on A's boundary, B's (point + separation / 2 * normal) on B's,
// and each lies in the other shape grown by |separation|.
//
// Tolerances. Closed-form cases use coordinates of a few units (L <= 4) and answers that are a
// handful of products and sums of them: 16 eps * L (eps of the scalar under test) allows for
// about 16 roundings of a magnitude-L value, a few times what the formulas take. Random box
// pairs (double) span coordinates up to L = 8; their tolerances are stated at each assertion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "gjk_oracles.hpp"
#include "simdphys/rigid/manifold.hpp"

namespace simdphys {
namespace {

using namespace test;

template <class T>
class Manifolds : public ::testing::Test {};
TYPED_TEST_SUITE(Manifolds, Scalars, ScalarName);

// ---- helpers, in double ----------------------------------------------------------------------

template <class T>
Manifoldd inDouble(const ManifoldT<T>& m) {
  Manifoldd r;
  r.normal = m.normal.template cast<double>();
  r.count = m.count;
  for (std::size_t i = 0; i < m.points.size(); ++i)
    r.points[i] = {m.points[i].point.template cast<double>(), double(m.points[i].separation),
                   m.points[i].id};
  return r;
}

template <class T>
ObbT<T> box(const Vec3d& centre, const Vec3d& half, const Mat3d& axes = Mat3d::Identity()) {
  return {centre.cast<T>(), half.cast<T>(), axes.cast<T>()};
}
Obbd seenBox(const Obb& b) {  // a float box as double, exactly (see seenVec)
  Obbd r{seenVec(b.center), seenVec(b.halfExtents), Mat3d()};
  for (int k = 0; k < 3; ++k) r.axes.col(k) = seenVec(Vec3f(b.axes.col(k)));
  return r;
}

Mat3d about(const Vec3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// Distance from p to the boundary of a box (inside or out).
double boundaryDistance(const Obbd& b, const Vec3d& p) {
  const Vec3d excess = (b.axes.transpose() * (p - b.center)).cwiseAbs() - b.halfExtents;
  return excess.maxCoeff() > 0 ? excess.cwiseMax(0.0).norm() : -excess.maxCoeff();
}
double boundaryDistance(const Sphered& s, const Vec3d& p) {
  return std::abs((p - s.center).norm() - s.radius);
}
double boundaryDistance(const Planed& q, const Vec3d& p) { return std::abs(q.signedDistance(p)); }
double distanceInto(const Planed& q, const Vec3d& p) {  // to the solid behind the plane
  return std::max(0.0, q.signedDistance(p));
}
template <class S>
double distanceInto(const S& s, const Vec3d& p) {
  return distanceTo(s, p);
}

// The largest error of a manifold's points against the header's conventions: A's and B's surface
// points on their boundaries, each within |separation| of the other shape; also fails on a
// non-unit normal, a separation beyond maxSeparation or a repeated id.
template <class A, class B>
::testing::AssertionResult surfaceErrors(const Manifoldd& m, const A& a, const B& b,
                                         double maxSeparation, double tol) {
  if (std::abs(m.normal.norm() - 1) > tol)
    return ::testing::AssertionFailure() << "normal not unit: " << m.normal.transpose();
  std::set<std::uint32_t> ids;
  for (int i = 0; i < m.count; ++i) {
    const ContactPointT<double>& c = m.points[std::size_t(i)];
    const Vec3d onA = c.point - c.separation / 2 * m.normal;
    const Vec3d onB = c.point + c.separation / 2 * m.normal;
    const double errors[] = {boundaryDistance(a, onA), boundaryDistance(b, onB),
                             distanceInto(b, onA) - std::abs(c.separation),
                             distanceInto(a, onB) - std::abs(c.separation)};
    for (int e = 0; e < 4; ++e)
      if (errors[e] > tol)
        return ::testing::AssertionFailure()
               << "point " << i << " (" << c.point.transpose() << ", separation " << c.separation
               << "): check " << e << " off by " << errors[e] << " > " << tol;
    if (c.separation > maxSeparation + tol)
      return ::testing::AssertionFailure() << "separation " << c.separation << " > maxSeparation";
    if (!ids.insert(c.id).second)
      return ::testing::AssertionFailure() << "id " << c.id << " repeated";
  }
  return ::testing::AssertionSuccess();
}

double deepest(const Manifoldd& m) {
  double s = INFINITY;
  for (int i = 0; i < m.count; ++i) s = std::min(s, m.points[std::size_t(i)].separation);
  return s;
}
std::multiset<std::uint32_t> idsOf(const Manifoldd& m) {
  std::multiset<std::uint32_t> r;
  for (int i = 0; i < m.count; ++i) r.insert(m.points[std::size_t(i)].id);
  return r;
}
// The largest distance from a point of m to the nearest of `expected` (inf if m has none).
double farthestFrom(const Manifoldd& m, const std::vector<Vec3d>& expected) {
  double worst = m.count ? 0 : INFINITY;
  for (int i = 0; i < m.count; ++i) {
    double nearest = INFINITY;
    for (const Vec3d& e : expected)
      nearest = std::min(nearest, (m.points[std::size_t(i)].point - e).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

// ---- spheres and planes: closed forms -------------------------------------------------------

TYPED_TEST(Manifolds, SphereSphereClosedForm) {
  using T = TypeParam;
  const double L = 8, tol = 16 * kEps<T> * L;
  const SphereT<T> a{v3<T>(1, 2, 3), T(1)};
  // Centres 5 apart along (0.6, 0.8, 0): separation 5 - 1 - 0.5 = 3.5, point 1 + 1.75 along it.
  const SphereT<T> far{v3<T>(4, 6, 3), T(0.5)};
  Manifoldd m = inDouble(collide(a, far, T(4)));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0.6, 0.8, 0), tol));
  EXPECT_TRUE(closeTo(m.points[0].separation, 3.5, tol));
  EXPECT_TRUE(closeTo(m.points[0].point, Vec3d(1 + 2.75 * 0.6, 2 + 2.75 * 0.8, 3), tol));
  EXPECT_TRUE(surfaceErrors(m, seen(a), seen(far), 4, tol));
  EXPECT_EQ(collide(a, far, T(3)).count, 0);  // 3.5 > maxSeparation
  // Radius 4.5: overlapping by 0.5; the point is 0.25 inside A's surface point, towards B.
  const SphereT<T> near{v3<T>(4, 6, 3), T(4.5)};
  m = inDouble(collide(a, near, T(0)));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.points[0].separation, -0.5, tol));
  EXPECT_TRUE(closeTo(m.points[0].point, Vec3d(1 + 0.75 * 0.6, 2 + 0.75 * 0.8, 3), tol));
  EXPECT_TRUE(surfaceErrors(m, seen(a), seen(near), 0, tol));
  // Concentric: any unit normal, separation -(1 + 2).
  m = inDouble(collide(a, SphereT<T>{a.center, T(2)}, T(0)));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal.norm(), 1.0, tol));
  EXPECT_TRUE(closeTo(m.points[0].separation, -3.0, tol));
}

TYPED_TEST(Manifolds, SphereBoxClosedForm) {
  using T = TypeParam;
  const double L = 8, tol = 16 * kEps<T> * L;
  // A box turned a quarter about z (local x is world y), half extents (1, 2, 3).
  const Mat3d R = about(Vec3d::UnitZ(), std::numbers::pi / 2);
  const Obbd bd{Vec3d(1, 1, 1), Vec3d(1, 2, 3), R};
  const ObbT<T> b = box<T>(bd.center, bd.halfExtents, R);
  const auto world = [&](double x, double y, double z) -> Vec3d {
    return bd.center + R * Vec3d(x, y, z);
  };
  struct Case {
    Vec3d local;
    double radius, separation;
    Vec3d normalLocal;  // from the sphere to the box, in the box's frame
  };
  const double third = 1.0 / 3;
  const Case cases[] = {
      {{1.5, 0, 0}, 1, 0.5 - 1, {-1, 0, 0}},                        // face region: 0.5 from +x
      {{1.3, 2.4, 0}, 0.25, 0.5 - 0.25, {-0.6, -0.8, 0}},           // edge region: (0.3, 0.4) out
      {{2, 4, 5}, 0.5, 3 - 0.5, {-third, -2 * third, -2 * third}},  // corner: (1, 2, 2) out
      {{0.8, 0, 0}, 0.5, -0.2 - 0.5, {-1, 0, 0}},                   // inside: 0.2 from +x
      {{-0.8, 0, 0}, 0.5, -0.2 - 0.5, {1, 0, 0}},                   // inside: 0.2 from -x
      {{0, -1.5, 2}, 0.5, -0.5 - 0.5, {0, 1, 0}},                   // inside: 0.5 from -y
  };
  std::set<std::uint32_t> ids;
  for (const Case& c : cases) {
    const Sphered sd{world(c.local.x(), c.local.y(), c.local.z()), c.radius};
    const Manifoldd m = inDouble(collide(inScalar<T>(sd), b, T(4)));
    ASSERT_EQ(m.count, 1) << c.local.transpose();
    EXPECT_TRUE(closeTo(m.normal, R * c.normalLocal, tol)) << c.local.transpose();
    EXPECT_TRUE(closeTo(m.points[0].separation, c.separation, tol)) << c.local.transpose();
    EXPECT_TRUE(surfaceErrors(m, sd, bd, 4, tol)) << c.local.transpose();
    ids.insert(m.points[0].id);
  }
  // Each case is a different feature of the box (face, edge, corner, inside through +x, -x, -y).
  EXPECT_EQ(ids.size(), std::size(cases));
  EXPECT_EQ(collide(SphereT<T>{v3<T>(1, 1, 7), T(0.5)}, b, T(2)).count, 0);  // 3 - 0.5 > 2
}

TYPED_TEST(Manifolds, SpherePlaneClosedForm) {
  using T = TypeParam;
  const double L = 8, tol = 16 * kEps<T> * L;
  const Planed qd{Vec3d(0, 0.6, 0.8), -1};  // 0.6 y + 0.8 z = 1
  const PlaneT<T> q = cast<T>(qd);
  // Centre (1, 2, 3): signed distance 1.2 + 2.4 - 1 = 2.6.
  for (const double radius : {0.5, 3.0}) {
    const Sphered sd{Vec3d(1, 2, 3), radius};
    const Manifoldd m = inDouble(collide(inScalar<T>(sd), q, T(3)));
    ASSERT_EQ(m.count, 1);
    EXPECT_TRUE(closeTo(m.normal, Vec3d(0, -0.6, -0.8), tol));
    EXPECT_TRUE(closeTo(m.points[0].separation, 2.6 - radius, tol));
    // Midway between the sphere's lowest point and the plane.
    EXPECT_TRUE(closeTo(m.points[0].point,
                        Vec3d(1, 2, 3) - (radius + (2.6 - radius) / 2) * qd.normal, tol));
    EXPECT_TRUE(surfaceErrors(m, sd, qd, 3, tol));
  }
  EXPECT_EQ(collide(SphereT<T>{v3<T>(1, 2, 3), T(0.5)}, q, T(2)).count, 0);  // 2.1 > 2
}

TYPED_TEST(Manifolds, BoxPlaneClosedForm) {
  using T = TypeParam;
  const double L = 8, tol = 16 * kEps<T> * L;
  const Planed ground{Vec3d::UnitY(), 0};
  // A box turned 30 degrees about y, sunk 1/64 into the ground: its 4 bottom corners.
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Obbd bd{Vec3d(1, 0.25 - 1.0 / 64, 2), Vec3d(0.5, 0.25, 1),
                about(Vec3d::UnitY(), std::numbers::pi / 6)};
  Manifoldd m =
      inDouble(collide(box<T>(bd.center, bd.halfExtents, bd.axes), cast<T>(ground), T(0.1)));
  ASSERT_EQ(m.count, 4);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0, -1, 0), tol));
  std::vector<Vec3d> corners;  // local (+-0.5, +-1) in x, z turned by 30 degrees about y
  for (const double x : {-0.5, 0.5})
    for (const double z : {-1.0, 1.0})
      corners.push_back(Vec3d(1 + c * x + s * z, -1.0 / 128, 2 - s * x + c * z));
  EXPECT_LE(farthestFrom(m, corners), tol);
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(closeTo(m.points[std::size_t(i)].separation, -1.0 / 64, tol));
  EXPECT_TRUE(surfaceErrors(m, bd, ground, 0.1, tol));
  EXPECT_EQ(idsOf(m).size(), 4u);
  // On an edge (turned 45 degrees about z), 1/64 deep: the two lowest corners.
  const Obbd edge{Vec3d(0, std::sqrt(0.5) - 1.0 / 64, 0), Vec3d(0.5, 0.5, 0.5),
                  about(Vec3d::UnitZ(), std::numbers::pi / 4)};
  m = inDouble(collide(box<T>(edge.center, edge.halfExtents, edge.axes), cast<T>(ground), T(0.1)));
  ASSERT_EQ(m.count, 2);
  EXPECT_LE(farthestFrom(m, {Vec3d(0, -1.0 / 128, -0.5), Vec3d(0, -1.0 / 128, 0.5)}), tol);
  EXPECT_TRUE(surfaceErrors(m, edge, ground, 0.1, tol));
  // Lifted 1/4 above the ground: nothing within 1/8, all four bottom corners within 1/2.
  const ObbT<T> lifted = box<T>(Vec3d(0, 0.75, 0), Vec3d(0.5, 0.5, 0.5));
  EXPECT_EQ(collide(lifted, cast<T>(ground), T(0.125)).count, 0);
  m = inDouble(collide(lifted, cast<T>(ground), T(0.5)));
  ASSERT_EQ(m.count, 4);
  EXPECT_TRUE(closeTo(deepest(m), 0.25, tol));
}

// ---- box-box: closed forms ------------------------------------------------------------------

// A unit box (B) resting 1/64 deep on a corner of a larger one (A): exactly the 4 corners of the
// overlap rectangle, x in [1.25, 2], z in [-1.5, -0.75], midway between A's top (y = 0.5) and B's
// bottom (0.5 - 1/64); seen from B, the same points with the normal reversed.
TYPED_TEST(Manifolds, BoxRestingFlatOnBox) {
  using T = TypeParam;
  const double L = 4, tol = 16 * kEps<T> * L;
  const Obbd ad{Vec3d::Zero(), Vec3d(2, 0.5, 1.5)};
  const Obbd bd{Vec3d(1.75, 1 - 1.0 / 64, -1.25), Vec3d(0.5, 0.5, 0.5)};
  const ObbT<T> a = box<T>(ad.center, ad.halfExtents), b = box<T>(bd.center, bd.halfExtents);
  std::vector<Vec3d> expected;
  for (const double x : {1.25, 2.0})
    for (const double z : {-1.5, -0.75}) expected.push_back(Vec3d(x, 0.5 - 1.0 / 128, z));
  for (const bool swap : {false, true}) {
    const Manifoldd m = inDouble(swap ? collide(b, a, T(0.01)) : collide(a, b, T(0.01)));
    ASSERT_EQ(m.count, 4) << swap;
    EXPECT_TRUE(closeTo(m.normal, Vec3d(0, swap ? -1 : 1, 0), tol)) << swap;
    EXPECT_LE(farthestFrom(m, expected), tol) << swap;
    for (int i = 0; i < 4; ++i)
      EXPECT_TRUE(closeTo(m.points[std::size_t(i)].separation, -1.0 / 64, tol)) << swap;
    EXPECT_TRUE(swap ? surfaceErrors(m, bd, ad, 0.01, tol) : surfaceErrors(m, ad, bd, 0.01, tol));
    EXPECT_EQ(idsOf(m).size(), 4u);
  }
}

// Lifted by a gap: no points beyond maxSeparation, the 4 speculative ones within it.
TYPED_TEST(Manifolds, BoxAboveBoxSpeculative) {
  using T = TypeParam;
  const double L = 4, tol = 16 * kEps<T> * L;
  const ObbT<T> a = box<T>(Vec3d::Zero(), Vec3d(1, 0.5, 1));
  const ObbT<T> b = box<T>(Vec3d(0.25, 1.25, 0), Vec3d(0.5, 0.5, 0.5));  // gap 0.25
  EXPECT_EQ(collide(a, b, T(0.2)).count, 0);
  EXPECT_EQ(collide(b, a, T(0.2)).count, 0);
  const Manifoldd m = inDouble(collide(a, b, T(0.3)));
  ASSERT_EQ(m.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(closeTo(m.points[std::size_t(i)].separation, 0.25, tol));
  EXPECT_TRUE(surfaceErrors(m, box<double>(Vec3d::Zero(), Vec3d(1, 0.5, 1)),
                            box<double>(Vec3d(0.25, 1.25, 0), Vec3d(0.5, 0.5, 0.5)), 0.3, tol));
}

// Two unit boxes, the upper (B) turned 45 degrees about y and 1/64 deep: the incident square
// clipped by the reference square is a regular octagon with vertices (+-1/2, +-(sqrt(1/2) - 1/2))
// and (+-(sqrt(1/2) - 1/2), +-1/2); four of them are kept, and the pruning's choice (deepest, the
// farthest from it, the largest triangle, the largest quadrilateral) is every other vertex, a
// square of area 2 - sqrt(2). On a larger box turned 45 degrees, a unit box's bottom face lies
// inside the top face: its own 4 corners.
TYPED_TEST(Manifolds, BoxOnBoxTurned45) {
  using T = TypeParam;
  const double L = 4, tol = 16 * kEps<T> * L;
  const double k = std::sqrt(0.5) - 0.5, y = 0.5 - 1.0 / 128;
  const Mat3d turn = about(Vec3d::UnitY(), std::numbers::pi / 4);
  const Obbd ad{Vec3d::Zero(), Vec3d(0.5, 0.5, 0.5)};
  const Obbd bd{Vec3d(0, 1 - 1.0 / 64, 0), Vec3d(0.5, 0.5, 0.5), turn};
  Manifoldd m = inDouble(
      collide(box<T>(ad.center, ad.halfExtents), box<T>(bd.center, bd.halfExtents, turn), T(0.01)));
  ASSERT_EQ(m.count, 4);
  const std::vector<Vec3d> octagon = {{0.5, y, k},   {k, y, 0.5},   {-k, y, 0.5}, {-0.5, y, k},
                                      {-0.5, y, -k}, {-k, y, -0.5}, {k, y, -0.5}, {0.5, y, -k}};
  EXPECT_LE(farthestFrom(m, octagon), tol);
  for (int i = 0; i < 4; ++i)
    EXPECT_TRUE(closeTo(m.points[std::size_t(i)].separation, -1.0 / 64, tol));
  // The area of the kept points' hull (they are vertices of a convex polygon: sort by angle).
  std::vector<Vec3d> kept;
  for (int i = 0; i < 4; ++i) kept.push_back(m.points[std::size_t(i)].point);
  std::sort(kept.begin(), kept.end(), [](const Vec3d& p, const Vec3d& q) {
    return std::atan2(p.z(), p.x()) < std::atan2(q.z(), q.x());
  });
  double area = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3d &p = kept[std::size_t(i)], &q = kept[std::size_t((i + 1) % 4)];
    area += (p.x() * q.z() - q.x() * p.z()) / 2;
  }
  EXPECT_TRUE(closeTo(std::abs(area), 2 - std::sqrt(2.0), tol));
  EXPECT_TRUE(surfaceErrors(m, ad, bd, 0.01, tol));
  EXPECT_EQ(idsOf(m).size(), 4u);

  const Obbd big{Vec3d::Zero(), Vec3d(2, 0.5, 2), turn};
  const Obbd unit{Vec3d(0.25, 1 - 1.0 / 64, 0), Vec3d(0.5, 0.5, 0.5)};
  m = inDouble(collide(box<T>(big.center, big.halfExtents, turn),
                       box<T>(unit.center, unit.halfExtents), T(0.01)));
  ASSERT_EQ(m.count, 4);
  EXPECT_LE(farthestFrom(m, {{-0.25, y, -0.5}, {-0.25, y, 0.5}, {0.75, y, -0.5}, {0.75, y, 0.5}}),
            tol);
  EXPECT_TRUE(surfaceErrors(m, big, unit, 0.01, tol));
}

// Crossed edges: A turned 45 degrees about z (top edge along z at y = sqrt(1/2)), B turned 45
// degrees about x (bottom edge along x at its centre's y - sqrt(1/2)), 1/64 deep: one point at
// (0, sqrt(1/2) - 1/128, 0), normal +y (the edge axis z x x), separation -1/64. Every face axis
// overlaps by more than 0.3, far past the faces' preference.
TYPED_TEST(Manifolds, EdgeEdgeClosedForm) {
  using T = TypeParam;
  const double L = 4, tol = 16 * kEps<T> * L;
  const Obbd ad{Vec3d::Zero(), Vec3d(0.5, 0.5, 0.5), about(Vec3d::UnitZ(), std::numbers::pi / 4)};
  const Obbd bd{Vec3d(0, std::sqrt(2.0) - 1.0 / 64, 0), Vec3d(0.5, 0.5, 0.5),
                about(Vec3d::UnitX(), std::numbers::pi / 4)};
  const ObbT<T> a = box<T>(ad.center, ad.halfExtents, ad.axes);
  const ObbT<T> b = box<T>(bd.center, bd.halfExtents, bd.axes);
  const Manifoldd m = inDouble(collide(a, b, T(0)));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0, 1, 0), tol));
  EXPECT_TRUE(closeTo(m.points[0].separation, -1.0 / 64, tol));
  EXPECT_TRUE(closeTo(m.points[0].point, Vec3d(0, std::sqrt(0.5) - 1.0 / 128, 0), tol));
  EXPECT_TRUE(surfaceErrors(m, ad, bd, 0, tol));
  const Manifoldd swapped = inDouble(collide(b, a, T(0)));  // the same contact seen from B
  ASSERT_EQ(swapped.count, 1);
  EXPECT_TRUE(closeTo(swapped.normal, Vec3d(0, -1, 0), tol));
  EXPECT_TRUE(closeTo(swapped.points[0].separation, -1.0 / 64, tol));
  EXPECT_TRUE(closeTo(swapped.points[0].point, m.points[0].point, tol));
}

// A resting box nudged (moved by up to 0.012, turned by up to 0.005 radians) keeps its contact's
// features, so the same count and ids: flat, with two corners over A's top and two clipped by its
// side z = -1.5 (no side within 0.05 of a corner), and turned, on its lowest corner.
TYPED_TEST(Manifolds, BoxBoxIdsStableUnderSmallMotion) {
  using T = TypeParam;
  const ObbT<T> a = box<T>(Vec3d::Zero(), Vec3d(2, 0.5, 1.5));
  for (const bool turned : {false, true}) {
    const Mat3d base = turned ? about(Vec3d(0.2, 1, 0.1), 0.6) : Mat3d::Identity();
    // Turned about a tilted axis the box rests on its lowest corner, 1/64 deep.
    const Vec3d centre(1.3, 0.5 - 1.0 / 64 + 0.5 * base.row(1).cwiseAbs().sum(), -1.2);
    const Manifoldd m0 =
        inDouble(collide(a, box<T>(centre, Vec3d(0.5, 0.5, 0.5), base), T(1.0 / 32)));
    ASSERT_GE(m0.count, 1) << turned;
    for (int step = 1; step <= 5; ++step) {
      const Mat3d nudge = about(Vec3d(0.3, 1, -0.2), 1e-3 * step) * base;
      const Vec3d moved = centre + 1e-3 * step * Vec3d(1, -0.5, 2);
      const Manifoldd m =
          inDouble(collide(a, box<T>(moved, Vec3d(0.5, 0.5, 0.5), nudge), T(1.0 / 32)));
      EXPECT_EQ(m.count, m0.count) << turned << " step " << step;
      EXPECT_EQ(idsOf(m), idsOf(m0)) << turned << " step " << step;
    }
  }
}

// Equal boxes stacked flush (B's bottom face exactly over A's top face, and half a box over, as
// in a pyramid, flush along z), jittered by 1e-6 (translation, and rotation in radians), far below
// the clip's snap (1e-4 of the size): still exactly B's 4 bottom corners' features, so the same
// ids, whichever way the rounding and the jitter put each corner with respect to A's sides.
TYPED_TEST(Manifolds, BoxBoxFlushStackIdsStable) {
  using T = TypeParam;
  Rng rng(99);
  const ObbT<T> a = box<T>(Vec3d::Zero(), Vec3d(0.5, 0.5, 0.5));
  for (const double shift : {0.0, 0.5}) {
    const Vec3d centre(shift, 1 - 1.0 / 64, 0);
    const Manifoldd m0 = inDouble(collide(a, box<T>(centre, Vec3d(0.5, 0.5, 0.5)), T(0.01)));
    ASSERT_EQ(m0.count, 4) << shift;
    for (int trial = 0; trial < 20; ++trial) {
      const Mat3d jitter = about(rng.dir(), 1e-6);
      const Vec3d moved = centre + 1e-6 * rng.dir();
      const Manifoldd m =
          inDouble(collide(a, box<T>(moved, Vec3d(0.5, 0.5, 0.5), jitter), T(0.01)));
      EXPECT_EQ(idsOf(m), idsOf(m0)) << shift << " trial " << trial;
    }
  }
}

// ---- box-box: random pairs against the oracles (double) ------------------------------------

// Random pairs: A anywhere in [-4, 4]^3, half extents in [0.1, 1], any rotation; B likewise,
// placed by `kind`: 0 anywhere around A (mostly edge or vertex contacts), 1 with a face parallel
// to one of A's (B turned about one of A's axes), 2 turned from A by 1e-7 to 1e-2 radians (nearly
// parallel faces and edges); then, with `gap` given, moved along the SAT oracle's axis until the
// boxes' separation is `gap` (negative: overlapping).
struct Pair {
  Obbd a, b;
  double turn = 0;  // kind 2: the angle between A's and B's frames
};
Pair randomPair(Rng& rng, int kind) {
  Pair p;
  p.a = {rng.point(-4, 4), rng.point(0.1, 1), rng.rotation()};
  const Vec3d half = rng.point(0.1, 1);
  Mat3d axes = rng.rotation();
  if (kind == 1) axes = p.a.axes * about(Vec3d::Unit(int(rng.u(0, 2.99))), rng.u(0, 6.28));
  if (kind == 2) p.turn = std::pow(10.0, rng.u(-7, -2)), axes = p.a.axes * about(rng.dir(), p.turn);
  const double reach = p.a.halfExtents.norm() + half.norm();
  p.b = {p.a.center + rng.dir() * reach * rng.u(0, 1), half, axes};
  return p;
}
void moveToSeparation(Pair& p, double gap) {
  const Sat s = satOracle(p.a, p.b);
  p.b.center += (gap - s.separation) * s.axis;
}

// The margin by which the oracle's best axis must beat the runner-up for the manifold's axis to
// be determined (the header's preference tolerances), plus 1e-9 of slack for rounding.
double smallerSize(const Obbd& a, const Obbd& b) {
  return std::min(a.halfExtents.maxCoeff(), b.halfExtents.maxCoeff());
}
double preference(const Obbd& a, const Obbd& b, double separation) {
  return kBoxAxisRelativeTolerance<double> * std::abs(separation) +
         kBoxAxisAbsoluteTolerance<double> * smallerSize(a, b) + 1e-9;
}
// The surface tolerance of random pairs in double: 1e-9 (coordinates up to L = 8: 5e5 eps * L,
// room for the clipping's divisions by the sine of an incident edge's angle to a side plane; the
// measured worst is printed) plus the clip's snap (a corner that close outside a side plane is
// kept as it is, that far off the reference face).
double surfaceTolerance(const Obbd& a, const Obbd& b) {
  return 1e-9 + kBoxClipSnap<double> * smallerSize(a, b);
}

// Overlapping pairs: deep ones (anywhere around A), face-face, nearly parallel, shallow (1e-4
// deep) and touching. Against EPA and the SAT oracle:
//  - every point passes surfaceErrors within surfaceTolerance;
//  - the deepest separation is minus the penetration depth (the SAT oracle's separation, and
//    -EPA's depth, which agree within 1e-6) within the preference margin (the manifold may take
//    an axis up to that much deeper) plus 1e-6: edge pairs within sqrt(eps) = 1.5e-8 radians of
//    parallel give no axis, which moves the depth by up to 1.5e-8 times the boxes' size (<= 3.5),
//    and EPA's own error on the nearly flat polytopes of nearly parallel boxes;
//  - where the oracle's axis beats its runner-up by more than the margin, the normal is that axis
//    and EPA's normal within 1e-6 plus twice the angle between the boxes' frames for nearly
//    parallel pairs (each of A's face normals is then within that angle of one of B's, which the
//    oracle counts as the same axis; the manifold prefers A's), and swapping A and B reverses the
//    normal and keeps the separations, within 1e-9 plus the same angle (times 8 for separations);
//    EPA's normal is a facet normal of the Minkowski difference, which for nearly parallel edges
//    is known only to about eps / sine.
TEST(ManifoldsRandom, BoxBoxOverlappingAgainstEpaAndSat) {
  Rng rng(20240601);
  Worst surface("box-box points on surfaces (overlapping)", kEps<double>);
  Worst depth("box-box deepest separation vs SAT depth, determined axis", kEps<double>);
  Worst normal("box-box normal vs EPA normal, determined axis", kEps<double>);
  int determined = 0, edges = 0, faces = 0, cases = 0;
  for (int i = 0; i < 320; ++i) {
    Pair p = randomPair(rng, i % 3);
    if (i % 4 == 1) moveToSeparation(p, -1e-4);  // shallow
    if (i % 8 == 3) moveToSeparation(p, 0);      // touching
    const Sat sat = satOracle(p.a, p.b);
    if (sat.separation > 0) continue;  // drawn apart: the speculative test's business
    ++cases;
    const Manifoldd m = collide(p.a, p.b, 1e-9);  // touching pairs' separations round to +-1e-16
    ASSERT_GE(m.count, 1) << i;
    (m.count == 1 ? edges : faces)++;
    EXPECT_TRUE(surfaceErrors(m, p.a, p.b, 1e-9, surfaceTolerance(p.a, p.b))) << i;
    for (int k = 0; k < m.count; ++k) {
      const ContactPointT<double>& c = m.points[std::size_t(k)];
      surface.add(boundaryDistance(p.b, c.point + c.separation / 2 * m.normal), 8);
    }
    const double s = deepest(m);
    EXPECT_GE(s, sat.separation - preference(p.a, p.b, sat.separation) - 1e-6) << i;
    EXPECT_LE(s, sat.separation + 1e-6) << i;
    const std::optional<Penetrationd> pen = epa(p.a, p.b);
    if (sat.separation < -1e-9) {
      ASSERT_TRUE(pen.has_value()) << i;
      EXPECT_TRUE(closeTo(-pen->depth, sat.separation, 1e-6)) << i;  // the two oracles agree
    }
    if (sat.separation - sat.runnerUp <= preference(p.a, p.b, sat.runnerUp) + 1e-6) continue;
    ++determined;
    const double angle = 2 * p.turn;
    EXPECT_TRUE(closeTo(s, sat.separation, 1e-6)) << i;
    depth.add(std::abs(s - sat.separation), 8);
    EXPECT_TRUE(closeTo(m.normal, sat.axis, 1e-6 + angle)) << i;
    if (pen && sat.separation < -1e-9) {
      EXPECT_TRUE(closeTo(m.normal, pen->normal, 1e-6 + angle)) << i;
      if (p.turn == 0) normal.add(maxDiff(m.normal, pen->normal), 1);
    }
    const Manifoldd swapped = collide(p.b, p.a, 1e-9);
    ASSERT_EQ(swapped.count, m.count) << i;
    EXPECT_TRUE(closeTo(swapped.normal, -m.normal, 1e-9 + angle)) << i;
    std::vector<double> s1, s2;
    for (int k = 0; k < m.count; ++k)
      s1.push_back(m.points[std::size_t(k)].separation),
          s2.push_back(swapped.points[std::size_t(k)].separation);
    std::sort(s1.begin(), s1.end()), std::sort(s2.begin(), s2.end());
    for (std::size_t k = 0; k < s1.size(); ++k)
      EXPECT_TRUE(closeTo(s1[k], s2[k], 1e-9 + 8 * angle)) << i;
  }
  // The draw must exercise what it claims: most pairs overlap, both contact kinds occur, and
  // most axes are determined.
  EXPECT_GE(cases, 200);
  EXPECT_GE(edges, 20);
  EXPECT_GE(faces, 60);
  EXPECT_GE(determined, cases / 2);
  std::printf("[ cases    ] %d overlapping (%d edge, %d face contacts), %d determined axes\n",
              cases, edges, faces, determined);
}

// Separated pairs, SAT separation 1e-3 to 0.2 below maxSeparation = 0.25 (speculative contacts):
// the points pass surfaceErrors within surfaceTolerance; the deepest separation is at least the
// SAT oracle's within 1e-9 (an axis's separation bounds the distance between the boxes from
// below, and a face contact's points are no nearer than their axis says); and where the closest
// points found by GJK lie along the oracle's axis (within 1e-6: vertex-face, edge-edge and
// face-face closest features, not vertex-vertex or vertex-edge, where SAT only bounds the
// distance and a manifold may miss it) and that axis is determined, the manifold is not empty and
// its deepest separation is GJK's distance within 1e-7 (GJK stops at 16 eps of the problem's
// size; 1e-7 leaves room for the direction's 1e-6 slack times the sizes).
// Moved apart beyond maxSeparation (SAT separation 0.26 to 1), the manifold is empty.
TEST(ManifoldsRandom, BoxBoxSpeculativeAgainstGjk) {
  Rng rng(777);
  int compared = 0, empty = 0;
  for (int i = 0; i < 150; ++i) {
    Pair p = randomPair(rng, i % 3);
    moveToSeparation(p, rng.u(1e-3, 0.2));
    const Sat sat = satOracle(p.a, p.b);
    const Manifoldd m = collide(p.a, p.b, 0.25);
    empty += m.count == 0;
    EXPECT_TRUE(surfaceErrors(m, p.a, p.b, 0.25, surfaceTolerance(p.a, p.b))) << i;
    if (m.count) {
      EXPECT_GE(deepest(m), sat.separation - 1e-9) << i;
    }
    const GjkResultd g = gjkDistance(p.a, p.b);
    ASSERT_FALSE(g.intersecting) << i;
    const Vec3d direction = (g.pointB - g.pointA) / g.distance;
    if (maxDiff(direction, sat.axis) < 1e-6 &&
        sat.separation - sat.runnerUp > preference(p.a, p.b, sat.runnerUp) + 1e-6) {
      ++compared;
      ASSERT_GE(m.count, 1) << i;
      EXPECT_TRUE(closeTo(deepest(m), g.distance, 1e-7)) << i;
    }
    Pair far = p;
    moveToSeparation(far, rng.u(0.26, 1));
    EXPECT_EQ(collide(far.a, far.b, 0.25).count, 0) << i;
    EXPECT_EQ(collide(far.b, far.a, 0.25).count, 0) << i;
  }
  EXPECT_GE(compared, 50);  // the filter must leave enough cases to mean something
  std::printf("[ cases    ] %d speculative pairs compared with GJK's distance, %d empty\n",
              compared, empty);
}

// Float against double on the same boxes (the float ones, seen exactly in double), where the axis
// is determined with room to spare (margin 1e-3, far above float's rounding): the same count and
// the normal and deepest separation within 2e-5, and where the ids agree (the same features) the
// points within 2e-5. Float rounds each input coordinate by up to eps/2 * L = 4.8e-7 (L = 8); the
// clipping divides by the sine of an incident edge's angle to a side plane, and the edge axis by
// the sine of the edges' angle, both usually above 0.1 in these draws: 2e-5 is about
// 20 eps * L / 0.1. Ids differ where the pruning's choices tie (equally deep points of parallel
// faces: which is deepest is rounding's choice), and at most for a fifth of the pairs here.
TEST(ManifoldsRandom, BoxBoxFloatAgreesWithDouble) {
  Rng rng(4242);
  Worst point("box-box float vs double points, same ids", kEps<float>);
  int compared = 0, idMismatches = 0;
  for (int i = 0; i < 150; ++i) {
    Pair p = randomPair(rng, i % 3);
    if (i % 2) moveToSeparation(p, rng.u(-0.05, 0.05));
    const Obb af = cast<float>(p.a), bf = cast<float>(p.b);
    const Obbd a = seenBox(af), b = seenBox(bf);
    const Sat sat = satOracle(a, b);
    if (sat.separation > 0.1 ||
        sat.separation - sat.runnerUp <= preference(a, b, sat.runnerUp) + 1e-3)
      continue;
    ++compared;
    const Manifoldd md = collide(a, b, 0.1);
    const Manifoldd mf = inDouble(collide(af, bf, 0.1f));
    ASSERT_EQ(mf.count, md.count) << i;
    EXPECT_TRUE(closeTo(mf.normal, md.normal, 2e-5)) << i;
    EXPECT_TRUE(closeTo(deepest(mf), deepest(md), 2e-5)) << i;
    if (idsOf(mf) != idsOf(md)) {
      ++idMismatches;
      continue;
    }
    std::vector<Vec3d> expected;
    for (int k = 0; k < md.count; ++k) expected.push_back(md.points[std::size_t(k)].point);
    EXPECT_LE(farthestFrom(mf, expected), 2e-5) << i;
    point.add(farthestFrom(mf, expected), 8);
  }
  EXPECT_GE(compared, 60);
  EXPECT_LE(idMismatches, compared / 5);
  std::printf("[ cases    ] %d float/double pairs, %d with different ids\n", compared,
              idMismatches);
}

}  // namespace
}  // namespace simdphys

// Tests of include/simdphys/geometry3d/{support,gjk,epa}.hpp on random inputs: support functions,
// GJK distance and intersection and EPA penetration against closed forms and oracles in double
// (tests/gjk_oracles.hpp), in float and in double.
//
// Every expected value comes from a closed form or an oracle of tests/gjk_oracles.hpp, in double,
// on the double shapes the inputs were rounded from (never from another library header):
// centre-line formulas for spheres, clamping for sphere-box, per-axis gaps and overlaps for
// box-box, a dense barycentric sampling for point-triangle, a 15-axis separating-axis test for
// OBB-OBB, and for mixed pairs a certificate (both points lie in their shapes and the direction
// between them separates the shapes by the distance; EPA's depth is the overlap along its normal
// and no sampled direction overlaps less).
//
// Tolerances are in units of eps * L: eps the machine epsilon of the scalar under test (1.19e-7
// for float, 2.22e-16 for double) and L the size of the problem (the span of the coordinates
// involved). One rounding of an input coordinate is eps/2 * L; GJK's answer is a short sum of
// products of such numbers, a few eps * L; the library stops its iterations at 16 eps * L
// (kGjkTolerance). So the bounds are 64 eps * L unless stated, with the measured maxima printed
// as "[ accuracy ]" lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "gjk_oracles.hpp"

namespace simdphys {
namespace {

using namespace test;

template <class T>
class Gjk : public ::testing::Test {};
TYPED_TEST_SUITE(Gjk, Scalars, ScalarName);

// ---- support functions ----------------------------------------------------------------------

TYPED_TEST(Gjk, SupportHandWorked) {
  using T = TypeParam;
  const double tol = 4 * kEps<T> * 4;  // a normalisation and one product, on values up to 4
  const SphereT<T> s{v3<T>(1, 2, 3), T(2)};
  // (3, 0, 4) / 5 * 2 = (1.2, 0, 1.6); the direction's length does not matter.
  EXPECT_LE(maxDiff(support(s, v3<T>(30, 0, 40)), Vec3d(2.2, 2, 4.6)), tol);
  EXPECT_LE(maxDiff(support(s, v3<T>(3e-30, 0, 4e-30)), Vec3d(2.2, 2, 4.6)), tol);  // no underflow
  EXPECT_EQ(support(s, Vec3<T>::Zero()), s.center);  // zero direction: the centre
  const AabbT<T> b{v3<T>(-1, -2, -3), v3<T>(1, 2, 3)};
  EXPECT_EQ(support(b, v3<T>(1, -1, 0)), v3<T>(1, -2, 3));  // 0 picks max
  EXPECT_EQ(support(b, Vec3<T>::Zero()), b.max);
  // An OBB turned a quarter about z: local x is world y, local y is world -x.
  ObbT<T> o{v3<T>(10, 0, 0), v3<T>(1, 2, 3), Mat3<T>::Identity()};
  o.axes << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  // Along (1, 1, -1): local x (+y world) +1, local y (-x world) -2 -> +2 in x, local z -3.
  EXPECT_LE(maxDiff(support(o, v3<T>(1, 1, -1)), Vec3d(12, 1, -3)), 0.0);
  const TriangleT<T> t{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_EQ(support(t, v3<T>(1, 0.5, 0)), t.b);
  EXPECT_EQ(support(t, v3<T>(-1, 2, 0)), t.c);
  EXPECT_EQ(support(t, v3<T>(0, 0, 1)), t.a);  // a tie goes to the first vertex
  const SegmentT<T> g{v3<T>(0, 0, 0), v3<T>(0, 0, 5)};
  EXPECT_EQ(support(g, v3<T>(0, 0, 1)), g.end);
  EXPECT_EQ(support(g, v3<T>(0, 1, -1)), g.start);
  const std::vector<Vec3<T>> pts = {v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 3, 0)};
  const ConvexHullT<T> h{pts};
  EXPECT_EQ(support(h, v3<T>(1, 0.1, 0)), pts[1]);
  EXPECT_EQ(support(h, v3<T>(0, 1, 0)), pts[3]);
  EXPECT_EQ(support(h, Vec3<T>::Zero()), pts[0]);
  EXPECT_THROW(support(ConvexHullT<T>{}, v3<T>(1, 0, 0)), Error);
  // A capsule as segment + sphere: the segment's end plus the radius along the direction.
  const MinkowskiSumT<SegmentT<T>, SphereT<T>> capsule{g, {Vec3<T>::Zero(), T(1)}};
  EXPECT_LE(maxDiff(support(capsule, v3<T>(0, 3, 4)), Vec3d(0, 0.6, 5.8)), tol);
  const MinkowskiDifferenceT<AabbT<T>, SegmentT<T>> diff{b, g};
  EXPECT_EQ(support(diff, v3<T>(1, 1, 1)), v3<T>(1, 2, 3));  // max of b minus min of g (start)
}

// ---- sphere pairs ---------------------------------------------------------------------------

TYPED_TEST(Gjk, SphereSphereRandomAgainstCentreLine) {
  using T = TypeParam;
  Worst dist("sphere-sphere distance, " + typeName<T>(), kEps<T>);
  Worst points("sphere-sphere closest points, " + typeName<T>(), kEps<T>);
  Worst depth("sphere-sphere EPA depth, " + typeName<T>(), kEps<T>);
  Worst normal("sphere-sphere EPA normal (|n - u|, L = 1), " + typeName<T>(), kEps<T>);
  Rng rng(101);
  for (int i = 0; i < 4000; ++i) {
    const Sphered a{rng.point(-10, 10), rng.u(0.1, 3)};
    const double rb = rng.u(0.1, 3);
    // Half the pairs within 1e-3 of touching, the others anywhere up to 3 apart or deep.
    const double gap = i % 2 ? rng.u(-1e-3, 1e-3) : rng.u(-3, 3);
    const Vec3d u = rng.dir();
    const Sphered b{a.center + (a.radius + rb + gap) * u, rb};
    const SphereT<T> at = inScalar<T>(a), bt = inScalar<T>(b);
    const Sphered ar = seen(at), br = seen(bt);  // the shapes GJK saw
    const Vec3d cr = br.center - ar.center;
    const double truth = cr.norm() - ar.radius - br.radius;
    const Vec3d ur = cr.normalized();
    const double L = extent(ar) + extent(br);
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(at, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    ASSERT_TRUE(finite(r.pointA.template cast<double>()) && std::isfinite(double(r.distance)));
    if (truth > tol) {
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      const Vec3d pa = ar.center + ar.radius * ur, pb = br.center - br.radius * ur;
      points.add(std::max(maxDiff(r.pointA, pa), maxDiff(r.pointB, pb)), L);
      ASSERT_LE(maxDiff(r.pointA, pa), tol) << i;
      ASSERT_LE(maxDiff(r.pointB, pb), tol) << i;
      EXPECT_FALSE(epa(at, bt).has_value());
    } else if (truth < -tol) {
      ASSERT_TRUE(r.intersecting) << i;
      EXPECT_EQ(r.distance, T(0));
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value()) << i;
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      depth.add(std::abs(p->depth + truth), L);
      ASSERT_LE(std::abs(p->depth + truth), tol) << i;
      // The normal is the centre line: its error is the centres' rounding over their distance.
      if (cr.norm() > 1e-3 * L) {
        const double ntol = 64 * kEps<T> * L / cr.norm();
        normal.add(maxDiff(p->normal, ur), 1);
        ASSERT_LE(maxDiff(p->normal, ur), ntol) << i;
      }
      // pointA - pointB = depth * normal, both on their spheres.
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
      ASSERT_LE(std::abs((p->pointA.template cast<double>() - ar.center).norm() - ar.radius), tol);
      ASSERT_LE(std::abs((p->pointB.template cast<double>() - br.center).norm() - br.radius), tol);
    } else {
      // Within rounding of touching: whatever the flag, the distance is tiny.
      ASSERT_LE(double(r.distance), 2 * tol) << i;
    }
  }
}

// ---- sphere-AABB ----------------------------------------------------------------------------

TYPED_TEST(Gjk, SphereAabbRandomAgainstClamping) {
  using T = TypeParam;
  Worst dist("sphere-AABB distance, " + typeName<T>(), kEps<T>);
  Worst points("sphere-AABB closest points, " + typeName<T>(), kEps<T>);
  Worst depth("sphere-AABB EPA depth (centre outside or inside), " + typeName<T>(), kEps<T>);
  Rng rng(202);
  int inside = 0, shallow = 0, apart = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3d lo = rng.point(-5, 5);
    const Aabbd box{lo, lo + rng.point(0.1, 4)};
    const double radius = i % 5 == 0 ? 0.0 : rng.u(0.05, 2);
    // Centres around the box; a third of them pushed onto a face, edge or corner + radius + tiny.
    Vec3d c = box.center() + (box.halfExtents() * 1.6).cwiseProduct(rng.point(-1, 1));
    if (i % 3 == 0) {
      const Vec3d q = clampToAabb(c, box);
      if ((c - q).norm() > 0) c = q + (c - q).normalized() * (radius + rng.u(-1e-3, 1e-3));
    }
    const SphereT<T> st{c.cast<T>(), T(radius)};
    const AabbT<T> bt = inScalar<T>(box);
    const Sphered s = seen(st);
    const Aabbd b = seen(bt);
    const double L = extent(s) + extent(b);
    const double tol = 64 * kEps<T> * L;
    const Vec3d q = clampToAabb(s.center, b);
    const double outside = (s.center - q).norm();
    const double truth = outside - s.radius;  // valid when the centre is outside
    const GjkResultT<T> r = gjkDistance(st, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (outside > 0 && truth > tol) {
      ++apart;
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      const Vec3d n = (q - s.center) / outside;
      points.add(std::max(maxDiff(r.pointA, s.center + s.radius * n), maxDiff(r.pointB, q)), L);
      ASSERT_LE(maxDiff(r.pointB, q), tol) << i;
      ASSERT_LE(maxDiff(r.pointA, s.center + s.radius * n), tol) << i;
    } else if (outside > tol && truth < -tol) {
      ++shallow;  // the centre outside the box, the sphere dipping in: along centre to clamp
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(st, bt);
      ASSERT_TRUE(p.has_value());
      depth.add(std::abs(p->depth + truth), L);
      ASSERT_LE(std::abs(p->depth + truth), tol) << i;
      ASSERT_LE(maxDiff(p->normal, (q - s.center) / outside), 64 * kEps<T> * L / outside) << i;
    } else if (outside == 0) {
      // The centre inside: out through the nearest face, depth = that gap + radius, normal minus
      // the face's outward normal (B moves the other way). Checked where the nearest face is
      // clear (the next is 1e-3 L farther).
      std::array<std::pair<double, Vec3d>, 6> faces;
      for (int k = 0; k < 3; ++k) {
        faces[2 * k] = {b.max[k] - s.center[k], -Vec3d::Unit(k)};
        faces[2 * k + 1] = {s.center[k] - b.min[k], Vec3d::Unit(k)};
      }
      std::sort(faces.begin(), faces.end(), [](auto& x, auto& y) { return x.first < y.first; });
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(st, bt);
      ASSERT_TRUE(p.has_value());
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      const double expected = faces[0].first + s.radius;
      if (faces[1].first - faces[0].first > 1e-3 * L) {
        ++inside;
        depth.add(std::abs(p->depth - expected), L);
        ASSERT_LE(std::abs(p->depth - expected), tol) << i;
        ASSERT_LE(maxDiff(p->normal, faces[0].second), 64 * kEps<T>) << i;
      }
    }
  }
  // The generator must hit every branch often (a test that skips everything cannot fail).
  EXPECT_GT(apart, 500);
  EXPECT_GT(shallow, 200);
  EXPECT_GT(inside, 200);
}

// ---- AABB pairs -----------------------------------------------------------------------------

TYPED_TEST(Gjk, AabbAabbRandomAgainstAxisGaps) {
  using T = TypeParam;
  Worst dist("AABB-AABB distance (per-axis gaps), " + typeName<T>(), kEps<T>);
  Worst depth("AABB-AABB EPA depth (least overlap axis), " + typeName<T>(), kEps<T>);
  Rng rng(303);
  int separated = 0, overlapping = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3d lo = rng.point(-3, 3);
    const Aabbd a0{lo, lo + rng.point(0.1, 3)};
    const Vec3d h = rng.point(0.05, 1.5);
    Vec3d c = a0.center() + (a0.halfExtents() + h).cwiseProduct(rng.point(-1.3, 1.3));
    if (i % 3 == 0) {  // snap one axis to within 1e-3 of touching
      const int k = i % 9 / 3;
      c[k] = a0.center()[k] +
             (c[k] > a0.center()[k] ? 1 : -1) * (a0.halfExtents()[k] + h[k] + rng.u(-1e-3, 1e-3));
    }
    const AabbT<T> at = inScalar<T>(a0), bt = inScalar<T>(Aabbd::fromCenter(c, h));
    const Aabbd a = seen(at), b = seen(bt);
    const double L = extent(a) + extent(b);
    const double tol = 64 * kEps<T> * L;
    const Vec3d gaps = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0);
    const double truth = gaps.norm();
    const GjkResultT<T> r = gjkDistance(at, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (truth > tol) {
      ++separated;
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      // The closest points lie in their boxes and differ by the gap vector (B - A per axis).
      ASSERT_LE(distanceTo(a, r.pointA.template cast<double>()), tol);
      ASSERT_LE(distanceTo(b, r.pointB.template cast<double>()), tol);
    } else if (gaps.maxCoeff() == 0) {
      // Overlap on every axis: B must move by the least of the six overlaps.
      std::array<std::pair<double, Vec3d>, 6> moves;
      for (int k = 0; k < 3; ++k) {
        moves[2 * k] = {a.max[k] - b.min[k], Vec3d::Unit(k)};
        moves[2 * k + 1] = {b.max[k] - a.min[k], -Vec3d::Unit(k)};
      }
      std::sort(moves.begin(), moves.end(), [](auto& x, auto& y) { return x.first < y.first; });
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value());
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      ++overlapping;
      depth.add(std::abs(p->depth - moves[0].first), L);
      ASSERT_LE(std::abs(p->depth - moves[0].first), tol) << i;
      if (moves[1].first - moves[0].first > 1e-3 * L) {  // a clear minimum: the axis is known
        ASSERT_LE(maxDiff(p->normal, moves[0].second), 64 * kEps<T>) << i;
      }
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
    }
  }
  EXPECT_GT(separated, 1000);
  EXPECT_GT(overlapping, 300);
}

// ---- point-triangle -------------------------------------------------------------------------

TYPED_TEST(Gjk, PointTriangleAgainstBarycentricSampling) {
  using T = TypeParam;
  Worst dist("point-triangle distance vs sampling (minus its bound), " + typeName<T>(), kEps<T>);
  Rng rng(404);
  constexpr int N = 300;  // grid steps per edge: 45,451 samples per triangle
  for (int i = 0; i < 150; ++i) {
    const TriangleT<T> tt{rng.point(-2, 2).cast<T>(), rng.point(-2, 2).cast<T>(),
                          rng.point(-2, 2).cast<T>()};
    const Triangled t = seen(tt);
    // Points near the plane, the edges and the corners, some on the triangle itself.
    Vec3d p = rng.point(-3, 3);
    if (i % 4 == 1) p = (t.a + t.b) / 2 + rng.u(-0.01, 0.01) * rng.dir();
    if (i % 4 == 2) p = t.c + rng.u(0, 0.5) * rng.dir();
    if (i % 4 == 3) p = (t.a + t.b + t.c) / 3 + rng.u(-1, 1) * t.normal().normalized();
    const SphereT<T> point{p.cast<T>(), T(0)};
    const Vec3d pr = seenVec(point.center);
    const Vec3d e1 = t.b - t.a, e2 = t.c - t.a;
    double oracle = INFINITY;
    for (int u = 0; u <= N; ++u)
      for (int v = 0; u + v <= N; ++v)
        oracle = std::min(oracle, (t.a + (u * e1 + v * e2) / N - pr).norm());
    // The nearest grid point to the true closest point is at most (|e1| + |e2|) / N away.
    const double grid = (e1.norm() + e2.norm()) / N;
    const double L = extent(t) + pr.cwiseAbs().maxCoeff();
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(point, tt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    ASSERT_LE(double(r.distance), oracle + tol) << i;
    ASSERT_GE(double(r.distance), oracle - grid - tol) << i;
    dist.add(std::max(0.0, std::abs(double(r.distance) - oracle) - grid), L);
    // The point on the triangle lies on it, and is the distance away.
    ASSERT_LE(distanceTo(t, r.pointB.template cast<double>()), tol) << i;
    if (!r.intersecting) {
      ASSERT_LE(std::abs((r.pointB - r.pointA).norm() - r.distance), tol) << i;
    }
  }
}

// ---- OBB pairs against the 15-axis SAT ------------------------------------------------------

TYPED_TEST(Gjk, ObbObbRandomAgainstSat) {
  using T = TypeParam;
  Worst depth("OBB-OBB EPA depth vs SAT least overlap, " + typeName<T>(), kEps<T>);
  Worst lower("OBB-OBB distance below SAT separation, " + typeName<T>(), kEps<T>);
  Rng rng(505);
  int agree = 0, ambiguous = 0, maxGjk = 0, maxEpa = 0;
  for (int i = 0; i < 3000; ++i) {
    const Obbd a0{rng.point(-2, 2), rng.point(0.1, 2), rng.rotation()};
    Obbd b0{Vec3d::Zero(), rng.point(0.1, 2), rng.rotation()};
    // B's centre at (1 + s) times the sum of the two boxes' radii along a random direction, s
    // within 0.1 (many near-touching), sometimes deep inside.
    const Vec3d u = rng.dir();
    double reach = 0;
    for (int k = 0; k < 3; ++k)
      reach += a0.halfExtents[k] * std::abs(a0.axes.col(k).dot(u)) +
               b0.halfExtents[k] * std::abs(b0.axes.col(k).dot(u));
    b0.center = a0.center + u * reach * (i % 4 == 0 ? rng.u(0, 0.9) : 1 + rng.u(-0.1, 0.1));
    const ObbT<T> at = inScalar<T>(a0), bt = inScalar<T>(b0);
    // The oracle sees the double boxes; the float ones differ by input rounding (within tol).
    const Sat sat = satOracle(a0, b0);
    const double L = extent(a0) + extent(b0);
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(at, bt);
    maxGjk = std::max(maxGjk, r.iterations);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    EXPECT_EQ(gjkIntersect(bt, at), gjkIntersect(at, bt)) << i;
    if (std::abs(sat.separation) <= tol) {
      ++ambiguous;
      ASSERT_LE(double(r.distance), 2 * tol);
      continue;
    }
    ++agree;
    ASSERT_EQ(r.intersecting, sat.separation < 0) << i << " sat " << sat.separation;
    if (sat.separation > 0) {
      // The SAT separation is a lower bound of the distance.
      lower.add(std::max(0.0, sat.separation - r.distance), L);
      ASSERT_GE(double(r.distance), sat.separation - tol) << i;
      ASSERT_LE(distanceTo(a0, r.pointA.template cast<double>()), tol);
      ASSERT_LE(distanceTo(b0, r.pointB.template cast<double>()), tol);
      EXPECT_FALSE(epa(at, bt).has_value());
    } else {
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value()) << i;
      maxEpa = std::max(maxEpa, p->iterations);
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      depth.add(std::abs(p->depth + sat.separation), L);
      ASSERT_LE(std::abs(p->depth + sat.separation), tol) << i;
      if (sat.runnerUp - sat.separation < -1e-3 * L) {       // a clear least-overlap axis
        ASSERT_LE(maxDiff(p->normal, sat.axis), 1e-3) << i;  // see below
      }
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
    }
  }
  // The normal bound: a normal off by angle a changes the overlap by about a^2 / 2 * L only when
  // the axis is a minimum, so a 1e-3 L clear minimum pins the normal to well under 1e-3.
  std::printf(
      "[ accuracy ] OBB-OBB %s: %d decided, %d within tolerance of touching, max GJK "
      "iterations %d, max EPA iterations %d\n",
      typeName<T>().c_str(), agree, ambiguous, maxGjk, maxEpa);
  EXPECT_GT(agree, 2800);
}

// ---- mixed random pairs: certificates -------------------------------------------------------

// Sample directions for EPA's minimality check: the 3 axes, 200 random unit vectors.
std::vector<Vec3d> sampleDirections() {
  std::vector<Vec3d> d = {Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ()};
  Rng rng(9);
  for (int i = 0; i < 200; ++i) d.push_back(rng.dir());
  return d;
}

struct MixedStats {
  int separated = 0, intersecting = 0, ambiguous = 0, maxGjk = 0, maxEpa = 0;
};

template <class T, class SA, class SB>
void checkPair(const SA& a, const SB& b, const std::vector<Vec3d>& dirs, Worst& gap, Worst& pen,
               Worst& vsDouble, MixedStats& stats, const std::string& where) {
  const auto at = inScalar<T>(a);
  const auto bt = inScalar<T>(b);
  const double L = extent(a) + extent(b);
  const double tol = 64 * kEps<T> * L;
  const GjkResultT<T> r = gjkDistance(view(at), view(bt));
  SCOPED_TRACE(where);
  stats.maxGjk = std::max(stats.maxGjk, r.iterations);
  ASSERT_LT(r.iterations, kGjkMaxIterations);
  const Vec3d pa = r.pointA.template cast<double>(), pb = r.pointB.template cast<double>();
  ASSERT_TRUE(finite(pa) && finite(pb) && std::isfinite(double(r.distance)));
  // Both points lie in their shapes.
  ASSERT_LE(distanceTo(a, pa), tol);
  ASSERT_LE(distanceTo(b, pb), tol);
  // Symmetric: B against A gives the same distance.
  const GjkResultT<T> s = gjkDistance(view(bt), view(at));
  ASSERT_LE(std::abs(double(s.distance) - double(r.distance)), tol);
  // The double answer, certified below; a float answer agrees with it to the float bound.
  const GjkResultd d = gjkDistance(view(inScalar<double>(a)), view(inScalar<double>(b)));
  if constexpr (std::is_same_v<T, float>) {
    vsDouble.add(std::abs(double(r.distance) - d.distance), L);
    ASSERT_LE(std::abs(double(r.distance) - d.distance), tol);
  }
  if (r.intersecting != d.intersecting) {
    // Float and double disagree only within the float bound of touching.
    ASSERT_LE(d.distance, 2 * tol);
    ++stats.ambiguous;
    return;
  }
  if (!r.intersecting) {
    ++stats.separated;
    ASSERT_GT(r.distance, T(0));
    ASSERT_LE(std::abs((pb - pa).norm() - double(r.distance)), tol);
    // The certificate, on the double answer: along n = (pb - pa) / |pb - pa| the shapes are
    // apart by the distance, so no two of their points are closer. The direction carries the
    // points' rounding (eps L) over their distance: the separation along it may fall short by
    // that angle times the shapes' size, eps L * L / distance.
    const Vec3d n = (d.pointB - d.pointA).normalized();
    const double separation = minDot(b, n) - maxDot(a, n);
    const double dtol = 64 * kEps<double> * L * (1 + 2 * L / d.distance);
    gap.add(std::max(0.0, d.distance - separation), L * (1 + 2 * L / d.distance));
    ASSERT_GE(separation, d.distance - dtol);
    ASSERT_FALSE(epa(view(at), view(bt)).has_value());
    return;
  }
  // Intersecting: the common point is in both shapes (checked above, pa == pb).
  ASSERT_LE(maxDiff(r.pointA, r.pointB), 0.0);
  const auto p = epa(view(at), view(bt));
  ASSERT_TRUE(p.has_value());
  ++stats.intersecting;
  stats.maxEpa = std::max(stats.maxEpa, p->iterations);
  ASSERT_LT(p->iterations, kEpaMaxIterations);
  const Vec3d n = p->normal.template cast<double>();
  ASSERT_LE(std::abs(n.norm() - 1), 8 * kEps<T>);
  ASSERT_GE(p->depth, T(0));
  ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
  // The depth is the overlap along the normal (moving B by it makes them touch) ...
  const double along = maxDot(a, n) - minDot(b, n);
  pen.add(std::abs(double(p->depth) - along), L);
  ASSERT_LE(std::abs(double(p->depth) - along), tol);
  // ... and no other direction overlaps less: it is the least translation (within tol).
  for (const Vec3d& l : dirs)
    for (const Vec3d& m : {l, Vec3d(-l)})
      ASSERT_GE(maxDot(a, m) - minDot(b, m), double(p->depth) - tol) << m.transpose();
  ASSERT_LE(distanceTo(a, p->pointA.template cast<double>()), tol);
  ASSERT_LE(distanceTo(b, p->pointB.template cast<double>()), tol);
}

TYPED_TEST(Gjk, MixedRandomPairsCertified) {
  using T = TypeParam;
  Worst gap("mixed pairs: double distance above certified separation (L(1+2L/d))", kEps<double>);
  Worst pen("mixed pairs: EPA depth vs overlap along its normal, " + typeName<T>(), kEps<T>);
  Worst vsDouble("mixed pairs: float distance vs double GJK, float", kEps<T>);
  const std::vector<Vec3d> dirs = sampleDirections();
  MixedStats stats;
  Rng rng(606);
  for (int i = 0; i < 150; ++i) {
    const Vec3d c = rng.point(-1, 1);
    auto near = [&]() -> Vec3d { return c + rng.point(-1.5, 1.5); };
    const Sphered sphere{near(), rng.u(0.1, 1)};
    const Vec3d lo = near();
    const Aabbd aabb{lo, lo + rng.point(0.1, 1.5)};
    const Obbd obb{near(), rng.point(0.1, 1), rng.rotation()};
    const Triangled tri{near(), near(), near()};
    const Segmentd seg{near(), near()};
    const HullShape<double> hull = makeHull(Obbd{near(), rng.point(0.1, 1), rng.rotation()}, rng);
    // Each pair as generated, and moved to within 1e-3 of touching along GJK's direction (or,
    // if it overlaps, pushed in by up to 10% of its depth from touching).
    auto both = [&](const auto& a, const auto& b, const char* name) {
      const std::string where = std::string(name) + " #" + std::to_string(i);
      checkPair<T>(a, b, dirs, gap, pen, vsDouble, stats, where);
      const GjkResultd d = gjkDistance(view(a), view(b));
      if (!d.intersecting) {
        const Vec3d n = (d.pointB - d.pointA) / d.distance;
        const auto moved = translated(b, -n * (d.distance + rng.u(-1e-3, 1e-3)));
        checkPair<T>(a, moved, dirs, gap, pen, vsDouble, stats, where + " near touching");
      } else if (const auto p = epa(view(a), view(b))) {
        const auto moved = translated(b, p->normal * p->depth * rng.u(0.9, 1.001));
        checkPair<T>(a, moved, dirs, gap, pen, vsDouble, stats, where + " nearly apart");
      }
    };
    both(sphere, aabb, "sphere-aabb");
    both(sphere, obb, "sphere-obb");
    both(sphere, tri, "sphere-triangle");
    both(sphere, seg, "sphere-segment");
    both(sphere, hull, "sphere-hull");
    both(aabb, obb, "aabb-obb");
    both(aabb, tri, "aabb-triangle");
    both(obb, tri, "obb-triangle");
    both(obb, seg, "obb-segment");
    both(obb, hull, "obb-hull");
    both(hull, tri, "hull-triangle");
    both(hull, seg, "hull-segment");
    both(tri, seg, "triangle-segment");
    both(seg, Segmentd{near(), near()}, "segment-segment");
    both(tri, Triangled{near(), near(), near()}, "triangle-triangle");
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf(
      "[ accuracy ] mixed pairs %s: %d separated, %d intersecting, %d within the float "
      "bound of touching, max GJK iterations %d, max EPA iterations %d\n",
      typeName<T>().c_str(), stats.separated, stats.intersecting, stats.ambiguous, stats.maxGjk,
      stats.maxEpa);
  EXPECT_GT(stats.separated, 1000);
  EXPECT_GT(stats.intersecting, 1000);
}

}  // namespace
}  // namespace simdphys

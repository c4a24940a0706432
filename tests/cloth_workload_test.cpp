// W3 (workloads/cloth.hpp): the grid, pins and springs WORKLOADS.md specifies, against an
// independent classification of every particle pair; and W3's measures on cases whose answer is
// known in closed form.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "cloth.hpp"
#include "expect_error.hpp"

namespace simdphys {
namespace {

using workloads::ClothSpring;
using workloads::ClothWorkload;
using workloads::SpringKind;

constexpr double kD = 0.05;  // W3's spacing

TEST(ClothWorkload, SpringCountsAreTheGridFormulas) {
  // structural 2 n (n-1), shear 2 (n-1)^2, bend 2 n (n-2), worked out by hand.
  const std::map<std::size_t, std::array<std::size_t, 3>> expected = {
      {4, {24, 18, 16}}, {128, {32'512, 32'258, 32'256}}};
  for (const auto& [n, counts] : expected) {
    const ClothWorkload w = workloads::makeClothWorkload(n);
    std::array<std::size_t, 3> found{};
    for (const ClothSpring& s : w.springs) ++found[std::size_t(s.kind)];
    EXPECT_EQ(found, counts) << "n = " << n;
    for (SpringKind kind : {SpringKind::kStructural, SpringKind::kShear, SpringKind::kBend})
      EXPECT_EQ(workloads::clothSpringCount(n, kind), counts[std::size_t(kind)]) << "n = " << n;
  }
}

TEST(ClothWorkload, PositionsAndPinsAreTheSpecs) {
  for (std::size_t n : {std::size_t(4), std::size_t(128)}) {
    const ClothWorkload w = workloads::makeClothWorkload(n);
    ASSERT_EQ(w.n, n);
    ASSERT_EQ(w.positions.size(), n * n);
    ASSERT_EQ(w.invMass.size(), n * n);
    const double half = (double(n) - 1) / 2;
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = j * n + i;
        const Vec3f spec(float((double(i) - half) * kD), 2, float((double(j) - half) * kD));
        ASSERT_EQ(w.positions[k], spec) << "particle (" << i << ", " << j << ") of n = " << n;
        const bool pinned = k == 0 || k == n - 1;  // (0, 0) and (n-1, 0)
        ASSERT_EQ(w.invMass[k], pinned ? 0.0f : 1.0f) << "particle (" << i << ", " << j << ")";
      }
  }
  // n = 4 by hand: the corners at +-0.075.
  const ClothWorkload w = workloads::makeClothWorkload(4);
  EXPECT_EQ(w.positions[0], Vec3f(-0.075f, 2, -0.075f));
  EXPECT_EQ(w.positions[3], Vec3f(0.075f, 2, -0.075f));
  EXPECT_EQ(w.positions[15], Vec3f(0.075f, 2, 0.075f));
  EXPECT_EQ(workloads::kClothSphere.center, Vec3f(0, 1.2f, 0.3f));
  EXPECT_EQ(workloads::kClothSphere.radius, 0.5f);
  EXPECT_EQ(workloads::kClothGravity, Vec3f(0, -9.82f, 0));
  EXPECT_EQ(workloads::kClothFrames, 300);
  EXPECT_EQ(workloads::kClothFrameTime, 1.0f / 60.0f);
}

// Every pair of particles classified by its grid offset, independently of the generator: the
// springs are exactly these pairs, each once, grouped by kind, with its initial length as rest.
TEST(ClothWorkload, SpringsAreTheGridPairs) {
  for (std::size_t n : {std::size_t(4), std::size_t(7)}) {
    const ClothWorkload w = workloads::makeClothWorkload(n);
    std::map<std::pair<std::uint32_t, std::uint32_t>, SpringKind> oracle;
    for (std::uint32_t p = 0; p < n * n; ++p)
      for (std::uint32_t q = p + 1; q < n * n; ++q) {
        const long di = std::labs(long(p % n) - long(q % n)),
                   dj = std::labs(long(p / n) - long(q / n));
        if (di + dj == 1) oracle[{p, q}] = SpringKind::kStructural;
        if (di == 1 && dj == 1) oracle[{p, q}] = SpringKind::kShear;
        if ((di == 2 && dj == 0) || (di == 0 && dj == 2)) oracle[{p, q}] = SpringKind::kBend;
      }
    ASSERT_EQ(w.springs.size(), oracle.size()) << "n = " << n;
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    const double rest[] = {kD, kD * std::sqrt(2.0), 2 * kD};
    for (std::size_t k = 0; k < w.springs.size(); ++k) {
      const ClothSpring& s = w.springs[k];
      const auto key = std::minmax(s.a, s.b);
      ASSERT_TRUE(oracle.contains(key)) << "spring " << k << ": " << s.a << " - " << s.b;
      EXPECT_EQ(s.kind, oracle.at(key)) << "spring " << k;
      EXPECT_TRUE(seen.insert(key).second) << "spring " << k << " repeats a pair";
      if (k > 0) {
        EXPECT_GE(s.kind, w.springs[k - 1].kind) << "spring " << k << ": kinds mixed";
      }
      const double length =
          (w.positions[s.a].cast<double>() - w.positions[s.b].cast<double>()).norm();
      EXPECT_EQ(s.rest, float(length)) << "spring " << k;
      // The coordinates are rounded to float (half an ulp of 0.2, 7e-9, each).
      EXPECT_NEAR(s.rest, rest[std::size_t(s.kind)], 4e-8) << "spring " << k;
    }
  }
  // The documented order: first spring of each family of n = 4.
  const ClothWorkload w = workloads::makeClothWorkload(4);
  const std::pair<std::uint32_t, std::uint32_t> first[] = {{0, 1}, {0, 4}, {0, 5},
                                                           {1, 4}, {0, 2}, {0, 8}};
  const std::size_t start[] = {0, 12, 24, 33, 42, 50};  // families of 12, 12, 9, 9, 8, 8
  for (int f = 0; f < 6; ++f) {
    const ClothSpring& s = w.springs[start[f]];
    EXPECT_EQ(std::make_pair(s.a, s.b), first[f]) << "family " << f;
  }
  // Within a family, j-major: the second structural spring along x is (1, 0)-(2, 0), the fourth
  // (0, 1)-(1, 1).
  EXPECT_EQ(std::make_pair(w.springs[1].a, w.springs[1].b), std::make_pair(1u, 2u));
  EXPECT_EQ(std::make_pair(w.springs[3].a, w.springs[3].b), std::make_pair(4u, 5u));
}

TEST(ClothWorkload, StretchOfAUniformlyStretchedGridIsItsFactor) {
  const ClothWorkload w = workloads::makeClothWorkload(8);
  std::vector<Vec3f> x = w.positions;
  for (Vec3f& p : x) p = (Vec3f(p.x(), p.y() - 2, p.z()) * 1.01f) + Vec3f(0, 2, 0);
  const workloads::ClothStretch s = workloads::clothStretch(w, x);
  // Coordinates below 0.2 rounded to float: 1e-8 each, 4e-7 of a 0.05 spring.
  EXPECT_NEAR(s.mean, 0.01, 1e-6);
  EXPECT_NEAR(s.p99, 0.01, 1e-6);
  EXPECT_NEAR(s.max, 0.01, 1e-6);
  EXPECT_NEAR(s.maxAwayFromPins, 0.01, 1e-6);
  const workloads::ClothStretch rest = workloads::clothStretch(w, w.positions);
  // At rest, only the rest lengths' rounding to float: half an ulp, 2^-24 of the length at most.
  EXPECT_LE(rest.max, 0x1p-24);
  EXPECT_LE(rest.mean, rest.max);
}

// Lifting particles out of the plane by h = 1/16 (exact in float at y = 2) stretches their
// structural springs from d to sqrt(d^2 + h^2). The rest lengths are float roundings of d (3e-7
// of it), hence the tolerances.
TEST(ClothWorkload, StretchFiguresSeparate) {
  const std::size_t n = 11;  // 220 structural springs: the 99th percentile is the 218th smallest
  const ClothWorkload w = workloads::makeClothWorkload(n);
  const double h = 0.0625, bent = std::sqrt(1 + (h / kD) * (h / kD)) - 1;
  const auto lifted = [&](std::initializer_list<std::size_t> particles) {
    std::vector<Vec3f> x = w.positions;
    for (std::size_t k : particles) x[k].y() += float(h);
    return workloads::clothStretch(w, x);
  };
  // An edge particle, (0, 5): three springs, so the 218th smallest is one of them.
  workloads::ClothStretch s = lifted({5 * n});
  EXPECT_NEAR(s.mean, 3 * bent / 220, 1e-7);
  EXPECT_NEAR(s.p99, bent, 2e-6);
  EXPECT_NEAR(s.max, bent, 2e-6);
  EXPECT_NEAR(s.maxAwayFromPins, bent, 2e-6);
  // The free corner (0, n-1): two springs, the 219th and 220th; the 218th is 0.
  s = lifted({(n - 1) * n});
  EXPECT_EQ(s.p99, 0);
  EXPECT_NEAR(s.max, bent, 2e-6);
  // A pinned corner: both its springs touch a pin.
  s = lifted({0});
  EXPECT_NEAR(s.max, bent, 2e-6);
  EXPECT_EQ(s.maxAwayFromPins, 0);
  // The pinned corner pulled out along -x by d / 2: its x spring to 1.5 d, its z spring to
  // d sqrt(1.25).
  std::vector<Vec3f> x = w.positions;
  x[0].x() -= float(kD / 2);
  s = workloads::clothStretch(w, x);
  EXPECT_NEAR(s.max, 0.5, 1e-6);
  EXPECT_NEAR(s.mean, (0.5 + std::sqrt(1.25) - 1) / 220, 1e-7);
  EXPECT_EQ(s.maxAwayFromPins, 0);
}

TEST(ClothWorkload, SpherePenetration) {
  const Sphere& sphere = workloads::kClothSphere;
  const Vec3f c = sphere.center;
  EXPECT_EQ(workloads::spherePenetration(sphere, {}), 0);
  const std::vector<Vec3f> outside = {c + Vec3f(0, 0.6f, 0), c + Vec3f(0.3f, 0.3f, 0.3f)};
  EXPECT_EQ(workloads::spherePenetration(sphere, outside), 0);  // |(0.3, 0.3, 0.3)| = 0.52
  const std::vector<Vec3f> points = {c + Vec3f(0, 0.6f, 0), c + Vec3f(0, 0.4f, 0),
                                     c + Vec3f(0.3f, 0, 0.4f), c + Vec3f(0, 0.45f, 0)};
  // Depth 0.1 (distance 0.4, twice) is the deepest; float offsets round by 3e-8.
  EXPECT_NEAR(workloads::spherePenetration(sphere, points), 0.1, 1e-7);
  EXPECT_NEAR(workloads::spherePenetration(sphere, std::vector<Vec3f>{c}), 0.5, 0);
}

TEST(ClothWorkload, NonFinitePositions) {
  const ClothWorkload w = workloads::makeClothWorkload(4);
  EXPECT_TRUE(workloads::allFinite(w.positions));
  std::vector<Vec3f> x = w.positions;
  x[6].z() = std::numeric_limits<float>::quiet_NaN();  // an interior particle: 4 springs
  EXPECT_FALSE(workloads::allFinite(x));
  const workloads::ClothStretch s = workloads::clothStretch(w, x);
  EXPECT_EQ(s.max, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.maxAwayFromPins, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.mean, std::numeric_limits<double>::infinity());
  EXPECT_EQ(workloads::spherePenetration(workloads::kClothSphere, x),
            std::numeric_limits<double>::infinity());
  x[6].z() = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(workloads::allFinite(x));
}

TEST(ClothWorkload, BadInput) {
  test::expectError([] { workloads::makeClothWorkload(2); }, "n = 2");
  const ClothWorkload w = workloads::makeClothWorkload(4);
  test::expectError([&] { workloads::clothStretch(w, std::vector<Vec3f>(15)); }, "15 positions");
}

}  // namespace
}  // namespace simdphys

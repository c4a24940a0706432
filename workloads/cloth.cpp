#include "cloth.hpp"

#include "simdphys/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "simdphys/core.hpp"

namespace simdphys::workloads {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One spring family of W3: the springs (i + i0, j) - (i + i0 + di, j + dj), for every (i, j)
// both ends of which lie in the grid. i0 = 1 only for the second shear family, (i+1,j)-(i,j+1).
struct Family {
  SpringKind kind;
  int i0, di, dj;
};
constexpr Family kFamilies[] = {
    {SpringKind::kStructural, 0, 1, 0}, {SpringKind::kStructural, 0, 0, 1},
    {SpringKind::kShear, 0, 1, 1},      {SpringKind::kShear, 1, -1, 1},
    {SpringKind::kBend, 0, 2, 0},       {SpringKind::kBend, 0, 0, 2},
};

double length(const Vec3f& a, const Vec3f& b) {
  return (a.cast<double>() - b.cast<double>()).norm();
}

}  // namespace

std::size_t clothSpringCount(std::size_t n, SpringKind kind) {
  switch (kind) {
    case SpringKind::kStructural:
      return 2 * n * (n - 1);
    case SpringKind::kShear:
      return 2 * (n - 1) * (n - 1);
    case SpringKind::kBend:
      return 2 * n * (n - 2);
  }
  return 0;
}

ClothWorkload makeClothWorkload(std::size_t n) {
  if (n < 3) throw Error("W3 cloth: n = " + std::to_string(n) + " is below 3 (no bend springs)");
  ClothWorkload w;
  w.n = n;
  const double half = double(n - 1) / 2;
  w.positions.reserve(n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      w.positions.emplace_back(float((double(i) - half) * kClothSpacing), float(kClothHeight),
                               float((double(j) - half) * kClothSpacing));
  w.invMass.assign(n * n, 1.0f);
  w.invMass[0] = w.invMass[n - 1] = 0;

  std::size_t total = 0;
  for (SpringKind kind : {SpringKind::kStructural, SpringKind::kShear, SpringKind::kBend})
    total += clothSpringCount(n, kind);
  w.springs.reserve(total);
  const auto side = std::ptrdiff_t(n);
  for (const Family& f : kFamilies) {
    // The first corners (i + i0, j) whose partner lies in the grid.
    const std::ptrdiff_t iLast = side - 1 - std::max({f.i0, f.i0 + f.di});
    const std::ptrdiff_t jLast = side - 1 - f.dj;
    for (std::ptrdiff_t j = 0; j <= jLast; ++j)
      for (std::ptrdiff_t i = 0; i <= iLast; ++i) {
        const auto a = std::uint32_t(j * side + i + f.i0);
        const auto b = std::uint32_t((j + f.dj) * side + i + f.i0 + f.di);
        w.springs.push_back({a, b, float(length(w.positions[a], w.positions[b])), f.kind});
      }
  }
  return w;
}

ClothStretch clothStretch(const ClothWorkload& w, std::span<const Vec3f> positions) {
  if (positions.size() != w.positions.size())
    throw Error("W3 stretch: " + std::to_string(positions.size()) + " positions for a cloth of " +
                std::to_string(w.positions.size()) + " particles");
  std::vector<Spring> structural;
  for (const ClothSpring& s : w.springs)
    if (s.kind == SpringKind::kStructural) structural.push_back({s.a, s.b, s.rest});
  const Stretch s = stretchOf(structural, positions, w.invMass);
  return {s.mean, s.p99, s.max, s.maxAwayFromPins};
}

double spherePenetration(const Sphere& sphere, std::span<const Vec3f> positions) {
  const Vec3d c = sphere.center.cast<double>();
  double deepest = 0;
  for (const Vec3f& p : positions) {
    const double depth = double(sphere.radius) - (p.cast<double>() - c).norm();
    if (!std::isfinite(depth)) return kInf;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

bool allFinite(std::span<const Vec3f> positions) {
  return std::all_of(positions.begin(), positions.end(),
                     [](const Vec3f& p) { return p.allFinite(); });
}

ClothGrid clothGrid(const ClothWorkload& w) {
  ClothGrid g;
  g.nx = g.nz = w.n;
  g.positions = w.positions;
  g.invMass = w.invMass;
  return g;
}

std::vector<Spring> clothSprings(const ClothWorkload& w) {
  std::vector<Spring> springs;
  for (const ClothSpring& s : w.springs) springs.push_back({s.a, s.b, s.rest});
  return springs;
}

}  // namespace simdphys::workloads

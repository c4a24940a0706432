#include "simdphys/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simdphys {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double boxDepth(const Vec3d& local, const Vec3d& half) {
  const Vec3d gap = half - local.cwiseAbs();  // > 0 on every axis inside
  return std::max(0.0, gap.minCoeff());
}

// The structural springs of a cloth in particle indices: a grid's (i, j)-(i+1, j) and
// (i, j)-(i, j+1), rest at their distance now; a network's springs as they are.
std::vector<Spring> structuralSprings(const Cloth& c) {
  if (!c.isGrid()) return {c.springs().begin(), c.springs().end()};
  std::vector<Spring> out;
  const std::size_t nx = c.gridColumns(), nz = c.gridRows();
  auto add = [&](std::size_t a, std::size_t b) {
    const Vec3d pa = c.position(std::uint32_t(a)).cast<double>();
    const Vec3d pb = c.position(std::uint32_t(b)).cast<double>();
    out.push_back({std::uint32_t(a), std::uint32_t(b), float((pa - pb).norm())});
  };
  for (std::size_t j = 0; j < nz; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) add(j * nx + i, j * nx + i + 1);
  for (std::size_t j = 0; j + 1 < nz; ++j)
    for (std::size_t i = 0; i < nx; ++i) add(j * nx + i, (j + 1) * nx + i);
  return out;
}

double clothDepth(const World& world, const Cloth& c) {
  double deepest = 0;
  for (std::uint32_t i = 0; i < c.size(); ++i) {
    const Vec3f p = c.position(i);
    if (!p.allFinite()) return kInf;
    for (const ObstacleShape& s : world.obstacles().shapes())
      deepest = std::max(deepest, depthInside(s, p));
  }
  return deepest;
}

}  // namespace

Stretch stretchOf(std::span<const Spring> springs, std::span<const Vec3f> positions,
                  std::span<const float> invMass) {
  Stretch out;
  if (springs.empty()) return out;
  std::vector<double> stretch;
  stretch.reserve(springs.size());
  for (const Spring& s : springs) {
    const double l = (positions[s.a].cast<double>() - positions[s.b].cast<double>()).norm();
    double e = std::abs(l - double(s.rest)) / double(s.rest);
    if (!std::isfinite(e)) e = kInf;  // NaN too: it must still sort
    stretch.push_back(e);
    out.mean += e;
    out.max = std::max(out.max, e);
    if (invMass[s.a] != 0 && invMass[s.b] != 0)
      out.maxAwayFromPins = std::max(out.maxAwayFromPins, e);
  }
  const std::size_t m = stretch.size();
  out.mean /= double(m);
  const auto rank = std::size_t(std::ceil(0.99 * double(m)));  // 1-based
  std::nth_element(stretch.begin(), stretch.begin() + std::ptrdiff_t(rank - 1), stretch.end());
  out.p99 = stretch[rank - 1];
  return out;
}

double depthInside(const ObstacleShape& shape, const Vec3f& point) {
  const Vec3d p = point.cast<double>();
  if (const auto* s = std::get_if<Plane>(&shape))
    return std::max(0.0, -(s->normal.cast<double>().dot(p) + double(s->d)));
  if (const auto* s = std::get_if<Sphere>(&shape))
    return std::max(0.0, double(s->radius) - (p - s->center.cast<double>()).norm());
  if (const auto* s = std::get_if<Aabb>(&shape)) {
    const Vec3d lo = s->min.cast<double>(), hi = s->max.cast<double>();
    return boxDepth(p - 0.5 * (lo + hi), 0.5 * (hi - lo));
  }
  if (const auto* s = std::get_if<Obb>(&shape))
    return boxDepth(s->axes.cast<double>().transpose() * (p - s->center.cast<double>()),
                    s->halfExtents.cast<double>());
  return 0;  // a mesh is a surface
}

WorldMonitor::WorldMonitor(const World& world) {
  const RigidBodies& bodies = world.bodies();
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    bodies_.push_back(bodies.handle(i));
    bodyStart_.push_back(bodies.position(bodies_.back()));
  }
  for (std::size_t c = 0; c < world.clothCount(); ++c)
    clothSprings_.push_back(structuralSprings(world.cloth(world.clothHandle(c))));
  deepestCloth_.assign(world.clothCount(), 0);
}

void WorldMonitor::observe(const World& world) {
  const double body = world.bodies().deepestPenetration();
  deepestBody_ = std::isfinite(body) ? std::max(deepestBody_, body) : kInf;
  for (std::size_t c = 0; c < world.clothCount() && c < deepestCloth_.size(); ++c)
    deepestCloth_[c] =
        std::max(deepestCloth_[c], clothDepth(world, world.cloth(world.clothHandle(c))));
}

WorldMeasures WorldMonitor::measure(const World& world) const {
  WorldMeasures m;
  const RigidBodies& bodies = world.bodies();
  m.bodies.deepestPenetration = deepestBody_;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!bodies.contains(bodies_[i])) continue;  // removed since the start
    ++m.bodies.count;
    const Vec3f p = bodies.position(bodies_[i]);
    m.bodies.finite = m.bodies.finite && p.allFinite();
    const double d = (p.cast<double>() - bodyStart_[i].cast<double>()).norm();
    m.bodies.maxDisplacement = std::max(m.bodies.maxDisplacement, std::isfinite(d) ? d : kInf);
    m.bodies.standing = m.bodies.standing && d <= 0.5;
  }
  for (std::size_t c = 0; c < world.clothCount() && c < clothSprings_.size(); ++c) {
    const Cloth& cloth = world.cloth(world.clothHandle(c));
    ClothMeasures cm;
    cm.particles = cloth.size();
    cm.springs = clothSprings_[c].size();
    const std::vector<Vec3f> positions = cloth.positions();
    std::vector<float> invMass(cloth.size());
    for (std::uint32_t i = 0; i < cloth.size(); ++i) invMass[i] = cloth.invMass(i);
    cm.stretch = stretchOf(clothSprings_[c], positions, invMass);
    cm.deepestPenetration = deepestCloth_[c];
    cm.finite = std::all_of(positions.begin(), positions.end(),
                            [](const Vec3f& p) { return p.allFinite(); });
    m.cloths.push_back(cm);
  }
  for (std::size_t s = 0; s < world.particleSystemCount(); ++s) {
    const ParticleSystem& system = world.particles(world.particleSystemHandle(s));
    ParticleMeasures pm;
    pm.count = system.size();
    double height = 0;
    for (std::size_t i = 0; i < system.size(); ++i) {
      const Vec3f p(system.x()[i], system.y()[i], system.z()[i]);
      pm.finite = pm.finite && p.allFinite();
      pm.inside += world.obstacles().inside(p) ? 1 : 0;
      height += double(p.y());
    }
    pm.meanHeight = pm.count ? height / double(pm.count) : 0;
    m.particles.push_back(pm);
  }
  return m;
}

}  // namespace simdphys

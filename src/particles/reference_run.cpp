// testing/particles.hpp: a particle system stepped by the double-precision reference.
#include <cmath>

#include "src/particles/step.hpp"
#include "testing/particles.hpp"

namespace simdphys::test {

ParticlesD toDouble(const ParticleSystem& s) {
  ParticlesD p;
  for (std::uint32_t i = 0; i < s.size(); ++i) {
    const Handle h = s.handle(i);
    p.x.push_back(s.position(h).cast<double>());
    p.v.push_back(s.velocity(h).cast<double>());
    p.invMass.push_back(s.invMass()[i]);
  }
  // The forces are write-only in the API: read them from the streams.
  const auto& fx = s.field(fields::Particle::fx);
  const auto& fy = s.field(fields::Particle::fy);
  const auto& fz = s.field(fields::Particle::fz);
  for (std::uint32_t i = 0; i < s.size(); ++i) p.force.emplace_back(fx[i], fy[i], fz[i]);
  return p;
}

core::ParticleCounts stepDouble(ParticlesD& p, const ParticleSystem& system, World& world) {
  world.obstacles().update();
  const WorldSettings& w = world.settings();
  std::vector<ObstacleShapeT<double>> shapes;
  for (const ObstacleShape& o : world.obstacles().shapes())
    shapes.push_back(std::visit(
        [](const auto& x) -> ObstacleShapeT<double> {
          if constexpr (std::is_same_v<std::decay_t<decltype(x)>, MeshObstacle>)
            return x;
          else
            return cast<double>(x);
        },
        o));
  const Obstacles& o = world.obstacles();
  const reference::ObstacleSetT<double> set(shapes, o.tree(), o.bounded(), o.boxes(), o.planes());
  // The settings as the float paths take them, with the substep and its damping in double.
  reference::ParticleStep<double> step =
      reference::particleStep<double>(detail::stepParams(system, 0, 0));
  step.dt = double(w.timeStep) / w.substeps;
  step.damping = std::pow(double(system.settings().damping), 1.0 / w.substeps);
  core::ParticleCounts counts;
  for (int sub = 0; sub < w.substeps; ++sub) {
    step.pushOutFirst = p.outsideOf != o.version();
    core::ParticleCounts c;
    for (std::size_t i = 0; i < p.x.size(); ++i)
      reference::stepParticle<double>(step, set, p.x[i], p.v[i], p.invMass[i], p.force[i], c);
    p.outsideOf = c.endPushed == 0 ? o.version() : 0;
    counts += c;
  }
  return counts;
}

core::ParticleCounts stepEveryObstacle(std::vector<Vec3f>& x, std::vector<Vec3f>& v,
                                       const ParticleSystem& system, const World& world) {
  const WorldSettings& w = world.settings();
  const float damping = w.substeps == 1
                            ? system.settings().damping
                            : std::pow(system.settings().damping, 1.0f / float(w.substeps));
  const reference::ParticleStep<float> step = reference::particleStep<float>(
      detail::stepParams(system, w.timeStep / float(w.substeps), damping));
  const reference::ObstacleSetT<float> all(world.obstacles().shapes());
  const auto& f = [&](std::size_t k) { return system.field(k).view(); };
  core::ParticleCounts counts;
  for (int sub = 0; sub < w.substeps; ++sub)
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3f force(f(fields::Particle::fx)[i], f(fields::Particle::fy)[i],
                        f(fields::Particle::fz)[i]);
      reference::stepParticle<float>(step, all, x[i], v[i], system.invMass()[i], force, counts);
    }
  return counts;
}

}  // namespace simdphys::test

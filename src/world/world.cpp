// World (world.hpp): settings, obstacles, particle systems behind handles, and the step.
#include "simdphys/world.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "src/cloth/step.hpp"
#include "src/particles/step.hpp"
#include "src/reference/validate-inl.hpp"
#include "src/rigid/step.hpp"
#include "src/world/obstacle_rows.hpp"

namespace simdphys {

void validate(const WorldSettings& s, const char* where) {
  detail::require(s.timeStep > 0 && s.timeStep <= 1, s.timeStep, where, "timeStep",
                  "must be in (0, 1] s");
  detail::require(s.substeps >= 1 && s.substeps <= 1024, s.substeps, where, "substeps",
                  "must be in [1, 1024]");
  detail::require(s.threads >= 0, s.threads, where, "threads",
                  "must be >= 0 (0: OpenMP's default)");
}

World::World(const WorldSettings& settings) : settings_(settings) { validate(settings, "World"); }

void World::setSettings(const WorldSettings& settings) {
  validate(settings, "World::setSettings");
  settings_ = settings;
}

Handle World::addParticles(const ParticleSettings& settings) {
  validate(settings, "World::addParticles: system " + std::to_string(systems_.size()));
  systems_.emplace_back(settings);
  return systemHandles_.add();
}

void World::removeParticles(Handle h) {
  const std::uint32_t i = systemHandles_.remove(h, "World::removeParticles", "particle system");
  systems_[i] = std::move(systems_.back());
  systems_.pop_back();
}

ParticleSystem& World::particles(Handle h) {
  return systems_[systemHandles_.index(h, "World::particles", "particle system")];
}

const ParticleSystem& World::particles(Handle h) const {
  return systems_[systemHandles_.index(h, "World::particles", "particle system")];
}

Handle World::addCloth(Cloth cloth) {
  cloths_.push_back(std::move(cloth));
  return clothHandles_.add();
}

void World::removeCloth(Handle h) {
  const std::uint32_t i = clothHandles_.remove(h, "World::removeCloth", "cloth");
  cloths_[i] = std::move(cloths_.back());
  cloths_.pop_back();
}

Cloth& World::cloth(Handle h) { return cloths_[clothHandles_.index(h, "World::cloth", "cloth")]; }

const Cloth& World::cloth(Handle h) const {
  return cloths_[clothHandles_.index(h, "World::cloth", "cloth")];
}

void World::step() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  profile_ = {};
  // What may refuse the step is asked before anything moves.
  const float dt = settings_.timeStep / float(settings_.substeps);
  std::vector<int> clothSubsteps;
  for (std::size_t c = 0; c < cloths_.size(); ++c)
    clothSubsteps.push_back(
        detail::clothSubsteps(cloths_[c], dt, "World::step: cloth " + std::to_string(c)));
  if (!systems_.empty()) {
    obstacles_.update();
    const std::vector<core::ObstacleRow> rows = detail::obstacleRows(obstacles_);
    for (int sub = 0; sub < settings_.substeps; ++sub)
      for (ParticleSystem& s : systems_) {
        const float damping = settings_.substeps == 1 ? s.settings().damping
                                                      : std::pow(s.settings().damping,
                                                                 1.0f / float(settings_.substeps));
        const core::ParticleCounts c =
            detail::stepParticles(s, obstacles_, rows, dt, damping, settings_.threads);
        profile_.particles.elements += s.size();
        profile_.contacts += c.contacts;
        profile_.pushedOut += c.pushedOut;
        profile_.bounceLimited += c.bounceLimited;
        profile_.outOfRange += c.outOfRange;
      }
    profile_.particles.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  }
  if (!cloths_.empty()) {
    const auto clothStart = Clock::now();
    const std::vector<core::ObstacleRow> rows = detail::clothRows(obstacles_);
    for (int sub = 0; sub < settings_.substeps; ++sub)
      for (std::size_t c = 0; c < cloths_.size(); ++c)
        profile_.cloth.elements +=
            detail::stepCloth(cloths_[c], obstacles_, rows, dt, clothSubsteps[c], settings_.threads,
                              "World::step: cloth " + std::to_string(c));
    profile_.cloth.seconds = std::chrono::duration<double>(Clock::now() - clothStart).count();
  }
  if (bodies_.size() != 0) {
    const auto bodiesStart = Clock::now();
    for (int sub = 0; sub < settings_.substeps; ++sub) {
      detail::stepBodies(bodies_, obstacles_, dt, settings_.threads, "World::step");
      profile_.bodies.elements += bodies_.size();
    }
    profile_.bodies.seconds = std::chrono::duration<double>(Clock::now() - bodiesStart).count();
  }
  profile_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace simdphys

// Stepping a particle system (particles.hpp) on the active path: the reference, particle by
// particle, or the SIMD kernel, over fixed partitions run in parallel.
#pragma once

#include <span>
#include <vector>

#include "core/particle_step.hpp"
#include "core/view.hpp"
#include "simdphys/obstacles.hpp"
#include "simdphys/particles.hpp"

namespace simdphys::detail {

struct ParticleStreams {
  // The system's fields, whole padded arrays, to step in place.
  static core::View<fields::Particle, float> view(ParticleSystem& system);
  // ParticleSystem::outsideOf_.
  static std::uint64_t& outsideOf(ParticleSystem& system) { return system.outsideOf_; }
};

// A system's settings as the kernels take them, for one substep of length dt with `damping` the
// substep's share of the per-step factor.
core::ParticleStepParams stepParams(const ParticleSystem& system, float dt, float damping);

// One substep of length dt for every particle of the system, with `damping` the substep's share
// of the per-step factor, against the obstacles and their rows (src/world/obstacle_rows.hpp);
// what the particles met.
core::ParticleCounts stepParticles(ParticleSystem& system, const Obstacles& obstacles,
                                   std::span<const core::ObstacleRow> rows, float dt, float damping,
                                   int threads);

}  // namespace simdphys::detail

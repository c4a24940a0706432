// Test support, not public API: the particle step's scalar reference (integrators, collision) for
// the closed-form tests, and a particle system stepped in double precision, the truth that the
// float paths' error is measured against (tests, W4 benchmark).
#pragma once

#include <vector>

#include "simdphys/world.hpp"
#include "src/reference/particles/step-inl.hpp"

namespace simdphys::test {

// A system's particles in double.
struct ParticlesD {
  std::vector<Vec3d> x, v, force;
  std::vector<double> invMass;
  std::uint64_t outsideOf = 0;  // ParticleSystem's: the step's first push-out is skipped alike
};

ParticlesD toDouble(const ParticleSystem& system);

// One world step (its substeps) of the particles by the double reference, with the system's
// settings and the world's obstacles (brought up to date first); what they met.
core::ParticleCounts stepDouble(ParticlesD& particles, const ParticleSystem& system, World& world);

// One world step of particles at x, v (in place; the system's inverse masses and forces) by the
// float reference, testing every obstacle of the world in order, without its tree: what the
// world's answers must equal, bit for bit. Compiled in the library, so that a test needs no
// instance of the reference step of its own.
core::ParticleCounts stepEveryObstacle(std::vector<Vec3f>& x, std::vector<Vec3f>& v,
                                       const ParticleSystem& system, const World& world);

}  // namespace simdphys::test

// W4 `particles` of WORKLOADS.md, generated exactly: N particles at rest above a ground box and a
// tilted ramp, in a World ready to step at 60 Hz (tests, benchmarks, peers).
#pragma once

#include <cstddef>

#include "simdphys/world.hpp"

namespace simdphys::workloads {

inline constexpr int kParticleFrames = 300;  // 5 s at 60 Hz

// W4: a World with the ground and the ramp (in that order) and one particle system of N
// particles from seed 4, x, y, z drawn in that order per particle. WORKLOADS.md does not state a
// friction: 0 (frictionless contacts). The integrator is the library's default.
struct ParticleWorkload {
  World world;
  Handle particles;  // the system's handle in `world`
};
ParticleWorkload makeParticleWorkload(std::size_t n = 100'000);

// The obstacles as W4 states them, in the world's order.
Obb particleGround();
Obb particleRamp();  // rotated 0.35 rad about +z, the axes computed in double and rounded once

}  // namespace simdphys::workloads

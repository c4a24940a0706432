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

// Our variant of W4 with many obstacles (not in WORKLOADS.md): 256 pillars after the ground and
// the ramp, a 16 x 16 grid at a pitch of 1.25 m over x, z in [-9.375, 9.375], standing on the
// ground; by (i + k) mod 3 a sphere (radius 0.4), an AABB (half extents 0.3, 0.6, 0.3) or an OBB
// (half extents 0.35, 0.5, 0.2, turned 0.3 (i + 2k) rad about +y). More than
// Obstacles::kFewObstacles: the particles find them through the obstacles' tree.
void addParticleField(World& world);

// Our variant of W4 with a triangle mesh (not in WORKLOADS.md): after the ground and the ramp, a
// terrain of 64 x 64 quads (8,192 triangles; mesh.hpp's heightfieldMesh) over x, z in [-10, 10],
// its height 0.3 + 0.25 sin(0.9 x) cos(0.7 z) m above the ground, under the ramp's high end.
void addParticleTerrain(World& world);

// The obstacles as W4 states them, in the world's order.
Obb particleGround();
Obb particleRamp();  // rotated 0.35 rad about +z, the axes computed in double and rounded once

}  // namespace simdphys::workloads

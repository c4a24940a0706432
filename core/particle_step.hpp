// What a particle step kernel is given, Eigen-free so that it crosses from the library to the
// kernels (simd/particles.cpp): one system's settings for one substep and the static obstacles as
// flat rows. The scalar reference (src/reference/particles/step-inl.hpp) defines the arithmetic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace simdphys::core {

// ParticleSettings for one substep: dt is the substep, damping its share of the per-step factor.
struct ParticleStepParams {
  // Integrator's values (particles.hpp; src/particles/step.cpp checks that they agree).
  enum Method : std::uint32_t {
    kExplicitEuler,
    kSemiImplicitEuler,
    kVelocityVerlet,
    kPositionVerlet
  };
  std::uint32_t integrator;  // a Method
  float gravity[3];
  float dt, damping, drag, restitution, friction, threshold, skin;
  float limit;  // kMaxCoordinate: a step that would take |x| or |v| past it is not taken
  int maxBounces;
  bool forces;  // the force fields are set or drag is on: a = g + w (f - drag v)
  // Look for particles inside an obstacle before the step: false when the last step left every
  // one outside the same obstacles (its final push-out moved none) and none was set since.
  bool pushOutFirst = true;
};

// One obstacle (obstacles.hpp), in the order the obstacles are tested.
struct ObstacleRow {
  enum Kind : std::uint32_t { kPlane, kSphere, kAabb, kObb, kMesh };
  Kind kind;
  // kPlane: normal (0..2), d (3). kSphere: centre (0..2), radius (3). kAabb: min (0..2), max
  // (3..5). kObb: centre (0..2), half extents (3..5), axes (6..14), column c (the box's local
  // axis c) at 6 + 3 c, as ObbT::axes.col(c). kMesh: none (ObstacleQueries::meshEntry).
  float v[15];
  // A world box around the solid (infinite for a plane), grown by a margin far above the rounding
  // of the exact tests (a thousandth of the solid's size and place, where the rounding is some
  // 1e-6 of them): with the path box's slack (simd/particles.cpp, ObstacleSetT), no path or point
  // outside it meets the solid in any computed test, so it may be culled.
  float lo[3], hi[3];
};

// What the kernels ask of the caller's obstacles. With many of them, the rows near a box come
// from their tree (Obstacles::tree()) rather than from a walk over every row; a mesh's triangles
// are tested by the caller, lane by lane, with the reference's test.
struct ObstacleQueries {
  const void* context;
  // Null without a tree. Sets `rows` to every plane's row and those whose boxes meet any of the
  // n boxes [lo, hi], in ascending order. lo and hi hold the x coordinates of the n boxes, then
  // the y, then the z; a box with lo > hi is empty.
  void (*near)(const void* context, const float* lo, const float* hi, std::size_t n,
               std::vector<std::uint32_t>& rows);
  // Null without meshes. For each of n paths x0 -> x0 + dir whose `live` is non-zero, the first
  // entry into the mesh of row `row`: `hit` 1 or 0, the fraction s of the path and the normal
  // (x, y, z blocks of n, as x0 and dir).
  void (*meshEntry)(const void* context, std::uint32_t row, std::size_t n, const float* x0,
                    const float* dir, const float* live, float* s, float* normal, float* hit);
};

// What the particles met (StepProfile's counters), summed over a kernel call.
struct ParticleCounts {
  std::uint64_t contacts = 0, pushedOut = 0, bounceLimited = 0, outOfRange = 0;
  std::uint64_t endPushed = 0;  // of pushedOut, those by the step's final push-out
  ParticleCounts& operator+=(const ParticleCounts& o) {
    contacts += o.contacts;
    pushedOut += o.pushedOut;
    bounceLimited += o.bounceLimited;
    outOfRange += o.outOfRange;
    endPushed += o.endPushed;
    return *this;
  }
};

}  // namespace simdphys::core

// The particle step's plain-loop baseline (simd/particles.cpp is the kernel): the same step,
// simd/particle_step-inl.hpp, with one float per lane (core/scalar_lanes-inl.hpp), left to the
// compiler for each target. A file of its own so that it compiles beside the kernel.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/particles_autovec.cpp"
#include <hwy/aligned_allocator.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <span>
#include <vector>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/particle_step-inl.hpp"

// ---- baseline ----------------------------------------------------------------------------------
// The same step as a plain loop over the particles, a float per lane, left to the compiler.
core::ParticleCounts StepParticlesAutovec(const ParticlesView& s, std::size_t begin,
                                          std::size_t end, const core::ObstacleRow* rows,
                                          std::size_t n, const core::ObstacleQueries* queries,
                                          const core::ParticleStepParams& params) {
  return stepRange(ScalarLane(), s, begin, end, rows, n, queries, params);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(StepParticlesAutovec, stepParticlesAutovec);
}  // namespace simdphys::simd
#endif

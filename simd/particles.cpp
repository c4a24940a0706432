// The particle step (particles.hpp) over the particle streams, a particle per lane: the push out
// of obstacles a particle starts in (a pass of its own, when one may be), forces, damping, the
// integrator, and the collision of the path travelled with every obstacle row, bounce after
// bounce (or resting contact) while any lane still meets one. A row whose box no live lane's path
// comes near is skipped for the vector: a cull with a margin far above rounding, so it changes no
// result. The step is simd/particle_step-inl.hpp, its lanes simd/particle_lanes-inl.hpp, its
// obstacle rows simd/particle_rows-inl.hpp; this file compiles it as the kernel,
// particles_autovec.cpp as the plain-loop baseline.
// The arithmetic is the scalar reference's (src/reference/particles/step-inl.hpp and the ray hits
// of src/reference/geometry3d/raycast-inl.hpp) operation for operation: Eigen's x + (y + z) sums,
// the same products and quotients in the same order, IEEE square roots and divisions, no
// contraction, std::max's and std::signbit's rules as selects. So every lane ends bit for bit where
// the float reference leaves its particle, and the counters agree exactly. Branches of the
// reference become selects; a lane that has left the bounce loop is masked, not moved.
//
// The step is written once for a lane type: a Highway vector (the kernel) or one float (the
// plain-loop baseline, a particle at a time, left to the compiler).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/particles.cpp"
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

core::ParticleCounts StepParticles(const ParticlesView& s, std::size_t begin, std::size_t end,
                                   const core::ObstacleRow* rows, std::size_t n,
                                   const core::ObstacleQueries* queries,
                                   const core::ParticleStepParams& params) {
  return stepRange(hn::ScalableTag<float>(), s, begin, end, rows, n, queries, params);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(StepParticles, stepParticles);
}  // namespace simdphys::simd
#endif

// The cloth step (cloth.hpp) as a kernel: simd/cloth_step-inl.hpp with Highway vectors, a slot
// per lane (cloth_autovec.cpp compiles the same step a float at a time, the plain-loop baseline).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/cloth.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

// The lanes the step is written in, then the step.
#include "simd/particle_lanes-inl.hpp"

#include "simd/cloth_step-inl.hpp"

void StepCloth(const ClothStepInput& in) {
  stepClothT(hn::ScalableTag<float>(), in.view, in.network, in.grid, in.tethers, in.rows, in.nRows,
             in.queries, in.quads, in.params, in.threads);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(StepCloth, stepCloth);
}  // namespace simdphys::simd
#endif

// The cloth step's plain-loop baseline (simd/cloth.cpp is the kernel): the same step,
// simd/cloth_step-inl.hpp, with one float per lane, left to the compiler for each target. A file
// of its own so that it compiles beside the kernel.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/cloth_autovec.cpp"
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

void StepClothAutovec(const ClothStepInput& in) {
  stepClothT(ScalarLane(), in.view, in.network, in.grid, in.tethers, in.rows, in.nRows, in.queries,
             in.quads, in.params, in.threads);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(StepClothAutovec, stepClothAutovec);
}  // namespace simdphys::simd
#endif

// Sweep and prune within one grid cell, SIMD across the candidates: for box i, the boxes after it
// in minX order are tested a vector at a time until one whole vector starts past maxX[i].
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/sweep.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "core/sweep-inl.hpp"

void SweepCell(const simd::SweepCell& c, std::vector<Pair>& out) {
  const hn::ScalableTag<float> d;
  const std::size_t lanes = hn::Lanes(d);
  for (std::size_t i = 0; i < c.count; ++i) {
    const auto maxX = hn::Set(d, c.maxX[i]);
    const auto minY = hn::Set(d, c.minY[i]), maxY = hn::Set(d, c.maxY[i]);
    const auto minZ = hn::Set(d, c.minZ[i]), maxZ = hn::Set(d, c.maxZ[i]);
    // Reads stay within the cell's sentinels: a vector starts before `count` or the scan stops.
    for (std::size_t j = i + 1; j < c.count; j += lanes) {
      auto inX = hn::Le(hn::LoadU(d, c.minX + j), maxX);
      if (hn::AllFalse(d, inX)) break;
      auto y =
          hn::And(hn::Le(hn::LoadU(d, c.minY + j), maxY), hn::Le(minY, hn::LoadU(d, c.maxY + j)));
      auto z =
          hn::And(hn::Le(hn::LoadU(d, c.minZ + j), maxZ), hn::Le(minZ, hn::LoadU(d, c.maxZ + j)));
      auto hit = hn::And(inX, hn::And(y, z));
      if (hn::AllFalse(d, hit)) continue;
      std::uint8_t bytes[8] = {};
      hn::StoreMaskBits(d, hit, bytes);
      std::uint64_t bits;
      std::memcpy(&bits, bytes, sizeof(bits));
      for (; bits; bits &= bits - 1) {
        std::size_t k = j + std::size_t(__builtin_ctzll(bits));
        if (ownsPair(c, i, k)) out.push_back(orderedPair(c.id[i], c.id[k]));
      }
    }
  }
}

void SweepCellAutovec(const simd::SweepCell& c, std::vector<Pair>& out) { sweepScalar(c, out); }

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(SweepCell, sweepCell);
SIMDPHYS_EXPORT(SweepCellAutovec, sweepCellAutovec);
}  // namespace simdphys::simd
#endif

// The 2D broadphase kernels: sweep and prune over one band's rectangles sorted by minX (for
// rectangle i, the candidates after it are tested a vector at a time until a whole vector starts
// past maxX[i]),
// and the brute force over all pairs (for rectangle i, every rectangle after it, a vector at a
// time). Each also as the plain loop left to the auto-vectoriser.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/broadphase2d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "core/sweep-inl.hpp"

// Calls `emit(k)` for each set lane k of the mask, lowest first.
template <class D, class M, class Emit>
HWY_INLINE void forEachLane(D d, M mask, Emit emit) {
  std::uint8_t bytes[8] = {};
  hn::StoreMaskBits(d, mask, bytes);
  std::uint64_t bits;
  std::memcpy(&bits, bytes, sizeof(bits));
  for (; bits; bits &= bits - 1) emit(std::size_t(__builtin_ctzll(bits)));
}

void SweepRects2dAutovec(const SortedRects2d& c, std::vector<Pair>& out) { sweepScalar(c, out); }

void SweepRects2d(const SortedRects2d& c, std::vector<Pair>& out) {
  const hn::ScalableTag<float> d;
  const std::size_t lanes = hn::Lanes(d);
  for (std::size_t i = 0; i < c.count; ++i) {
    const auto maxX = hn::Set(d, c.maxX[i]);
    const auto minY = hn::Set(d, c.minY[i]), maxY = hn::Set(d, c.maxY[i]);
    // Reads stay within the sentinels: a vector starts before `count` or the scan stops.
    for (std::size_t j = i + 1; j < c.count; j += lanes) {
      const auto inX = hn::Le(hn::LoadU(d, c.minX + j), maxX);
      if (hn::AllFalse(d, inX)) break;
      const auto hit = hn::And(inX, hn::And(hn::Le(hn::LoadU(d, c.minY + j), maxY),
                                            hn::Le(minY, hn::LoadU(d, c.maxY + j))));
      if (hn::AllFalse(d, hit)) continue;
      forEachLane(d, hit, [&](std::size_t k) {
        if (ownsPair(c, i, j + k)) out.push_back(orderedPair(c.id[i], c.id[j + k]));
      });
    }
  }
}

// The closed overlap of rectangle i with rectangles j.. of the stream (intersects(Rect, Rect)).
void BruteRects2dAutovec(const RectsView& v, std::vector<Pair>& out) {
  for (std::size_t i = 0; i < v.count; ++i)
    for (std::size_t j = i + 1; j < v.count; ++j)
      if (v[fields::Rect::minX][j] <= v[fields::Rect::maxX][i] &&
          v[fields::Rect::minX][i] <= v[fields::Rect::maxX][j] &&
          v[fields::Rect::minY][j] <= v[fields::Rect::maxY][i] &&
          v[fields::Rect::minY][i] <= v[fields::Rect::maxY][j])
        out.push_back({std::uint32_t(i), std::uint32_t(j)});
}

void BruteRects2d(const RectsView& v, std::vector<Pair>& out) {
  const hn::ScalableTag<float> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const std::size_t lanes = hn::Lanes(d);
  for (std::size_t i = 0; i < v.count; ++i) {
    const auto minX = hn::Set(d, v[fields::Rect::minX][i]),
               minY = hn::Set(d, v[fields::Rect::minY][i]);
    const auto maxX = hn::Set(d, v[fields::Rect::maxX][i]),
               maxY = hn::Set(d, v[fields::Rect::maxY][i]);
    auto overlap = [&](std::size_t j) {
      return hn::And(hn::And(hn::Le(hn::Load(d, v[fields::Rect::minX] + j), maxX),
                             hn::Le(minX, hn::Load(d, v[fields::Rect::maxX] + j))),
                     hn::And(hn::Le(hn::Load(d, v[fields::Rect::minY] + j), maxY),
                             hn::Le(minY, hn::Load(d, v[fields::Rect::maxY] + j))));
    };
    auto emit = [&](std::size_t j) {
      return [&out, i, j](std::size_t k) {
        out.push_back({std::uint32_t(i), std::uint32_t(j + k)});
      };
    };
    // The aligned vector holding i + 1 keeps only the lanes after i; padding lanes are empty
    // rectangles, which overlap nothing.
    std::size_t j = (i + 1) / lanes * lanes;
    if (j < v.padded) {
      const auto after =
          hn::RebindMask(d, hn::Gt(hn::Iota(du, std::uint32_t(j)), hn::Set(du, std::uint32_t(i))));
      const auto hit = hn::And(after, overlap(j));
      if (!hn::AllFalse(d, hit)) forEachLane(d, hit, emit(j));
    }
    for (j += lanes; j < v.padded; j += lanes) {
      const auto hit = overlap(j);
      if (!hn::AllFalse(d, hit)) forEachLane(d, hit, emit(j));
    }
  }
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(SweepRects2d, sweepRects2d);
SIMDPHYS_EXPORT(SweepRects2dAutovec, sweepRects2dAutovec);
SIMDPHYS_EXPORT(BruteRects2d, bruteRects2d);
SIMDPHYS_EXPORT(BruteRects2dAutovec, bruteRects2dAutovec);
}  // namespace simdphys::simd
#endif

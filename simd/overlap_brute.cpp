// Brute-force box overlap counting: every query against every box, the boxes in L1-sized blocks
// so each block is read from memory once for all queries.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/overlap_brute.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/box_overlap-inl.hpp"

constexpr std::size_t kBlock = 1024;  // 24 KiB of boxes

template <class CountBlock>
std::uint64_t blocked(const BoxesView& b, const Box* queries, std::size_t nQueries,
                      CountBlock countBlock) {
  std::uint64_t total = 0;
  for (std::size_t begin = 0; begin < b.padded; begin += kBlock) {
    std::size_t end = std::min(b.padded, begin + kBlock);
    for (std::size_t q = 0; q < nQueries; ++q) total += countBlock(queries[q], begin, end);
  }
  return total;
}

std::uint64_t CountOverlapsBrute(const BoxesView& b, const Box* queries, std::size_t nQueries) {
  const hn::ScalableTag<float> d;
  const hn::RebindToSigned<decltype(d)> di;
  return blocked(b, queries, nQueries, [&](const Box& q, std::size_t begin, std::size_t end) {
    const BoxOverlap overlap(d, q);
    // Counts accumulate per lane (a true mask lane is -1) and are reduced once per block.
    auto counts = hn::Zero(di);
    for (std::size_t i = begin; i < end; i += hn::Lanes(d)) {
      auto hit = overlap(d, b[fields::Box::minX], b[fields::Box::minY], b[fields::Box::minZ],
                         b[fields::Box::maxX], b[fields::Box::maxY], b[fields::Box::maxZ], i);
      counts = hn::Sub(counts, hn::VecFromMask(di, hn::RebindMask(di, hit)));
    }
    return std::uint64_t(hn::GetLane(hn::SumOfLanes(di, counts)));
  });
}

// Baseline: the same loop in plain C++, compiled for this target and left to the compiler.
std::uint64_t CountOverlapsBruteAutovec(const BoxesView& b, const Box* queries,
                                        std::size_t nQueries) {
  return blocked(b, queries, nQueries, [&](const Box& q, std::size_t begin, std::size_t end) {
    std::uint32_t count = 0;
    for (std::size_t i = begin; i < end; ++i)
      count += (b[fields::Box::minX][i] <= q.maxX) & (q.minX <= b[fields::Box::maxX][i]) &
               (b[fields::Box::minY][i] <= q.maxY) & (q.minY <= b[fields::Box::maxY][i]) &
               (b[fields::Box::minZ][i] <= q.maxZ) & (q.minZ <= b[fields::Box::maxZ][i]);
    return std::uint64_t(count);
  });
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(CountOverlapsBrute, countOverlapsBrute);
SIMDPHYS_EXPORT(CountOverlapsBruteAutovec, countOverlapsBruteAutovec);
}  // namespace simdphys::simd
#endif

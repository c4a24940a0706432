// The 2D broadphase: sweep and prune (in horizontal bands, or one), brute force and the quadtree
// behind one call, all returning the pairs sorted.
#include "simdphys/geometry2d/broadphase.hpp"

#include <algorithm>
#include <limits>

#include "../broadphase/pair_finder.hpp"
#include "../core/radix_sort.hpp"
#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/quadtree.hpp"
// The brute-force pairs call intersects per pair: its definition, so that it inlines.
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "src/views.hpp"

namespace simdphys {
namespace {

// Rectangles per band the banded sweep aims at, and the least band height in mean rectangle
// heights: bands short enough that the candidates along x stay few (a single band's grow with the
// square root of the count at constant density), tall enough that rectangles in two bands stay
// rare. Chosen by measurement on W7 (docs/geometry2d.md).
constexpr double kRectsPerBand = 256;
constexpr double kMinBandInRects = 16;

struct Bands {
  int count = 1;
  float origin = 0, scale = 0;
  // Monotonic in y, so a rectangle's bands are those from band(minY) to band(maxY). Clamped in
  // float before the conversion: the offset overflows to inf for rectangles spanning more than
  // FLT_MAX, and converting a float beyond int's range is undefined.
  // NaN-safe as PairFinder's grid cell (src/broadphase/pairs.cpp): 0 * inf for a denormal extent.
  int band(float y) const {
    const float v = (y - origin) * scale;
    return v > 0 ? int(std::min(v, float(count - 1))) : 0;
  }
};

Bands chooseBands(const RectStream& r, bool banded) {
  Bands b;
  const std::size_t n = r.size();
  if (!banded || n == 0) return b;
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  double height = 0;
  using F = fields::Rect;
  for (std::size_t i = 0; i < n; ++i) {
    lo = std::min(lo, r.field(F::minY)[i]), hi = std::max(hi, r.field(F::maxY)[i]);
    height += double(r.field(F::maxY)[i]) - r.field(F::minY)[i];
  }
  const double extent = double(hi) - lo, meanHeight = height / double(n);
  double count = double(n) / kRectsPerBand;
  if (meanHeight > 0) count = std::min(count, extent / (kMinBandInRects * meanHeight));
  b.count = int(std::clamp(count, 1.0, 65536.0));
  b.origin = lo;
  b.scale = hi > lo ? float(b.count / extent) : 0.0f;
  return b;
}

}  // namespace

template <>
struct PairFinder2d::Scratch {
  RadixSorter sorter;
  // The bands one after the other, each sorted by minX and followed by kStreamPad sentinels that
  // start past everything and overlap nothing.
  std::vector<float> minX, maxX, minY, maxY;
  std::vector<std::uint32_t> id;
  std::vector<std::int32_t> loBand, hiBand, bandLo;
  std::vector<std::uint32_t> begin, cursor;  // per band, into the arrays above
  std::vector<Pair> unsorted;                // the bands' pairs not yet dealt
  PairSorter pairSorter;

  // Sorts all rectangles by minX once (ties in index order), then deals them out to their bands in
  // that order, so each band comes out sorted.
  void fillBands(const RectStream& r, const Bands& b) {
    const std::size_t n = r.size(), bands = std::size_t(b.count);
    loBand.resize(n), hiBand.resize(n);
    begin.assign(bands + 1, 0);
    using F = fields::Rect;
    for (std::size_t i = 0; i < n; ++i) {
      loBand[i] = b.band(r.field(F::minY)[i]), hiBand[i] = b.band(r.field(F::maxY)[i]);
      for (int k = loBand[i]; k <= hiBand[i]; ++k) ++begin[std::size_t(k) + 1];
    }
    for (std::size_t k = 0; k < bands; ++k) begin[k + 1] += begin[k] + std::uint32_t(kStreamPad);
    const float inf = std::numeric_limits<float>::infinity();
    const std::size_t size = begin[bands];
    minX.assign(size, inf), minY.assign(size, inf), maxX.assign(size, -inf),
        maxY.assign(size, -inf);
    id.assign(size, 0), bandLo.assign(size, 0);
    cursor.assign(begin.begin(), begin.end() - 1);
    const auto& order = sorter.sort(r.field(F::minX).data(), n);
    for (const std::uint32_t i : order)
      for (int k = loBand[i]; k <= hiBand[i]; ++k) {
        const std::uint32_t at = cursor[std::size_t(k)]++;
        minX[at] = r.field(F::minX)[i], maxX[at] = r.field(F::maxX)[i];
        minY[at] = r.field(F::minY)[i], maxY[at] = r.field(F::maxY)[i];
        id[at] = i, bandLo[at] = loBand[i];
      }
  }

  simd::SortedRects2d band(std::size_t k) const {
    const std::size_t first = begin[k], count = begin[k + 1] - first - kStreamPad;
    return {minX.data() + first,
            maxX.data() + first,
            minY.data() + first,
            maxY.data() + first,
            id.data() + first,
            bandLo.data() + first,
            count,
            std::int32_t(k)};
  }

  template <class Sweep>
  void sweep(const RectStream& r, std::vector<Pair>& pairs, bool banded, Sweep sweepKernel) {
    unsorted.clear();
    const Bands b = chooseBands(r, banded);
    fillBands(r, b);
    // The bands' pairs go to the sorter a chunk's worth at a time, while in cache.
    const std::size_t bands = std::size_t(b.count);
    pairSorter.begin(bands, r.size());
    for (std::size_t k = 0, part = 0; k < bands; ++k) {
      sweepKernel(band(k), unsorted);
      if (unsorted.size() >= PairSorter::kChunk || k + 1 == bands) {
        pairSorter.deal(part++, unsorted);
        unsorted.clear();
      }
    }
    pairSorter.finish(pairs);
  }
};

namespace {

void bruteReference(const RectStream& r, std::vector<Pair>& pairs) {
  pairs.clear();
  for (std::uint32_t i = 0; i < r.size(); ++i) {
    const Rect a = r[i];
    for (std::uint32_t j = i + 1; j < r.size(); ++j)
      if (intersects(a, r[j])) pairs.push_back({i, j});
  }
}

void quadtreePairs(const RectStream& r, std::vector<Pair>& pairs) {
  pairs.clear();
  if (r.size() == 0) return;
  Rect bounds = r[0];
  for (std::size_t i = 1; i < r.size(); ++i) {
    bounds.min = bounds.min.cwiseMin(r[i].min);
    bounds.max = bounds.max.cwiseMax(r[i].max);
  }
  Quadtree tree(bounds);
  for (std::uint32_t i = 0; i < r.size(); ++i) tree.insert(i, r[i]);
  pairs = tree.pairs();
}

}  // namespace

namespace {
// kAuto's choice for this many rectangles; other methods as asked.
PairMethod2d resolved(PairMethod2d method, const RectStream& r) {
  if (method != PairMethod2d::kAuto) return method;
  return r.size() < kBruteBelow ? PairMethod2d::kBrute : PairMethod2d::kBandedSweep;
}
}  // namespace

template <>
void PairFinder2d::findWith(const RectStream& r, std::vector<Pair>& pairs, PairMethod2d method) {
  const PairMethod2d m = resolved(method, r);
  const bool plain = detail::plainLoopsActive();
  const auto& sweepKernel = plain ? simd::sweepRects2dAutovec : simd::sweepRects2d;
  const bool reference = !plain && referencePathActive();
  switch (m) {
    case PairMethod2d::kAuto:  // resolved above
      break;
    case PairMethod2d::kQuadtree:
      if (plain) throw Error("PairFinder2d: the quadtree method has no plain-loop form");
      return quadtreePairs(r, pairs);
    case PairMethod2d::kBrute:
      if (reference) return bruteReference(r, pairs);
      pairs.clear();
      return (plain ? simd::bruteRects2dAutovec : simd::bruteRects2d)(view(r), pairs);
    case PairMethod2d::kBandedSweep:
    case PairMethod2d::kSweep: {
      const bool banded = m == PairMethod2d::kBandedSweep;
      if (reference)
        return scratch_->sweep(r, pairs, banded, reference::sweepScalar<simd::SortedRects2d>);
      return scratch_->sweep(r, pairs, banded, sweepKernel);
    }
  }
  throw Error("PairFinder2d::find: unknown method " + std::to_string(int(method)));
}

template class PairFinderOf<RectStream, PairMethod2d>;

void findPairs(const RectStream& r, std::vector<Pair>& pairs, PairMethod2d method) {
  PairFinder2d().find(r, pairs, method);
}

}  // namespace simdphys

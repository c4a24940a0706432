// The 2D broadphase: sweep and prune, brute force and the quadtree behind one call, all returning
// the pairs sorted.
#include "simdphys/geometry2d/broadphase.hpp"

#include <algorithm>
#include <limits>

#include "../core/radix_sort.hpp"
#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/quadtree.hpp"
#include "views.hpp"

namespace simdphys {
namespace reference {
#include "sweep-inl.hpp"
}  // namespace reference

struct PairFinder2d::Scratch {
  RadixSorter sorter;
  std::vector<float> minX, maxX, minY, maxY;
  std::vector<std::uint32_t> id;
  std::vector<std::uint32_t> start;  // counting sort of pairs: the first slot of each `a`
  std::vector<Pair> sorted;

  // The rectangles sorted by minX (ties in index order) as the sweep reads them, followed by
  // kStreamPad sentinels that start past everything and overlap nothing.
  simd::SortedRects2d sortByMinX(const RectStream& r) {
    const std::size_t n = r.size(), size = n + kStreamPad;
    const float inf = std::numeric_limits<float>::infinity();
    minX.assign(size, inf), minY.assign(size, inf);
    maxX.assign(size, -inf), maxY.assign(size, -inf);
    id.assign(size, 0);
    const std::vector<std::uint32_t>& order = sorter.sort(r.minX().data(), n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = order[k];
      minX[k] = r.minX()[i], maxX[k] = r.maxX()[i], minY[k] = r.minY()[i], maxY[k] = r.maxY()[i];
      id[k] = i;
    }
    return {minX.data(), maxX.data(), minY.data(), maxY.data(), id.data(), n};
  }

  // Sorts pairs ascending: a counting sort on a (a < n), then each run of equal a, which holds the
  // few partners of one rectangle, by b.
  void sortPairs(std::vector<Pair>& pairs, std::size_t n) {
    start.assign(n + 1, 0);
    for (const Pair& p : pairs) ++start[p.a + 1];
    for (std::size_t a = 0; a < n; ++a) start[a + 1] += start[a];
    sorted.resize(pairs.size());
    for (const Pair& p : pairs) sorted[start[p.a]++] = p;
    for (auto run = sorted.begin(); run != sorted.end();) {
      const auto end =
          std::find_if(run, sorted.end(), [&](const Pair& p) { return p.a != run->a; });
      std::sort(run, end);
      run = end;
    }
    pairs.swap(sorted);
  }

  template <class Sweep>
  void sweep(const RectStream& r, std::vector<Pair>& pairs, Sweep sweepKernel) {
    pairs.clear();
    sweepKernel(sortByMinX(r), pairs);
    sortPairs(pairs, r.size());
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
  Rect bounds{{r.minX()[0], r.minY()[0]}, {r.maxX()[0], r.maxY()[0]}};
  for (std::size_t i = 1; i < r.size(); ++i) {
    bounds.min = bounds.min.cwiseMin(Vec2f(r.minX()[i], r.minY()[i]));
    bounds.max = bounds.max.cwiseMax(Vec2f(r.maxX()[i], r.maxY()[i]));
  }
  Quadtree tree(bounds);
  for (std::uint32_t i = 0; i < r.size(); ++i) tree.insert(i, r[i]);
  pairs = tree.pairs();
}

}  // namespace

PairFinder2d::PairFinder2d() : scratch_(std::make_unique<Scratch>()) {}
PairFinder2d::~PairFinder2d() = default;
PairFinder2d::PairFinder2d(PairFinder2d&&) noexcept = default;
PairFinder2d& PairFinder2d::operator=(PairFinder2d&&) noexcept = default;

void PairFinder2d::find(const RectStream& r, std::vector<Pair>& pairs, PairMethod2d method) {
  switch (method) {
    case PairMethod2d::kQuadtree:
      return quadtreePairs(r, pairs);
    case PairMethod2d::kBrute:
      if (referencePathActive()) return bruteReference(r, pairs);
      pairs.clear();
      return simd::bruteRects2d(view(r), pairs);
    case PairMethod2d::kSweep:
      if (referencePathActive()) return scratch_->sweep(r, pairs, reference::sweepRects2dScalar);
      return scratch_->sweep(r, pairs, [](const simd::SortedRects2d& s, std::vector<Pair>& out) {
        simd::sweepRects2d(s, out);
      });
  }
  throw Error("PairFinder2d::find: unknown method " + std::to_string(int(method)));
}

void findPairs(const RectStream& r, std::vector<Pair>& pairs, PairMethod2d method) {
  PairFinder2d().find(r, pairs, method);
}

void detail::findPairs2dAutovec(PairFinder2d& finder, const RectStream& r, std::vector<Pair>& pairs,
                                PairMethod2d method) {
  if (method == PairMethod2d::kBrute) {
    pairs.clear();
    return simd::bruteRects2d(view(r), pairs, simd::Loop::kAutovec);
  }
  if (method != PairMethod2d::kSweep)
    throw Error("findPairs2dAutovec: only the sweep and the brute force have a plain loop");
  finder.scratch_->sweep(r, pairs, [](const simd::SortedRects2d& s, std::vector<Pair>& out) {
    simd::sweepRects2d(s, out, simd::Loop::kAutovec);
  });
}

}  // namespace simdphys

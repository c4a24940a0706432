// The 2D broadphase: every overlapping pair among many axis-aligned rectangles. Circles and
// oriented rectangles enter it by their bounding rectangles (boundingRect of primitives.hpp); the
// candidate pairs are then narrowed by the scalar intersects() of collisions.hpp.
#pragma once

#include <memory>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry2d/streams.hpp"

namespace simdphys {

enum class PairMethod2d {
  // The default: kBrute below kBruteBelow rectangles, kBandedSweep from there (the crossover
  // measured in docs/geometry2d.md).
  kAuto,
  // Sweep and prune along x inside horizontal bands of a few rectangle heights each: sorted by
  // minX, each rectangle tests the ones starting before its maxX on y, a SIMD vector at a time. A
  // pair in several bands is found in the one holding the low edge of its intersection, so once.
  // The fastest measured from a few hundred rectangles up (docs/geometry2d.md).
  kBandedSweep,
  // The same sweep in a single band: the textbook sweep and prune. Its candidates along x grow
  // with the square root of the count at constant density.
  kSweep,
  // Every pair tested, a SIMD vector at a time: no sort, no structure. The fastest below about
  // 200 rectangles.
  kBrute,
  // The quadtree of quadtree.hpp, built from the rectangles (bounds: their containing rectangle,
  // default Config), then its pairs(). Scalar on every path.
  kQuadtree,
};

// Below this many rectangles kAuto tests every pair: measured on AVX-512, brute force takes 1.5 us
// for 100 rectangles against 3.6 us for the banded sweep, and 7.4 us against 6.8 us for 300.
inline constexpr std::size_t kBruteBelow = 200;

class PairFinder2d;
namespace detail {
// Benchmark baseline: the sweeps or the brute force as plain loops left to the auto-vectoriser.
void findPairs2dAutovec(PairFinder2d&, const RectStream&, std::vector<Pair>&, PairMethod2d);
}  // namespace detail

// Finds all overlapping pairs (closed test: touching rectangles overlap) among rectangles, each
// once as (a, b) with a < b, sorted ascending (by a, then b): every method and every path returns
// the same vector. Keeps its working memory from call to call, as a world's broadphase does from
// step to step. Runs on the active path.
class PairFinder2d {
 public:
  PairFinder2d();
  ~PairFinder2d();
  PairFinder2d(PairFinder2d&&) noexcept;
  PairFinder2d& operator=(PairFinder2d&&) noexcept;

  void find(const RectStream& rects, std::vector<Pair>& pairs,
            PairMethod2d method = PairMethod2d::kAuto);

 private:
  friend void detail::findPairs2dAutovec(PairFinder2d&, const RectStream&, std::vector<Pair>&,
                                         PairMethod2d);
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
};

// One-off form of PairFinder2d::find.
void findPairs(const RectStream& rects, std::vector<Pair>& pairs,
               PairMethod2d method = PairMethod2d::kAuto);

}  // namespace simdphys

// The 2D broadphase: every overlapping pair among many axis-aligned rectangles. Circles and
// oriented rectangles enter it by their bounding rectangles (boundingRect of primitives.hpp); the
// candidate pairs are then narrowed by the scalar intersects() of collisions.hpp.
#pragma once

#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry2d/streams.hpp"
#include "simdphys/pair_finder.hpp"

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

// The 2D pair finder (pair_finder.hpp; touching rectangles overlap). Runs on the active path.
using PairFinder2d = PairFinderOf<RectStream, PairMethod2d>;

// One-off form of PairFinder2d::find.
void findPairs(const RectStream& rects, std::vector<Pair>& pairs,
               PairMethod2d method = PairMethod2d::kAuto);

}  // namespace simdphys

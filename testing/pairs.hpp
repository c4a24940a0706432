// Test support, not public API: the pair finders with their kernels run as the plain loops left
// to the compiler's auto-vectoriser (on the best SIMD target, whatever the active path), the
// second baseline the benchmarks quote SIMD speed-ups against and the tests check against brute
// force.
#pragma once

#include <vector>

#include "simdphys/broadphase.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "testing/plain_loops.hpp"

namespace simdphys::test {

// A pair finder whose find() runs the plain loops. Throws Error for a method without one (the
// 3D BVH, the 2D quadtree).
template <class Finder>
class PlainLoop : public Finder {
 public:
  template <class Stream, class Method>
  void find(const Stream& stream, std::vector<Pair>& pairs, Method method) {
    const ScopedPlainLoops plain;
    Finder::find(stream, pairs, method);
  }
};

using PlainLoopPairFinder = PlainLoop<PairFinder>;
using PlainLoopPairFinder2d = PlainLoop<PairFinder2d>;

}  // namespace simdphys::test

// Internal: the broadphase driver with the plain-loop sweep, the auto-vectoriser baseline the
// benchmarks compare the SIMD sweep against.
#pragma once

#include <vector>

#include "simdphys/broadphase.hpp"

namespace simdphys::detail {
void findPairsAutovec(PairFinder& finder, const BoxStream& boxes, std::vector<Pair>& pairs);
}  // namespace simdphys::detail

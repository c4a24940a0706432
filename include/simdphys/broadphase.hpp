// Broadphase: which boxes of a stream overlap each other, and brute-force box queries.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/geometry3d.hpp"
#include "simdphys/pair_finder.hpp"

namespace simdphys {

enum class PairMethod {
  // Sweep and prune along x inside the cells of a coarse y-z grid (the default: fastest
  // measured, see docs/broadphase.md). A pair spanning several cells is found in the one that
  // holds the low corner of the boxes' intersection, so it is reported once.
  kGridSweep,
  // Plain sweep and prune along x over all boxes: the grid method with one cell.
  kSweep,
  // Each box queried against a BVH of all boxes.
  kBvh,
};

// The 3D pair finder (pair_finder.hpp). Cells are swept in parallel with OpenMP.
using PairFinder = PairFinderOf<BoxStream, PairMethod>;

// One-off form of PairFinder::find.
void findPairs(const BoxStream& boxes, std::vector<Pair>& pairs,
               PairMethod method = PairMethod::kGridSweep);

// The number of boxes each query overlaps, summed over the queries, testing every box: the
// baseline a tree query (Bvh::countOverlaps) is measured against. Runs on the active path.
std::uint64_t countOverlapsBrute(const BoxStream& boxes, std::span<const Aabb> queries);

}  // namespace simdphys

// Broadphase: which boxes of a stream overlap each other, and brute-force box queries.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "simdphys/geometry3d.hpp"

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

// Finds all overlapping pairs (closed test) among boxes, each once as (a, b) with a < b. The
// order is deterministic: it depends only on the input and the method, not on the path or the
// number of threads (grid row by row, cell by cell, and within a cell in sweep order). Cells are
// swept in parallel with OpenMP. Keeps its working memory from call to call, as a world's
// broadphase does from step to step.
class PairFinder;
namespace detail {
void findPairsAutovec(PairFinder&, const BoxStream&, std::vector<Pair>&);  // benchmark baseline
}

class PairFinder {
 public:
  PairFinder();
  ~PairFinder();
  PairFinder(PairFinder&&) noexcept;
  PairFinder& operator=(PairFinder&&) noexcept;

  // Replaces `pairs` with the overlapping pairs of `boxes`. Runs on the active path.
  void find(const BoxStream& boxes, std::vector<Pair>& pairs,
            PairMethod method = PairMethod::kGridSweep);

 private:
  friend void detail::findPairsAutovec(PairFinder&, const BoxStream&, std::vector<Pair>&);
  struct Scratch;
  std::unique_ptr<Scratch> scratch_;
};

// One-off form of PairFinder::find.
void findPairs(const BoxStream& boxes, std::vector<Pair>& pairs,
               PairMethod method = PairMethod::kGridSweep);

// The number of boxes each query overlaps, summed over the queries, testing every box: the
// baseline a tree query (Bvh::countOverlaps) is measured against. Runs on the active path.
std::uint64_t countOverlapsBrute(const BoxStream& boxes, std::span<const Aabb> queries);

}  // namespace simdphys

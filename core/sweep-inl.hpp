// The sweep over one cell of boxes or rectangles sorted by minX (simd::SweepCell, a cell of the 3D
// grid; simd::SortedRects2d, a 2D band), scalar: the reference path, and (included inside each
// SIMD target's namespace) the plain loop left to the auto-vectoriser. No include guard, by
// design. The includer provides the cell types and Pair, and includes <algorithm> and <vector>.

inline ::simdphys::Pair orderedPair(std::uint32_t a, std::uint32_t b) {
  return a < b ? ::simdphys::Pair{a, b} : ::simdphys::Pair{b, a};
}

// Whether elements i and j of the cell overlap on the axes other than x (closed).
inline bool overlapsAcross(const ::simdphys::simd::SweepCell& c, std::size_t i, std::size_t j) {
  return c.minY[j] <= c.maxY[i] && c.minY[i] <= c.maxY[j] && c.minZ[j] <= c.maxZ[i] &&
         c.minZ[i] <= c.maxZ[j];
}
inline bool overlapsAcross(const ::simdphys::simd::SortedRects2d& c, std::size_t i, std::size_t j) {
  return c.minY[j] <= c.maxY[i] && c.minY[i] <= c.maxY[j];
}

// True when the pair (i, j) of the cell is reported by this cell (see kernels.hpp).
inline bool ownsPair(const ::simdphys::simd::SweepCell& c, std::size_t i, std::size_t j) {
  return std::max(c.loY[i], c.loY[j]) == c.cellY && std::max(c.loZ[i], c.loZ[j]) == c.cellZ;
}
inline bool ownsPair(const ::simdphys::simd::SortedRects2d& c, std::size_t i, std::size_t j) {
  return std::max(c.loBand[i], c.loBand[j]) == c.band;
}

template <class Cell>
inline void sweepScalar(const Cell& c, std::vector<::simdphys::Pair>& out) {
  for (std::size_t i = 0; i < c.count; ++i) {
    // Sorted by minX: the first element starting past maxX[i] ends the scan (a sentinel at the
    // latest, minX = +inf).
    for (std::size_t j = i + 1; c.minX[j] <= c.maxX[i]; ++j)
      if (overlapsAcross(c, i, j) && ownsPair(c, i, j))
        out.push_back(orderedPair(c.id[i], c.id[j]));
  }
}

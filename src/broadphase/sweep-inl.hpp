// The sweep over one grid cell, scalar: the reference path, and (included inside each SIMD
// target's namespace) the plain loop left to the auto-vectoriser. No include guard, by design.
// The includer provides simd::SweepCell and Pair.

// True when the pair (i, j) of the cell is reported by this cell (see kernels.hpp).
inline bool ownsPair(const ::simdphys::simd::SweepCell& c, std::size_t i, std::size_t j) {
  return std::max(c.loY[i], c.loY[j]) == c.cellY && std::max(c.loZ[i], c.loZ[j]) == c.cellZ;
}

inline ::simdphys::Pair orderedPair(std::uint32_t a, std::uint32_t b) {
  return a < b ? ::simdphys::Pair{a, b} : ::simdphys::Pair{b, a};
}

inline void sweepCellScalar(const ::simdphys::simd::SweepCell& c,
                            std::vector<::simdphys::Pair>& out) {
  for (std::size_t i = 0; i < c.count; ++i) {
    // Boxes are sorted by minX: the first one starting past maxX[i] ends the scan.
    for (std::size_t j = i + 1; c.minX[j] <= c.maxX[i]; ++j) {
      bool hit = c.minY[j] <= c.maxY[i] && c.minY[i] <= c.maxY[j] && c.minZ[j] <= c.maxZ[i] &&
                 c.minZ[i] <= c.maxZ[j];
      if (hit && ownsPair(c, i, j)) out.push_back(orderedPair(c.id[i], c.id[j]));
    }
  }
}

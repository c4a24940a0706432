// The 2D sweep, scalar: the reference path, and (included inside each SIMD target's namespace) the
// plain loop left to the auto-vectoriser. No include guard, by design. The includer provides
// simd::SortedRects2d and Pair, and includes <algorithm>.

inline ::simdphys::Pair orderedPair2d(std::uint32_t a, std::uint32_t b) {
  return a < b ? ::simdphys::Pair{a, b} : ::simdphys::Pair{b, a};
}

// True when the pair (i, j) of the band is reported by this band (see kernels.hpp).
inline bool bandOwnsPair(const ::simdphys::simd::SortedRects2d& c, std::size_t i, std::size_t j) {
  return std::max(c.loBand[i], c.loBand[j]) == c.band;
}

inline void sweepRects2dScalar(const ::simdphys::simd::SortedRects2d& c,
                               std::vector<::simdphys::Pair>& out) {
  for (std::size_t i = 0; i < c.count; ++i) {
    // Sorted by minX: the first rectangle starting past maxX[i] ends the scan (a sentinel at the
    // latest, minX = +inf).
    for (std::size_t j = i + 1; c.minX[j] <= c.maxX[i]; ++j)
      if (c.minY[j] <= c.maxY[i] && c.minY[i] <= c.maxY[j] && bandOwnsPair(c, i, j))
        out.push_back(orderedPair2d(c.id[i], c.id[j]));
  }
}

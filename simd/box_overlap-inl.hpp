// The closed box-overlap test of one query box against rows of boxes, included inside each
// target's namespace (no include guard, by design). Used by the brute-force count (rows of a
// stream) and by the BVH (the rows of a node).

template <class D>
class BoxOverlap {
 public:
  BoxOverlap(D d, const Box& q)
      : minX_(hn::Set(d, q.minX)),
        minY_(hn::Set(d, q.minY)),
        minZ_(hn::Set(d, q.minZ)),
        maxX_(hn::Set(d, q.maxX)),
        maxY_(hn::Set(d, q.maxY)),
        maxZ_(hn::Set(d, q.maxZ)) {}

  // Lanes i.. of the six rows whose box overlaps the query (touching counts).
  auto operator()(D d, const float* minX, const float* minY, const float* minZ, const float* maxX,
                  const float* maxY, const float* maxZ, std::size_t i) const {
    auto x = hn::And(hn::Le(hn::Load(d, minX + i), maxX_), hn::Le(minX_, hn::Load(d, maxX + i)));
    auto y = hn::And(hn::Le(hn::Load(d, minY + i), maxY_), hn::Le(minY_, hn::Load(d, maxY + i)));
    auto z = hn::And(hn::Le(hn::Load(d, minZ + i), maxZ_), hn::Le(minZ_, hn::Load(d, maxZ + i)));
    return hn::And(x, hn::And(y, z));
  }

 private:
  hn::Vec<D> minX_, minY_, minZ_, maxX_, maxY_, maxZ_;
};

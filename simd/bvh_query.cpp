// Box queries against the wide BVH: one SIMD comparison per row tests all 8 children of a node.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/bvh_query.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/kernels.hpp"
#include "simdphys/bvh.hpp"

HWY_BEFORE_NAMESPACE();
namespace simdphys::simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "src/bvh/traverse-inl.hpp"

// The slots of a node whose box overlaps the query (closed test), as a bit mask.
class OverlapTest {
 public:
  explicit OverlapTest(const Box& q)
      : minX_(hn::Set(d_, q.minX)), minY_(hn::Set(d_, q.minY)), minZ_(hn::Set(d_, q.minZ)),
        maxX_(hn::Set(d_, q.maxX)), maxY_(hn::Set(d_, q.maxY)), maxZ_(hn::Set(d_, q.maxZ)) {}

  std::uint32_t operator()(const BvhNode& n) const {
    std::uint32_t mask = 0;
    for (std::size_t h = 0; h < BvhNode::kWidth; h += hn::Lanes(d_)) {
      auto x = hn::And(hn::Le(hn::Load(d_, n.minX + h), maxX_), hn::Le(minX_, hn::Load(d_, n.maxX + h)));
      auto y = hn::And(hn::Le(hn::Load(d_, n.minY + h), maxY_), hn::Le(minY_, hn::Load(d_, n.maxY + h)));
      auto z = hn::And(hn::Le(hn::Load(d_, n.minZ + h), maxZ_), hn::Le(minZ_, hn::Load(d_, n.maxZ + h)));
      std::uint8_t bits[8] = {};
      hn::StoreMaskBits(d_, hn::And(x, hn::And(y, z)), bits);
      mask |= std::uint32_t(bits[0]) << h;
    }
    return mask;
  }

 private:
  using D = hn::CappedTag<float, BvhNode::kWidth>;
  static constexpr D d_{};
  hn::Vec<D> minX_, minY_, minZ_, maxX_, maxY_, maxZ_;
};

std::uint64_t BvhCountOverlaps(const BvhNode* nodes, std::size_t nodeCount, const Box* queries,
                               std::size_t nQueries) {
  std::uint64_t count = 0;
  for (std::size_t q = 0; q < nQueries; ++q)
    traverseBvh(nodes, nodeCount, OverlapTest(queries[q]), [&](std::uint32_t) { ++count; });
  return count;
}

void BvhQuery(const BvhNode* nodes, std::size_t nodeCount, const Box& query,
              std::vector<std::uint32_t>& out) {
  traverseBvh(nodes, nodeCount, OverlapTest(query),
              [&](std::uint32_t leaf) { out.push_back(BvhNode::leafFirst(leaf)); });
}

}  // namespace HWY_NAMESPACE
}  // namespace simdphys::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace simdphys::simd {
HWY_EXPORT(BvhCountOverlaps);
HWY_EXPORT(BvhQuery);

std::uint64_t bvhCountOverlaps(const BvhNode* nodes, std::size_t nodeCount, const Box* queries,
                               std::size_t nQueries) {
  return HWY_DYNAMIC_DISPATCH(BvhCountOverlaps)(nodes, nodeCount, queries, nQueries);
}
void bvhQuery(const BvhNode* nodes, std::size_t nodeCount, const Box& query,
              std::vector<std::uint32_t>& out) {
  HWY_DYNAMIC_DISPATCH(BvhQuery)(nodes, nodeCount, query, out);
}
}  // namespace simdphys::simd
#endif

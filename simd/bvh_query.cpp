// Box queries against the wide BVH: one SIMD comparison per row tests all 8 children of a node.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/bvh_query.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstdint>
#include <limits>

#include "core/prefetch.hpp"
#include "simd/export.hpp"
#include "simd/kernels.hpp"
#include "simdphys/bvh_types.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "core/bvh_walk-inl.hpp"
#include "simd/box_overlap-inl.hpp"
#include "simd/compress-inl.hpp"

// Expands a node for a box query without a branch per slot: one comparison per row gives the
// slots that overlap; of those, child nodes are compressed onto the stack and leaves handed to
// the sink as a vector of references with a mask.
template <class Sink>
class OverlapWalk : public NodeWalk {
 public:
  OverlapWalk(const BvhNode* nodes, const Box& q, Sink& sink)
      : nodes_(nodes), sink_(sink), overlap_(d_, q) {}

  bool expand(const BvhNode& n, std::uint32_t&, std::uint32_t* stack, int& top) {
    for (std::size_t h = 0; h < BvhNode::kWidth; h += hn::Lanes(d_)) {
      auto hit =
          hn::RebindMask(du_, overlap_(d_, n.minX, n.minY, n.minZ, n.maxX, n.maxY, n.maxZ, h));
      if (hn::AllFalse(du_, hit)) continue;
      const auto child = hn::Load(du_, n.child + h);
      // An empty slot's bounds fail every finite query, but it must pass none: its reference
      // would be read as a leaf.
      hit = hn::AndNot(hn::Eq(child, hn::Set(du_, BvhNode::kEmpty)), hit);
      const auto leaf = hn::RebindMask(du_, hn::Lt(hn::BitCast(di_, child), hn::Zero(di_)));
      const int pushed = top;
      top += int(compressStore32(du_, child, hn::AndNot(leaf, hit), stack + top));
      // Large trees miss the cache: fetch the children now, while the siblings are tested.
      for (int s = pushed; s < top; ++s) core::prefetchLines(nodes_ + stack[s], sizeof(BvhNode));
      sink_(du_, child, hn::And(leaf, hit));
    }
    return false;
  }

 private:
  using D = hn::CappedTag<float, BvhNode::kWidth>;
  static constexpr D d_{};
  static constexpr hn::RebindToUnsigned<D> du_{};
  static constexpr hn::RebindToSigned<D> di_{};
  const BvhNode* nodes_;
  Sink& sink_;
  BoxOverlap<D> overlap_;
};

// Leaf sinks: count the leaves that pass, or collect their primitive ids.
struct CountLeaves {
  std::uint64_t total = 0;
  template <class DU, class V, class M>
  void operator()(DU du, V, M leaves) {
    total += hn::CountTrue(du, leaves);
  }
};

struct CollectLeaves {
  std::vector<std::uint32_t>& out;
  template <class DU, class V, class M>
  void operator()(DU du, V child, M leaves) {
    if (hn::AllFalse(du, leaves)) return;
    std::size_t size = out.size();
    out.resize(size + hn::Lanes(du));  // CompressStore writes a whole vector
    auto id = hn::And(child, hn::Set(du, BvhNode::kFirstMask));
    out.resize(size + compressStore32(du, id, leaves, out.data() + size));
  }
};

std::uint64_t BvhCountOverlaps(const BvhNode* nodes, std::size_t nodeCount, const Box* queries,
                               std::size_t nQueries) {
  CountLeaves count;
  for (std::size_t q = 0; q < nQueries; ++q) {
    OverlapWalk<CountLeaves> walk(nodes, queries[q], count);
    walkBvh(nodes, nodeCount, walk, 0u);
  }
  return count.total;
}

void BvhQuery(const BvhNode* nodes, std::size_t nodeCount, const Box& query,
              std::vector<std::uint32_t>& out) {
  CollectLeaves collect{out};
  OverlapWalk<CollectLeaves> walk(nodes, query, collect);
  walkBvh(nodes, nodeCount, walk, 0u);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(BvhCountOverlaps, bvhCountOverlaps);
SIMDPHYS_EXPORT(BvhQuery, bvhQuery);
}  // namespace simdphys::simd
#endif

// Frustum culling through the library's one BVH (a box tree over the objects' bounds), walked by
// the one walk (core/bvh_walk-inl.hpp) with the frustum as its node test.
#include <string>

#include "classify.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/scene/octree.hpp"
#include "src/bvh/scalar_walk.hpp"

namespace simdphys {
namespace {

// Every leaf below the node (ids of a box tree: one object a leaf), marked without tests.
class TakeAll : public reference::NodeWalk {
 public:
  explicit TakeAll(std::vector<std::uint64_t>& seen) : seen_(seen) {}
  bool expand(const BvhNode& node, std::uint32_t&, std::uint32_t* stack, int& top) {
    for (std::uint32_t c : node.child) {
      if (c == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(c))
        detail::markSeen(seen_, BvhNode::leafFirst(c));
      else
        stack[top++] = c;
    }
    return false;
  }

 private:
  std::vector<std::uint64_t>& seen_;
};

// Boxes partly inside are opened, boxes wholly inside taken whole, leaves tested exactly.
class FrustumWalk : public reference::NodeWalk {
 public:
  FrustumWalk(const Frustum& f, std::span<const BvhNode> nodes, const BoundsStream& boxes,
              std::vector<std::uint64_t>& seen)
      : f_(f), nodes_(nodes), boxes_(boxes), seen_(seen) {}
  bool expand(const BvhNode& node, std::uint32_t&, std::uint32_t* stack, int& top) {
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t c = node.child[k];
      if (c == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(c)) {
        // The exact per-object test on the object's own centre and extents, as the flat cull.
        const std::uint32_t id = BvhNode::leafFirst(c);
        using F = fields::Bounds;
        const Vec3f centre(boxes_.field(F::cx)[id], boxes_.field(F::cy)[id],
                           boxes_.field(F::cz)[id]);
        const Vec3f half(boxes_.field(F::ex)[id], boxes_.field(F::ey)[id], boxes_.field(F::ez)[id]);
        if (f_.intersectsBox(centre, half)) detail::markSeen(seen_, id);
        continue;
      }
      const Vec3f lo(node.minX[k], node.minY[k], node.minZ[k]);
      const Vec3f hi(node.maxX[k], node.maxY[k], node.maxZ[k]);
      const auto side = detail::classify(f_, lo, hi);
      if (side == detail::FrustumSide::kPartial) {
        stack[top++] = c;
      } else if (side == detail::FrustumSide::kInside) {
        TakeAll all(seen_);
        reference::walkBvh(nodes_.data(), nodes_.size(), all, c);
      }
    }
    return false;
  }

 private:
  const Frustum& f_;
  std::span<const BvhNode> nodes_;
  const BoundsStream& boxes_;
  std::vector<std::uint64_t>& seen_;
};

}  // namespace

std::size_t cull(const Frustum& f, const Bvh& bvh, const BoundsStream& boxes,
                 std::vector<std::uint32_t>& visible) {
  validate(f, "cull(Bvh)");
  if (bvh.size() != boxes.size())
    throw Error("cull: the BVH indexes " + std::to_string(bvh.size()) + " boxes, the stream has " +
                std::to_string(boxes.size()));
  if (!bvh.order().empty()) throw Error("cull: the BVH is not a box tree (one object per leaf)");
  std::vector<std::uint64_t> seen((boxes.size() + 63) / 64, 0);
  FrustumWalk walk(f, bvh.nodes(), boxes, seen);
  reference::walkBvh(bvh.nodes().data(), bvh.nodes().size(), walk, 0u);
  detail::seenToIds(seen, visible);
  return visible.size();
}

}  // namespace simdphys

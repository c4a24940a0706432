// Frustum culling through the library's one BVH (a box tree over the objects' bounds).
#include <string>

#include "classify.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/scene/octree.hpp"

namespace simdphys {
namespace {

// Every leaf below the node (ids of a box tree: one object a leaf), marked without tests.
void takeSubtree(std::span<const BvhNode> nodes, std::uint32_t n, std::vector<std::uint64_t>& seen,
                 std::vector<std::uint32_t>& stack) {
  stack.push_back(n);
  while (!stack.empty()) {
    const BvhNode& node = nodes[stack.back()];
    stack.pop_back();
    for (std::uint32_t c : node.child) {
      if (c == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(c))
        detail::markSeen(seen, BvhNode::leafFirst(c));
      else
        stack.push_back(c);
    }
  }
}

}  // namespace

std::size_t cull(const Frustum& f, const Bvh& bvh, const BoundsStream& boxes,
                 std::vector<std::uint32_t>& visible) {
  validate(f, "cull(Bvh)");
  if (bvh.size() != boxes.size())
    throw Error("cull: the BVH indexes " + std::to_string(bvh.size()) + " boxes, the stream has " +
                std::to_string(boxes.size()));
  if (!bvh.order().empty()) throw Error("cull: the BVH is not a box tree (one object per leaf)");
  std::vector<std::uint64_t> seen((boxes.size() + 63) / 64, 0);
  std::vector<std::uint32_t> stack, inner;
  const auto nodes = bvh.nodes();
  if (!nodes.empty()) stack.push_back(0);
  while (!stack.empty()) {
    const BvhNode& node = nodes[stack.back()];
    stack.pop_back();
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t c = node.child[k];
      if (c == BvhNode::kEmpty) continue;
      if (BvhNode::isLeaf(c)) {
        // The exact per-object test on the object's own centre and extents, as the flat cull.
        const std::uint32_t id = BvhNode::leafFirst(c);
        const Vec3f centre(boxes.cx()[id], boxes.cy()[id], boxes.cz()[id]);
        const Vec3f half(boxes.ex()[id], boxes.ey()[id], boxes.ez()[id]);
        if (f.intersectsBox(centre, half)) detail::markSeen(seen, id);
        continue;
      }
      const Vec3f lo(node.minX[k], node.minY[k], node.minZ[k]);
      const Vec3f hi(node.maxX[k], node.maxY[k], node.maxZ[k]);
      const auto side = detail::classify(f, lo, hi);
      if (side == detail::FrustumSide::kPartial)
        stack.push_back(c);
      else if (side == detail::FrustumSide::kInside)
        takeSubtree(nodes, c, seen, inner);
    }
  }
  detail::seenToIds(seen, visible);
  return visible.size();
}

}  // namespace simdphys

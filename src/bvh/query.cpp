// Box queries: the scalar reference runs the same traversal, testing slot by slot.
#include "../views.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace reference {
#include "traverse-inl.hpp"

// Expands a node for a box query: leaves that overlap go to `visit`, child nodes to the stack.
template <class Visit>
auto overlapExpander(const Aabb& q, Visit visit) {
  return [&q, visit](const BvhNode& n, std::uint32_t* stack, int top) mutable {
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      // An empty slot passes no query, not even one with infinite bounds.
      bool hit = n.child[k] != BvhNode::kEmpty && n.minX[k] <= q.max.x() &&
                 q.min.x() <= n.maxX[k] && n.minY[k] <= q.max.y() && q.min.y() <= n.maxY[k] &&
                 n.minZ[k] <= q.max.z() && q.min.z() <= n.maxZ[k];
      if (!hit) continue;
      if (BvhNode::isLeaf(n.child[k]))
        visit(BvhNode::leafFirst(n.child[k]));
      else
        stack[top++] = n.child[k];
    }
    return top;
  };
}
}  // namespace reference

void Bvh::query(const Aabb& q, std::vector<std::uint32_t>& out) const {
  validate(q, "Bvh::query");
  requireBoxTree("Bvh::query");
  if (!referencePathActive()) return simd::bvhQuery(nodes_.data(), nodes_.size(), box(q), out);
  reference::traverseBvh(
      nodes_.data(), nodes_.size(),
      reference::overlapExpander(q, [&](std::uint32_t id) { out.push_back(id); }));
}

std::uint64_t Bvh::countOverlaps(std::span<const Aabb> queries) const {
  requireBoxTree("Bvh::countOverlaps");
  for (std::size_t i = 0; i < queries.size(); ++i)
    validate(queries[i], "Bvh::countOverlaps: query " + std::to_string(i));
  if (!referencePathActive()) {
    std::vector<simd::Box> boxes;
    boxes.reserve(queries.size());
    for (const Aabb& q : queries) boxes.push_back(box(q));
    return simd::bvhCountOverlaps(nodes_.data(), nodes_.size(), boxes.data(), boxes.size());
  }
  std::uint64_t count = 0;
  for (const Aabb& q : queries)
    reference::traverseBvh(nodes_.data(), nodes_.size(),
                           reference::overlapExpander(q, [&](std::uint32_t) { ++count; }));
  return count;
}

}  // namespace simdphys

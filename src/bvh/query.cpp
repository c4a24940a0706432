// Box queries: the scalar reference runs the same traversal with a slot-by-slot test.
#include "../views.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace reference {
#include "traverse-inl.hpp"

inline std::uint32_t overlapMask(const BvhNode& n, const Aabb& q) {
  std::uint32_t mask = 0;
  for (int k = 0; k < BvhNode::kWidth; ++k) {
    bool hit = n.minX[k] <= q.max.x() && q.min.x() <= n.maxX[k] && n.minY[k] <= q.max.y() &&
               q.min.y() <= n.maxY[k] && n.minZ[k] <= q.max.z() && q.min.z() <= n.maxZ[k];
    mask |= std::uint32_t(hit) << k;
  }
  return mask;
}
}  // namespace reference

void Bvh::query(const Aabb& q, std::vector<std::uint32_t>& out) const {
  validate(q, "Bvh::query");
  if (!referencePathActive()) return simd::bvhQuery(nodes_.data(), nodes_.size(), box(q), out);
  reference::traverseBvh(
      nodes_.data(), nodes_.size(), [&](const BvhNode& n) { return reference::overlapMask(n, q); },
      [&](std::uint32_t leaf) { out.push_back(BvhNode::leafFirst(leaf)); });
}

std::uint64_t Bvh::countOverlaps(std::span<const Aabb> queries) const {
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
    reference::traverseBvh(
        nodes_.data(), nodes_.size(),
        [&](const BvhNode& n) { return reference::overlapMask(n, q); },
        [&](std::uint32_t) { ++count; });
  return count;
}

}  // namespace simdphys

// Box queries: the scalar reference runs the same walk, testing slot by slot.
#include "../views.hpp"
#include "scalar_walk.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {

void Bvh::query(const Aabb& q, std::vector<std::uint32_t>& out) const {
  validate(q, "Bvh::query");
  requireBoxTree("Bvh::query");
  if (!referencePathActive()) return simd::bvhQuery(nodes_.data(), nodes_.size(), box(q), out);
  reference::overlappingLeaves(nodes_, q,
                               [&](std::uint32_t id, std::uint32_t) { out.push_back(id); });
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
    reference::overlappingLeaves(nodes_, q, [&](std::uint32_t, std::uint32_t) { ++count; });
  return count;
}

}  // namespace simdphys

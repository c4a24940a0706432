// The reference path's BVH walks: the one walk of core/bvh_walk-inl.hpp with scalar node tests,
// slot by slot (the box overlap and the ray slab test), shared by the box queries (query.cpp),
// meshes (src/mesh/), the scene's rays and its cull (src/scene/).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "core/traversal_ray.hpp"
#include "simdphys/bvh_types.hpp"
#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys::reference {

// First: the lane-generic kernels below call its operations for floats.
#include "core/scalar_lanes-inl.hpp"

#include "core/bvh_walk-inl.hpp"
#include "core/closest_hits-inl.hpp"
#include "core/ray_slab-inl.hpp"

// The leaves whose slot box overlaps `q` (closed): visit(first, count) for each.
template <class Visit>
class OverlapWalk : public NodeWalk {
 public:
  OverlapWalk(const Aabb& q, Visit& visit) : q_(q), visit_(visit) {}

  bool expand(const BvhNode& n, std::uint32_t&, std::uint32_t* stack, int& top) {
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      // An empty slot passes no query, not even one with infinite bounds.
      const bool hit = n.child[k] != BvhNode::kEmpty && n.minX[k] <= q_.max.x() &&
                       q_.min.x() <= n.maxX[k] && n.minY[k] <= q_.max.y() &&
                       q_.min.y() <= n.maxY[k] && n.minZ[k] <= q_.max.z() &&
                       q_.min.z() <= n.maxZ[k];
      if (!hit) continue;
      const std::uint32_t c = n.child[k];
      if (BvhNode::isLeaf(c))
        visit_(BvhNode::leafFirst(c), BvhNode::leafCount(c));
      else
        stack[top++] = c;
    }
    return false;
  }

 private:
  const Aabb& q_;
  Visit& visit_;
};

template <class Visit>
void overlappingLeaves(std::span<const BvhNode> nodes, const Aabb& q, Visit visit) {
  OverlapWalk<Visit> walk(q, visit);
  walkBvh(nodes.data(), nodes.size(), walk, 0u);
}

// The ray node test, slot by slot: the children whose box the ray enters before `bound`, their
// references and scaled entry distances in refs and dists; returns their number. The SIMD
// kernel's test (simd/bvh_ray.cpp), the same raySlab on one lane.
inline int expandRay(const BvhNode& n, const detail::TraversalRay& ray, float bound,
                     std::uint32_t* refs, float* dists) {
  const float* lo[3] = {n.minX, n.minY, n.minZ};
  const float* hi[3] = {n.maxX, n.maxY, n.maxZ};
  int count = 0;
  for (int k = 0; k < BvhNode::kWidth; ++k) {
    if (n.child[k] == BvhNode::kEmpty) continue;
    auto faces = [&](int a, float& nearFace, float& farFace) {
      nearFace = ray.negative[a] ? hi[a][k] : lo[a][k];
      farFace = ray.negative[a] ? lo[a][k] : hi[a][k];
    };
    float enter;
    const bool hit =
        ray.finiteInverse
            ? raySlab<true>(ScalarLane{}, faces, ray.origin, ray.inverse, bound, enter)
            : raySlab<false>(ScalarLane{}, faces, ray.origin, ray.inverse, bound, enter);
    if (!hit) continue;
    refs[count] = n.child[k];
    dists[count++] = enter;
  }
  return count;
}

}  // namespace simdphys::reference

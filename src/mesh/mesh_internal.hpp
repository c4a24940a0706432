// What mesh_bvh.cpp and stream_tracing.cpp share: the reference path's ray traversals and the
// kernels' view of a tree.
#pragma once

#include <span>
#include <string_view>

#include "core/traversal_ray.hpp"
#include "simd/kernels.hpp"
#include "simdphys/mesh_bvh.hpp"

namespace simdphys {

namespace reference {
// The SIMD traversal's algorithm with a scalar core (mesh_bvh.cpp).
ElementHit closestHit(const Bvh& bvh, std::span<const TriangleBlock> blocks,
                      const detail::TraversalRay& ray);
bool anyHit(const Bvh& bvh, std::span<const TriangleBlock> blocks, const detail::TraversalRay& ray);
}  // namespace reference

namespace detail {
// Mesh::validate in its two parts, for a caller that makes something of each triangle (the
// tree's primitives) and so reads it once: the vertices, then triangle i.
void validateVertices(const Mesh& mesh, std::string_view where);
void validateTriangle(const Mesh& mesh, std::size_t i, std::string_view where);
}  // namespace detail

inline simd::MeshView meshView(const Bvh& bvh, std::span<const TriangleBlock> blocks) {
  return {bvh.nodes().data(), bvh.nodes().size(), blocks.data()};
}

}  // namespace simdphys

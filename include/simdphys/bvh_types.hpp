// The BVH's plain types, without Eigen: the node, a mesh leaf's block of triangles and the window
// within which two mesh hits tie (the hit itself is core.hpp's ElementHit). Part of the API
// (bvh.hpp and mesh_bvh.hpp include it) and the one public header the SIMD kernels read
// (simd/bvh_*.cpp), so the kernels compile no Eigen.
#pragma once

#include <cstdint>

namespace simdphys {

struct alignas(64) BvhNode {
  static constexpr int kWidth = 8;
  // child[k]: the index of a child node, or kLeaf | (count - 1) << kCountShift | first for a
  // leaf of `count` primitives starting at `first`. Unused slots are kEmpty with empty
  // bounds (min = +inf, max = -inf): no finite test passes them, and the box traversals skip
  // kEmpty whatever the query.
  static constexpr std::uint32_t kLeaf = 1u << 31;
  static constexpr int kCountShift = 27;
  static constexpr std::uint32_t kFirstMask = (1u << kCountShift) - 1;
  static constexpr std::uint32_t kEmpty = ~0u;
  // Depth bound the build guarantees, and the traversal stack it implies: each level leaves at
  // most kWidth - 1 siblings on the stack.
  static constexpr int kMaxDepth = 72;
  static constexpr int kStackSize = kMaxDepth * (kWidth - 1) + 1;

  float minX[kWidth], minY[kWidth], minZ[kWidth];
  float maxX[kWidth], maxY[kWidth], maxZ[kWidth];
  std::uint32_t child[kWidth];
  // leafSpan[k], for a child node: its own leaf children, which lie together (Bvh::build places
  // leaves in node order), as (count - 1) << kCountShift | first, first the first block of
  // leafAlign primitives they lie in and count the blocks; kEmpty if it has none or the tree has no
  // blocks. Lets a walk fetch a node's leaves with the node, one level ahead. It fills
  // the last line's padding (the node stays 4 lines).
  std::uint32_t leafSpan[kWidth];

  static bool isLeaf(std::uint32_t c) { return (c & kLeaf) != 0; }
  static std::uint32_t leafFirst(std::uint32_t c) { return c & kFirstMask; }
  static std::uint32_t leafCount(std::uint32_t c) { return ((c & ~kLeaf) >> kCountShift) + 1; }
};

static_assert(sizeof(BvhNode) == 256, "four cache lines");

// Mesh leaves' triangles (mesh_bvh.hpp): 8 lanes, a leaf a run of them (Bvh's leafAlign blocks).
struct alignas(64) TriangleBlock {
  static constexpr int kWidth = 8;
  float v[3][3][kWidth];  // v[vertex a, b, c][coordinate x, y, z][lane]
  std::uint32_t id[kWidth];

  // A leaf reference's block, and its first lane there (its lanes run on for its count).
  static std::uint32_t of(std::uint32_t leaf) { return BvhNode::leafFirst(leaf) / kWidth; }
  static std::uint32_t firstLane(std::uint32_t leaf) { return BvhNode::leafFirst(leaf) % kWidth; }
};

// Relative window within which two hits tie (W2): t <= tMin * kTieWindow.
inline constexpr float kTieWindow = 1.0f + 1e-6f;

}  // namespace simdphys

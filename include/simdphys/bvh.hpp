// The bounding volume hierarchy: one wide tree type for the whole library (box queries and the
// broadphase now; meshes, scenes and rays build on the same nodes).
//
// Each node has up to 8 children whose bounds are stored as SoA rows, so one SIMD comparison
// tests all of them. The tree is built top-down with a binned surface-area heuristic straight
// into 8-wide nodes (Wald 2007; the way Embree builds its BVH8): a node starts as one child
// holding all its primitives, and the child with the largest surface area is split until there
// are 8. A box tree's leaves hold one primitive each: the slot's bounds are the primitive's own
// box, so a slot test is the exact primitive test. Meshes (mesh_bvh.hpp) build the same tree with
// leaves of up to 8 triangles, which one SIMD test covers.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/bvh_types.hpp"
#include "simdphys/geometry3d.hpp"

namespace simdphys {

// How a tree is built from primitive bounds.
struct BvhBuildOptions {
  // Leaves hold at most this many primitives (1 to 16, the leaf reference's count field); a range
  // that fits is split further only while the surface-area heuristic says a split is cheaper.
  std::uint32_t maxLeafSize = 1;
  // Blocks of this many slots in order() (1, or at least maxLeafSize): no leaf straddles a multiple
  // of leafAlign, a block may hold several leaves (a node's leaves are packed together), and a slot
  // no leaf takes repeats its block's first primitive. An owner can then store the primitives in
  // blocks of `leafAlign` and find a leaf as lanes first % leafAlign onwards of block
  // first / leafAlign.
  std::uint32_t leafAlign = 1;
  // The SAH has no node cost to tune: a split inside a node adds no node to visit (the halves
  // take two of its slots), and a range a leaf can hold always becomes a leaf. It weighs leaves
  // only, by surface area times the blocks of leafAlign primitives they take.
};

namespace detail {
struct BvhPrimRef;  // simd/kernels.hpp: a primitive's box and id as the builder moves it
}

class Bvh {
 public:
  // Largest number of primitives a tree can index (27 bits of a leaf reference).
  static constexpr std::size_t kMaxPrimitives = BvhNode::kFirstMask + 1;

  Bvh() = default;
  explicit Bvh(const BoxStream& boxes) { build(boxes); }

  // Builds the tree over the boxes; their index in the stream is the primitive id. One box per
  // leaf, and the leaf reference's `first` is the box's id.
  void build(const BoxStream& boxes);
  // Builds the tree over primitives given by their bounds (index = primitive id). With
  // maxLeafSize > 1 a leaf references the range [first, first + count) of order(); with 1, as for
  // boxes, `first` is the primitive's id and order() is empty. Throws Error on a NaN or inverted
  // box (naming it) or bad options.
  void build(std::span<const Aabb> bounds, const BvhBuildOptions& options);
  // Updates the bounds after the boxes moved, keeping the topology (cheap, but the tree's quality
  // degrades with the motion; rebuild when it has moved a lot). Throws Error if the stream's
  // size differs from the one the tree was built on.
  void refit(const BoxStream& boxes);
  // The same for a tree built from bounds.
  void refit(std::span<const Aabb> bounds);

  // Ids of the boxes that overlap `box` (closed test), appended to `out` in traversal order.
  // Box queries need one primitive per leaf (a box tree); they throw Error on a mesh's tree.
  void query(const Aabb& box, std::vector<std::uint32_t>& out) const;
  // Number of boxes each query overlaps, summed over the queries.
  std::uint64_t countOverlaps(std::span<const Aabb> queries) const;

  std::size_t size() const { return primitives_; }
  std::span<const BvhNode> nodes() const { return nodes_; }
  // Primitive ids in leaf order, in blocks of options().leafAlign (empty for a box tree).
  std::span<const std::uint32_t> order() const { return order_; }
  const BvhBuildOptions& options() const { return options_; }
  // Longest root-to-leaf path, in nodes.
  int depth() const { return depth_; }

 private:
  // A mesh's tree makes its primitives straight from its triangles (no array of bounds first).
  friend class MeshBvh;
  void buildFrom(AlignedVector<detail::BvhPrimRef> prims, const BvhBuildOptions& options,
                 const char* where);
  void requireBoxTree(const char* where) const;

  AlignedVector<BvhNode> nodes_;
  AlignedVector<std::uint32_t> order_;
  BvhBuildOptions options_;
  std::size_t primitives_ = 0;
  int depth_ = 0;
};

}  // namespace simdphys

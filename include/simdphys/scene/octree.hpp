// The octree of book chapter 12, over boxes given as a BoundsStream (index = object id).
//
// The root cell is the cube around every box; a cell holding more than maxLeafSize boxes is
// split into eight equal octants, down to maxDepth. As in the book, an object that straddles the
// border between cells is stored in every leaf cell its box overlaps; queries report it once.
// Objects whose box is not inside the root cell (after moving) are kept on a list of their own
// that every query tests.
//
// Each node also keeps the bounds of the boxes stored below it. Queries and culling prune with
// those, not with the cells: an object can straddle cells that each fail a frustum plane while
// the object itself passes the conservative test, and the content bounds never miss it. So every
// query returns exactly what the per-object test over all boxes returns (ascending ids).
//
// For culling, the leaves' boxes are copied in leaf order into SoA arrays, each leaf starting on
// a 16-element boundary, so the batch cull kernel (scene.hpp's cull, on the active path) runs
// over a leaf as over a stream.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "simdphys/scene/frustum.hpp"

namespace simdphys {

struct OctreeOptions {
  std::uint32_t maxLeafSize = 64;  // a cell with more boxes is split (while depth allows)
  int maxDepth = 8;                // the root is depth 0
};

class Octree {
 public:
  Octree() = default;
  explicit Octree(const BoundsStream& boxes, const OctreeOptions& options = {}) {
    build(boxes, options);
  }

  // Builds the tree over the boxes. Throws Error on bad options.
  void build(const BoundsStream& boxes, const OctreeOptions& options = {});
  // The objects `moved` have the boxes `boxes` now (same stream size as the build): each is
  // removed from the leaves it was in and inserted into the leaves it overlaps now, as the book
  // does; cells are not split or merged (rebuild when the distribution changed a lot). Throws
  // Error on a size mismatch or an id out of range.
  void update(std::span<const std::uint32_t> moved, const BoundsStream& boxes);

  // Ids, ascending, of the boxes that overlap the query (closed tests of intersect.hpp).
  std::vector<std::uint32_t> query(const Aabb& box) const;
  std::vector<std::uint32_t> query(const Sphere& sphere) const;
  // Writes to `visible` the ids, ascending, of the boxes that pass Frustum::intersectsBox on
  // their centre and half extents, exactly as cull(frustum, boxes, visible) over the whole
  // stream; returns their number. Leaves run on the active path.
  std::size_t cull(const Frustum& frustum, std::vector<std::uint32_t>& visible) const;

  std::size_t size() const { return boxes_.size(); }
  std::size_t nodeCount() const { return nodes_.size(); }
  // Stored references, counting an object once per leaf it is in: size() plus the duplicates.
  std::size_t entryCount() const;
  int depth() const;
  const Aabb& rootCell() const { return nodes_.front().cell; }
  std::size_t outsideCount() const { return outside_.size(); }

 private:
  struct Node {
    Aabb cell{Vec3f::Zero(), Vec3f::Zero()};     // fixed: where objects are inserted
    Aabb content{Vec3f::Zero(), Vec3f::Zero()};  // the union of the boxes below, for pruning
    std::uint32_t firstChild = 0;                // 0 for a leaf; children are consecutive
    int depth = 0;
    std::vector<std::uint32_t> ids;                // a leaf's objects
    std::uint32_t packedBegin = 0, packedEnd = 0;  // the subtree's range of the packed arrays
  };
  template <class NodeTest, class ObjectTest>
  std::vector<std::uint32_t> collect(NodeTest nodeTest, ObjectTest objectTest) const;
  template <class F>
  void forLeaves(const Aabb& box, F visit);
  static std::array<float, 6> source(const BoundsStream& boxes, std::size_t i);
  void split(std::uint32_t node);
  void insert(std::uint32_t id);
  void refitAndPack();
  Aabb refit(std::uint32_t node);
  void pack(std::uint32_t node, std::uint32_t& at);
  void cullRange(const Frustum& frustum, std::uint32_t begin, std::uint32_t end,
                 std::vector<std::uint32_t>& scratch, std::vector<std::uint64_t>& seen) const;

  OctreeOptions options_;
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> outside_;  // ids not inside the root cell
  std::vector<Aabb> boxes_;             // each object's box, as BoundsStream::operator[] gives it
  std::vector<std::array<float, 6>> source_;  // and its centre and half extents, as given
  // Leaf-ordered copies for culling: centre, half extents, id (kEmpty in padding).
  std::array<Stream<float>, 6> packed_;
  std::vector<std::uint32_t> packedIds_;
  std::uint32_t outsideBegin_ = 0;  // the outside list is packed last, as one more leaf
};

// The same cull through the library's one BVH, built over the same boxes (one per leaf):
// subtrees whose bounds lie wholly outside a plane are skipped, wholly inside are taken without
// tests, and leaves are tested exactly. Equal to cull(frustum, boxes, visible); ascending ids.
class Bvh;
std::size_t cull(const Frustum& frustum, const Bvh& bvh, const BoundsStream& boxes,
                 std::vector<std::uint32_t>& visible);

}  // namespace simdphys

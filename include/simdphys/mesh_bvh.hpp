// A triangle mesh's BVH and its queries: closest-hit and any-hit rays (one, or a stream of them),
// linecasts and linetests, and overlap with spheres, boxes and triangles.
//
// The tree is the library's one Bvh, built over the triangles' bounds with leaves of up to
// 8 triangles. The triangles are copied into leaf order as blocks of 8 (Embree's Triangle8): the
// 9 vertex coordinates as rows of 8 floats and the 8 triangle ids, so one SIMD watertight test
// (Woop, Benthin, Wald 2013; raycast.hpp) covers a leaf. Leaves share blocks: a leaf is lanes
// first % 8 onwards of block first / 8, and the test masks the block's other lanes.
//
// Closest hit: the smallest t in [0, tMax], and where several triangles are hit within 1e-6
// relative of it (t <= tMin * (1 + 1e-6)), the one with the smallest id wins (workload W2's rule),
// its own t reported. Every path (reference and SIMD) computes every triangle's t bit for bit as
// raycast.hpp's intersectTriangle does, so the answers are the same on every path and equal to
// brute force over the triangles with the same rule.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "simdphys/bvh.hpp"
#include "simdphys/bvh_types.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "simdphys/mesh.hpp"

namespace simdphys {

// Rays as SoA: origin, direction (any non-zero length; t is in units of it) and tMax (>= 0).
// Padding rays have tMax = -inf and hit nothing.
class RayStream : public StreamSet<fields::Ray> {
 public:
  // Throws Error naming the element: a coordinate not finite, a zero direction, tMax < 0 or NaN.
  void push(const Ray& ray, float tMax = std::numeric_limits<float>::infinity());
  Ray operator[](std::size_t i) const;

  const Stream<float>& origin(int k) const { return field(fields::Ray::origin + k); }
  const Stream<float>& direction(int k) const { return field(fields::Ray::direction + k); }
  const Stream<float>& tMax() const { return field(fields::Ray::tMax); }
};

// How MeshBvh::raycast traces a ray stream: one ray at a time, or in packets of 8 or 16 rays that
// traverse the tree together (for coherent rays: a packet tests each box against all its rays in
// one SIMD operation, and rays that stay together share the node and triangle loads). A packet
// whose active rays drop to a few hands them to single-ray traversal, so packets of rays that
// diverge cost little more than single rays. Every mode returns the same hits, bit for bit.
struct RayStreamOptions {
  enum class Mode {
    // Packets for the groups whose rays all point into the same octant (the signs of the three
    // direction components agree: a camera's tile does, 16 random directions almost never);
    // single rays for the other groups. Thousands of single rays are first sorted by where they
    // enter the tree, so that rays traced one after another walk the same nodes (random rays
    // over a large mesh otherwise miss the cache at nearly every node); the hits come back in the
    // stream's order.
    kAuto,
    kSingle,   // one ray at a time, in the stream's order
    kPackets,  // every group as a packet, whatever its directions
  };
  Mode mode = Mode::kAuto;
  // Rays per packet: 8 or 16; 0 picks 16 (faster than 8 on AVX-512 and AVX2, equal on SSE4:
  // docs/bvh.md has the measurements).
  std::uint32_t packetSize = 0;
  // 0: a packet is consecutive rays of the stream. Otherwise the stream is an image in scanline
  // order, imageWidth rays a row, and a packet is a tile of it: 4 x 4 rays (16) or 4 x 2 (8),
  // cut off at the image's edges. Tiles are more coherent than rows.
  std::uint32_t imageWidth = 0;
};

class MeshBvh {
 public:
  static constexpr std::uint32_t kLeafSize = TriangleBlock::kWidth;

  MeshBvh() = default;
  // Validates the mesh (Mesh::validate) and builds the tree. Keeps a copy of the mesh.
  explicit MeshBvh(Mesh mesh);

  // After the vertices moved (same triangles): new bounds up the tree and new blocks. The tree's
  // shape stays, so it answers exactly like a rebuild, only slower as the motion grows.
  void refit(std::span<const Vec3f> vertices);

  // Closest hit with t in [0, tMax] (the rule above), or a miss.
  ElementHit raycast(const Ray& ray, float tMax = std::numeric_limits<float>::infinity()) const;
  // Whether any triangle is hit with t in [0, tMax]; stops at the first found.
  bool occluded(const Ray& ray, float tMax = std::numeric_limits<float>::infinity()) const;
  // For every ray of the stream, its closest hit (out.size() == rays.size()). The reference path
  // traces one ray at a time whatever the options.
  void raycast(const RayStream& rays, std::span<ElementHit> out,
               const RayStreamOptions& options = {}) const;
  // For every ray, whether it hits anything (1) or not (0).
  void occluded(const RayStream& rays, std::span<std::uint8_t> out) const;

  // The closest hit along the segment, t the distance from its start (raycast.hpp's linecast),
  // and whether the closed segment meets any triangle (linetest).
  ElementHit linecast(const Segment& segment) const;
  bool linetest(const Segment& segment) const;

  // Ids of the triangles the shape intersects (intersect.hpp's tests, closed), ascending. Throws
  // Error on an invalid shape or one outside the supported range (math.hpp).
  std::vector<std::uint32_t> overlapping(const Sphere& sphere) const;
  std::vector<std::uint32_t> overlapping(const Aabb& box) const;
  std::vector<std::uint32_t> overlapping(const Obb& box) const;
  std::vector<std::uint32_t> overlapping(const Triangle& triangle) const;

  const Mesh& mesh() const { return mesh_; }
  // activeEdges(mesh()) (mesh.hpp): what rigid bodies colliding with the mesh read. Computed on
  // the first call (thread-safe; it takes about as long as building the tree, which rays alone
  // never pay) and again on the first call after a refit.
  std::span<const std::uint8_t> activeEdges() const;
  const Bvh& bvh() const { return bvh_; }
  std::span<const TriangleBlock> blocks() const { return blocks_; }

 private:
  void fillBlocks();
  template <class Shape>
  std::vector<std::uint32_t> overlappingShape(const Shape& shape, const char* where) const;

  Mesh mesh_;
  Bvh bvh_;
  AlignedVector<TriangleBlock> blocks_;
  // activeEdges()'s, once; a copy computes its own when asked.
  struct LazyActiveEdges {
    std::unique_ptr<std::once_flag> once = std::make_unique<std::once_flag>();
    std::vector<std::uint8_t> bits;
    LazyActiveEdges() = default;
    LazyActiveEdges(const LazyActiveEdges&) : LazyActiveEdges() {}
    LazyActiveEdges(LazyActiveEdges&&) = default;
    LazyActiveEdges& operator=(const LazyActiveEdges&) { return *this = LazyActiveEdges(); }
    LazyActiveEdges& operator=(LazyActiveEdges&&) = default;
  };
  mutable LazyActiveEdges activeEdges_;
  float extent_ = 0;  // twice the largest |coordinate|: the overlap queries' tolerance scale
};

}  // namespace simdphys

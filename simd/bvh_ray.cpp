// Rays against a mesh's BVH, one ray at a time (for incoherent rays), and in packets
// (bvh_packet-inl.hpp, for coherent rays): the 8 children of a node
// are slab-tested together, the ones hit visited nearest first; a leaf's 8 triangles are tested
// together with the watertight test (watertight-inl.hpp), the same arithmetic as the scalar
// intersectTriangle, so every path returns the reference's hits bit for bit. Also the keys that
// order incoherent rays (MeshRayKeys: the root's slab test and a Morton code).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/bvh_ray.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

#include "core/prefetch.hpp"
#include "core/traversal_ray.hpp"
#include "simd/export.hpp"
#include "simd/kernels.hpp"
#include "simdphys/bvh_types.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "core/bvh_walk-inl.hpp"
#include "core/closest_hits-inl.hpp"
#include "core/ray_slab-inl.hpp"
#include "simd/compress-inl.hpp"
#include "simd/watertight-inl.hpp"

// A node's rows as offsets in floats from its start (BvhNode: minX minY minZ maxX maxY maxZ).
constexpr int kRow = BvhNode::kWidth;

// Large meshes miss the cache: the first line of what a walk will visit (a node's x rows, a
// block's x coordinates) is fetched while the rest is tested.
HWY_INLINE void prefetch(const MeshView& mesh, std::uint32_t ref) {
  if (BvhNode::isLeaf(ref))
    hwy::Prefetch(mesh.blocks + TriangleBlock::of(ref));
  else
    hwy::Prefetch(mesh.nodes + ref);
}

// All of it: a packet tests every line of what it visits.
HWY_INLINE void prefetchAll(const MeshView& mesh, std::uint32_t ref) {
  if (BvhNode::isLeaf(ref))
    core::prefetchLines(mesh.blocks + TriangleBlock::of(ref), sizeof(TriangleBlock));
  else
    core::prefetchLines(mesh.nodes + ref, sizeof(BvhNode));
}

// kFinite: the ray's inverse direction is finite on every axis (the common case), so no slab
// product is NaN and plain Min/Max bound the interval.
template <class Sink, bool kFinite>
class RayCore {
  using D = hn::CappedTag<float, BvhNode::kWidth>;

 public:
  RayCore(const MeshView& mesh, const detail::TraversalRay& ray, Sink& sink)
      : mesh_(mesh), ray_(ray), sink_(sink) {
    for (int a = 0; a < 3; ++a) {
      near_[a] = (ray.negative[a] ? 3 + a : a) * kRow;
      far_[a] = (ray.negative[a] ? a : 3 + a) * kRow;
    }
  }

  float bound() const { return sink_.bound(); }

  int expand(const BvhNode& n, float bound, std::uint32_t* refs, float* dists) const {
    const D d;
    const hn::RebindToUnsigned<D> du;
    const float* rows = n.minX;
    int count = 0;
    for (std::size_t h = 0; h < BvhNode::kWidth; h += hn::Lanes(d)) {
      hn::Vec<D> origin[3], inverse[3], enter;
      for (int a = 0; a < 3; ++a)
        origin[a] = hn::Set(d, ray_.origin[a]), inverse[a] = hn::Set(d, ray_.inverse[a]);
      auto faces = [&](int a, hn::Vec<D>& nearFace, hn::Vec<D>& farFace) {
        nearFace = hn::Load(d, rows + near_[a] + h);
        farFace = hn::Load(d, rows + far_[a] + h);
      };
      const auto hit = raySlab<kFinite>(d, faces, origin, inverse, hn::Set(d, bound), enter);
      if (hn::AllFalse(d, hit)) continue;
      const auto child = hn::Load(du, n.child + h);
      const int kept = int(compressStore32(du, child, hn::RebindMask(du, hit), refs + count));
      compressStore32(d, enter, hit, dists + count);
      for (int k = count; k < count + kept; ++k) prefetch(mesh_, refs[k]);
      count += kept;
    }
    return count;
  }

  // Tests the leaf's block; true stops the traversal (the sink wants any hit and has one).
  bool leaf(std::uint32_t ref) {
    const D d;
    const TriangleBlock& block = mesh_.blocks[TriangleBlock::of(ref)];
    // The leaf's lanes of its block, [begin, end): the others belong to other leaves, or repeat.
    const std::size_t begin = TriangleBlock::firstLane(ref);
    const std::size_t end = begin + BvhNode::leafCount(ref);
    for (std::size_t h = begin / hn::Lanes(d) * hn::Lanes(d); h < end; h += hn::Lanes(d)) {
      hn::Vec<D> t;
      auto hit = watertightHits(
          d, ray_, sink_.bound(), [&](int q, int k) { return hn::Load(d, block.v[q][k] + h); }, t);
      hit = hn::And(hit,
                    hn::AndNot(hn::FirstN(d, begin > h ? begin - h : 0), hn::FirstN(d, end - h)));
      if (hn::AllFalse(d, hit)) continue;
      if constexpr (Sink::kAnyHit) {
        sink_.found = true;
        return true;
      } else {
        alignas(64) float ts[hn::MaxLanes(D())];
        hn::Store(t, d, ts);
        std::uint8_t bits[8] = {};
        hn::StoreMaskBits(d, hit, bits);
        for (unsigned m = bits[0]; m != 0; m &= m - 1) {
          const int k = __builtin_ctz(m);
          sink_.offer(ts[k], block.id[h + k]);
        }
      }
    }
    return false;
  }

 private:
  const MeshView& mesh_;
  const detail::TraversalRay& ray_;
  Sink& sink_;
  int near_[3], far_[3];
};

template <class Sink>
void traverse(const MeshView& mesh, const detail::TraversalRay& ray, Sink& sink) {
  if (ray.finiteInverse) {
    RayCore<Sink, true> core(mesh, ray, sink);
    traverseRay(mesh.nodes, mesh.nodeCount, core);
  } else {
    RayCore<Sink, false> core(mesh, ray, sink);
    traverseRay(mesh.nodes, mesh.nodeCount, core);
  }
}

// Ray i of `rays` traced alone: its closest hit.
ElementHit closestHit(const MeshView& mesh, const RaysView& rays, std::size_t i) {
  const detail::TraversalRay ray = detail::traversalRay(rays, i);
  Closest closest(ray.tMax);
  traverse(mesh, ray, closest);
  return closest.result();
}

void MeshClosestHits(const MeshView& mesh, const RaysView& rays, std::uint32_t* id, float* t) {
  for (std::size_t i = 0; i < rays.count; ++i) {
    const ElementHit h = closestHit(mesh, rays, i);
    id[i] = h.index, t[i] = h.t;
  }
}

// 10 bits spread to every third bit of 30.
std::uint32_t spreadBits(std::uint32_t x) {
  x &= 0x3ffu;
  x = (x | x << 16) & 0x30000ffu;
  x = (x | x << 8) & 0x300f00fu;
  x = (x | x << 4) & 0x30c30c3u;
  return (x | x << 2) & 0x9249249u;
}

void MeshRayKeys(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                 std::size_t n, std::uint32_t* key) {
  if (mesh.nodeCount == 0) {
    std::fill(key, key + n, kMissKey);
    return;
  }
  const BvhNode& root = mesh.nodes[0];
  const float* rows[6] = {root.minX, root.minY, root.minZ, root.maxX, root.maxY, root.maxZ};
  float lo[3], scale[3];
  for (int a = 0; a < 3; ++a) {
    float l = std::numeric_limits<float>::infinity(), h = -l;
    for (int k = 0; k < BvhNode::kWidth; ++k)
      l = std::min(l, rows[a][k]), h = std::max(h, rows[3 + a][k]);
    lo[a] = l, scale[a] = h > l ? 511 / (h - l) : 0;
  }
  for (std::size_t k = 0; k < n; ++k) {
    // The slab test's fields only: the watertight shear is not needed for the root's boxes.
    detail::TraversalRay ray;
    const std::uint32_t i = index[k];
    using R = fields::Ray;
    detail::setSlabs(ray, rays[R::origin][i], rays[R::origin + 1][i], rays[R::origin + 2][i],
                     rays[R::direction][i], rays[R::direction + 1][i], rays[R::direction + 2][i],
                     rays[R::tMax][i]);
    Any any{ray.tMax};
    alignas(64) std::uint32_t refs[2 * BvhNode::kWidth];
    alignas(64) float dists[2 * BvhNode::kWidth];
    const int entered =
        ray.finiteInverse ? RayCore<Any, true>(mesh, ray, any).expand(root, ray.tMax, refs, dists)
                          : RayCore<Any, false>(mesh, ray, any).expand(root, ray.tMax, refs, dists);
    if (entered == 0) {
      key[k] = kMissKey;
      continue;
    }
    const float t = *std::min_element(dists, dists + entered);
    std::uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      const float u = (ray.origin[a] + t * rays[fields::Ray::direction + a][i] - lo[a]) * scale[a];
      code |= spreadBits(u > 0 ? std::uint32_t(std::min(u, 511.0f)) : 0) << a;  // NaN: 0
    }
    key[k] = code;
  }
}

#include "simd/bvh_packet-inl.hpp"

void MeshClosestHitPackets(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                           std::size_t packets, int width, ElementHit* out) {
  if (width == 16)
    closestHitPackets<16>(mesh, rays, index, packets, out);
  else
    closestHitPackets<8>(mesh, rays, index, packets, out);
}

void MeshClosestHitsOf(const MeshView& mesh, const RaysView& rays, const std::uint32_t* index,
                       std::size_t n, ElementHit* out) {
  for (std::size_t i = 0; i < n; ++i) out[index[i]] = closestHit(mesh, rays, index[i]);
}

void MeshAnyHits(const MeshView& mesh, const RaysView& rays, std::uint8_t* hit) {
  for (std::size_t i = 0; i < rays.count; ++i) {
    const detail::TraversalRay ray = detail::traversalRay(rays, i);
    Any any{ray.tMax};
    traverse(mesh, ray, any);
    hit[i] = any.found ? 1 : 0;
  }
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(MeshClosestHits, meshClosestHits);
SIMDPHYS_EXPORT(MeshAnyHits, meshAnyHits);
SIMDPHYS_EXPORT(MeshClosestHitPackets, meshClosestHitPackets);
SIMDPHYS_EXPORT(MeshClosestHitsOf, meshClosestHitsOf);
SIMDPHYS_EXPORT(MeshRayKeys, meshRayKeys);
}  // namespace simdphys::simd
#endif

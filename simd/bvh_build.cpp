// The BVH builder's passes over a range of primitives: binning, partitioning and bounds, each
// growing a box's three axes with one 4-lane operation (Embree's binner). Min, Max, Add, Sub and
// Mul are exact IEEE operations, so every target bins, splits and measures exactly as the others:
// the tree does not depend on the target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/bvh_build.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <limits>
#include <utility>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

// A row's x, y, z in one vector (or, on HWY_SCALAR, one lane at a time).
using D = hn::CappedTag<float, 4>;
using V = hn::Vec<D>;
constexpr std::size_t kLanes = hn::MaxLanes(D());
constexpr std::size_t kChunks = (3 + kLanes - 1) / kLanes;
constexpr float kInf = std::numeric_limits<float>::infinity();

// Lanes [k, k + kLanes) of a row, the lane past z zeroed: the first row's holds the id, whose bits
// read as a denormal float, and arithmetic on denormals is slow (binning ran 2.6x slower).
HWY_INLINE V Row(const float* row, std::size_t k) {
  const D d;
  return hn::IfThenElseZero(hn::FirstN(d, 3 - k), hn::Load(d, row + k));
}

struct Prim {
  V lo[kChunks], hi[kChunks];
  explicit Prim(const detail::BvhPrimRef& p) {
    for (std::size_t c = 0; c < kChunks; ++c)
      lo[c] = Row(p.lo, c * kLanes), hi[c] = Row(p.hi, c * kLanes);
  }
};

// A box and a centroid box grown in registers.
struct Bounds {
  V lo[kChunks], hi[kChunks], clo[kChunks], chi[kChunks];
  Bounds() {
    const D d;
    for (std::size_t c = 0; c < kChunks; ++c)
      lo[c] = clo[c] = hn::Set(d, kInf), hi[c] = chi[c] = hn::Set(d, -kInf);
  }
  HWY_INLINE void grow(const Prim& p) {
    for (std::size_t c = 0; c < kChunks; ++c) {
      const V centroid = hn::Add(p.lo[c], p.hi[c]);
      lo[c] = hn::Min(lo[c], p.lo[c]), hi[c] = hn::Max(hi[c], p.hi[c]);
      clo[c] = hn::Min(clo[c], centroid), chi[c] = hn::Max(chi[c], centroid);
    }
  }
  void store(BvhBox& box, BvhBox& centroids) const {
    const D d;
    for (std::size_t c = 0; c < kChunks; ++c) {
      hn::Store(lo[c], d, box.lo + c * kLanes), hn::Store(hi[c], d, box.hi + c * kLanes);
      hn::Store(clo[c], d, centroids.lo + c * kLanes);
      hn::Store(chi[c], d, centroids.hi + c * kLanes);
    }
    box.lo[3] = box.hi[3] = centroids.lo[3] = centroids.hi[3] = 0;  // unused; written on 1 lane too
  }
};

void BvhBin(const detail::BvhPrimRef* prims, std::size_t n, const BvhBinFrame& frame,
            BvhBins& out) {
  const D d;
  const hn::RebindToSigned<D> di;
  alignas(16) float origin[4] = {frame.origin[0], frame.origin[1], frame.origin[2], 0};
  alignas(16) float scale[4] = {frame.scale[0], frame.scale[1], frame.scale[2], 0};
  // Even and odd primitives fill separate bins: neighbours often share a bin, and one set would
  // chain every update on the previous one's store.
  BvhBins sets[2];
  for (BvhBins& set : sets)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < frame.bins; ++k) {
        std::fill_n(set.box[a][k].lo, 4, kInf);
        std::fill_n(set.box[a][k].hi, 4, -kInf);
        set.count[a][k] = 0;
      }
  const V top = hn::Set(d, float(frame.bins - 1));
  auto bin = [&](const detail::BvhPrimRef& ref, BvhBins& set) HWY_ATTR {
    const Prim p(ref);
    alignas(16) std::int32_t index[4];
    for (std::size_t c = 0; c < kChunks; ++c) {
      const std::size_t k = c * kLanes;
      // An axis of scale 0 puts everything in bin 0, even a centroid that overflowed to inf
      // (whose product with 0 is NaN, which Min/Max need not clamp).
      const V s = hn::Load(d, scale + k);
      const V x = hn::IfThenElseZero(
          hn::Gt(s, hn::Zero(d)),
          hn::Mul(hn::Sub(hn::Add(p.lo[c], p.hi[c]), hn::Load(d, origin + k)), s));
      hn::Store(hn::ConvertTo(di, hn::Min(hn::Max(x, hn::Zero(d)), top)), di, index + k);
    }
    for (int a = 0; a < 3; ++a) {
      BvhBox& box = set.box[a][index[a]];
      for (std::size_t c = 0; c < kChunks; ++c) {
        const std::size_t k = c * kLanes;
        hn::Store(hn::Min(hn::Load(d, box.lo + k), p.lo[c]), d, box.lo + k);
        hn::Store(hn::Max(hn::Load(d, box.hi + k), p.hi[c]), d, box.hi + k);
      }
      ++set.count[a][index[a]];
    }
  };
  std::size_t i = 0;
  for (; i + 1 < n; i += 2) bin(prims[i], sets[0]), bin(prims[i + 1], sets[1]);
  if (i < n) bin(prims[i], sets[0]);
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < frame.bins; ++k) {
      const BvhBox &b0 = sets[0].box[a][k], &b1 = sets[1].box[a][k];
      for (std::size_t c = 0; c < kChunks; ++c) {
        const std::size_t l = c * kLanes;
        hn::Store(hn::Min(hn::Load(d, b0.lo + l), hn::Load(d, b1.lo + l)), d, out.box[a][k].lo + l);
        hn::Store(hn::Max(hn::Load(d, b0.hi + l), hn::Load(d, b1.hi + l)), d, out.box[a][k].hi + l);
      }
      out.box[a][k].lo[3] = out.box[a][k].hi[3] = 0;  // unused; written on 1 lane too
      out.count[a][k] = sets[0].count[a][k] + sets[1].count[a][k];
    }
}

void BvhPartition(detail::BvhPrimRef* prims, std::size_t n, const BvhBinFrame& frame, int axis,
                  int split, BvhSides& sides) {
  const float origin = frame.origin[axis], scale = frame.scale[axis];
  // The binning kernel's operations on one lane, so a primitive goes to the side its bin says.
  auto goesLeft = [&](const detail::BvhPrimRef& p) {
    const float x = scale > 0 ? (p.centroid(axis) - origin) * scale : 0.0f;
    return int(std::min(std::max(x, 0.0f), float(frame.bins - 1))) < split;
  };
  Bounds left, right;
  std::size_t i = 0, j = n;
  while (true) {
    while (i < j && goesLeft(prims[i])) left.grow(Prim(prims[i++]));
    while (i < j && !goesLeft(prims[j - 1])) right.grow(Prim(prims[--j]));
    if (i >= j) break;
    std::swap(prims[i], prims[j - 1]);
  }
  left.store(sides.box[0], sides.centroids[0]);
  right.store(sides.box[1], sides.centroids[1]);
  sides.left = i;
}

void BvhBounds(const detail::BvhPrimRef* prims, std::size_t n, BvhBox& box, BvhBox& centroids) {
  Bounds b;
  for (std::size_t i = 0; i < n; ++i) b.grow(Prim(prims[i]));
  b.store(box, centroids);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(BvhBin, bvhBin);
SIMDPHYS_EXPORT(BvhPartition, bvhPartition);
SIMDPHYS_EXPORT(BvhBounds, bvhBounds);
}  // namespace simdphys::simd
#endif

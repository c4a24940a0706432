// Where a box of many objects lies against a frustum, for the tree culls (octree and BVH): wholly
// outside a plane (skip every object in it), wholly inside every plane (take them all), or
// neither (look closer). Both verdicts must agree with the per-object test of every object box
// inside, evaluated in float: so they need a margin beyond the rounding of both evaluations.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "simdphys/scene/frustum.hpp"

namespace simdphys::detail {

enum class FrustumSide { kOutside, kPartial, kInside };

// The per-object test n.c + d + |n|.h rounds each of its five operations once: its error is at
// most about 5 eps times sum |n_i| (|c_i| + h_i) + |d|; the same holds for this box's own test,
// and an object's (centre, extents) differ from the min/max box it was bounded with by an ulp.
// Objects inside the box have |c_i| + h_i no larger than the box's, so a margin of 32 eps times
// the box's scale covers the three with room to spare.
inline FrustumSide classify(const Frustum& f, const Vec3f& lo, const Vec3f& hi) {
  constexpr float kMargin = 32 * std::numeric_limits<float>::epsilon();
  const Vec3f c = (lo + hi) * 0.5f, h = (hi - lo) * 0.5f;
  bool inside = true;
  for (const Plane& p : f.planes) {
    const Vec3f an = p.normal.cwiseAbs();
    const float dist = p.normal.dot(c) + p.d;
    const float reach = an.dot(h);
    const float margin = kMargin * (an.dot(c.cwiseAbs() + h) + std::abs(p.d));
    if (dist + reach < -margin) return FrustumSide::kOutside;
    inside = inside && dist - reach >= margin;
  }
  return inside ? FrustumSide::kInside : FrustumSide::kPartial;
}

// Sets bit `id` of a visited-set; true if it was clear.
inline bool markSeen(std::vector<std::uint64_t>& seen, std::uint32_t id) {
  const std::uint64_t bit = std::uint64_t(1) << (id & 63);
  std::uint64_t& word = seen[id >> 6];
  const bool fresh = (word & bit) == 0;
  word |= bit;
  return fresh;
}

// The set bits, ascending.
inline void seenToIds(const std::vector<std::uint64_t>& seen, std::vector<std::uint32_t>& out) {
  out.clear();
  for (std::size_t w = 0; w < seen.size(); ++w)
    for (std::uint64_t bits = seen[w]; bits != 0; bits &= bits - 1)
      out.push_back(std::uint32_t(w * 64 + std::countr_zero(bits)));
}

}  // namespace simdphys::detail

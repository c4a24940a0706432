// One OBB against a stream of OBBs: the 15-axis separating-axis test of geometry3d/intersect.hpp's
// intersects(Obb, Obb), a box per lane. The arithmetic is the scalar function's operation for
// operation (midpoint, relative centres, scale, projections, Eigen's x + (y + z) sums, IEEE square
// roots, no contraction), so every lane gives the scalar's answer bit for bit. Only the order in
// which the axes are tried differs: "separated" is an OR over the axes, so the order is free, and
// the kernel stops as soon as every lane of the vector is separated. The speed comes from there.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/obb_batch.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/compress-inl.hpp"

// The SAT below is written once for a lane type V: a Highway vector (the kernel) or a float (the
// plain-loop baseline). These name the few operations whose spelling differs.
inline float absOf(float x) { return std::abs(x); }
inline float sqrtOf(float x) { return std::sqrt(x); }
inline bool greater(float a, float b) { return a > b; }
inline bool either(bool a, bool b) { return a | b; }
inline bool both(bool a, bool b) { return a & b; }
template <class V>
HWY_INLINE V absOf(V x) {
  return hn::Abs(x);
}
template <class V>
HWY_INLINE V sqrtOf(V x) {
  return hn::Sqrt(x);
}
template <class V>
HWY_INLINE auto greater(V a, V b) {
  return hn::Gt(a, b);
}
template <class M>
HWY_INLINE M either(M a, M b) {
  return hn::Or(a, b);
}
template <class M>
HWY_INLINE M both(M a, M b) {
  return hn::And(a, b);
}

// Eigen's 3-vector dot product (and squared norm): x + (y + z), its unrolled reduction's order.
template <class V>
HWY_INLINE V dot(const V* a, const V* b) {
  return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]);
}

// A box in lanes: centre, half extents, axes (u[i][k]: coordinate k of axis i).
template <class V>
struct BoxLanes {
  V c[3], h[3], u[3][3];
};

// The query box in every lane, with what the SAT needs of it alone, computed as the scalar does.
template <class V>
struct QueryLanes {
  BoxLanes<V> box;
  V halfCenter[3];  // centre * 0.5, the query's half of the midpoint
  V half;           // 0.5
  V halfSum;        // h.sum()
  V length[3];      // |u_i|
  V ownRadius[3];   // the query's radius on its own axis u_i: sum_k h_k |u_k . u_i|
  V tolerance;      // kGeometryTolerance
};

template <class V, class Splat>
QueryLanes<V> queryLanes(const ObbQuery& q, Splat splat) {
  QueryLanes<V> l;
  for (int k = 0; k < 3; ++k) {
    l.box.c[k] = splat(q.center[k]);
    l.box.h[k] = splat(q.half[k]);
    for (int i = 0; i < 3; ++i) l.box.u[i][k] = splat(q.axis[i][k]);
  }
  const BoxLanes<V>& a = l.box;
  l.half = splat(0.5f);
  for (int k = 0; k < 3; ++k) l.halfCenter[k] = a.c[k] * l.half;
  l.halfSum = a.h[0] + (a.h[1] + a.h[2]);
  for (int i = 0; i < 3; ++i) {
    l.length[i] = sqrtOf(dot(a.u[i], a.u[i]));
    l.ownRadius[i] = a.h[0] * absOf(dot(a.u[0], a.u[i])) + a.h[1] * absOf(dot(a.u[1], a.u[i])) +
                     a.h[2] * absOf(dot(a.u[2], a.u[i]));
  }
  l.tolerance = splat(q.tolerance);
  return l;
}

// intersect.hpp's separatedOn for two intervals given as centre and radius on an axis.
template <class V>
HWY_INLINE auto apart(V centerA, V radiusA, V centerB, V radiusB, V tolerance) {
  return either(greater((centerB - radiusB) - (centerA + radiusA), tolerance),
                greater((centerA - radiusA) - (centerB + radiusB), tolerance));
}

// The radius of box (h, u) on an axis, from the dots d_k = u_k . axis: sum_k h_k |d_k|.
template <class V>
HWY_INLINE V radius(const V* h, V d0, V d1, V d2) {
  return h[0] * absOf(d0) + h[1] * absOf(d1) + h[2] * absOf(d2);
}

// Whether box b is separated from the query on one of the 15 axes, or-ed into `separated` (whose
// set lanes are taken as already decided: padding). The loops are unrolled by request: GCC
// vectorises the plain-loop baseline only when no inner loop remains. `done(separated)` is asked
// after each axis; true stops the test (the kernel: all lanes separated; the baseline: never).
template <class V, class M, class Done>
HWY_INLINE M satSeparated(const QueryLanes<V>& q, const BoxLanes<V>& b, M separated, Done done) {
  const BoxLanes<V>& a = q.box;
  // Both boxes relative to the midpoint m = a.c * 0.5 + b.c * 0.5, as the scalar does.
  V ca[3], cb[3];
#pragma GCC unroll 9
  for (int k = 0; k < 3; ++k) {
    const V m = q.halfCenter[k] + b.c[k] * q.half;
    ca[k] = a.c[k] - m;
    cb[k] = b.c[k] - m;
  }
  const V scale =
      (sqrtOf(dot(ca, ca)) + q.halfSum) + (sqrtOf(dot(cb, cb)) + (b.h[0] + (b.h[1] + b.h[2])));
  const V tolScale = q.tolerance * scale;
  // r[i][j] = u_i . v_j: the dot of a query axis with a box axis is the same number whichever of
  // the two is the projection axis (products commute), so both face groups share it.
  V r[3][3];
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 9
    for (int j = 0; j < 3; ++j) r[i][j] = dot(a.u[i], b.u[j]);
      // The query's face axes first: its own radius is a constant there.
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) {
    const V rb = radius(b.h, r[i][0], r[i][1], r[i][2]);
    separated = either(separated, apart(dot(ca, a.u[i]), q.ownRadius[i], dot(cb, a.u[i]), rb,
                                        tolScale * q.length[i]));
    if (done(separated)) return separated;
  }
  // The box's face axes; g[k][j] = v_k . v_j (the diagonal is |v_j|^2, Eigen's squaredNorm).
  V g[3][3], lengthB[3];
#pragma GCC unroll 9
  for (int j = 0; j < 3; ++j)
#pragma GCC unroll 9
    for (int k = 0; k <= j; ++k) g[k][j] = g[j][k] = dot(b.u[k], b.u[j]);
#pragma GCC unroll 9
  for (int j = 0; j < 3; ++j) {
    lengthB[j] = sqrtOf(g[j][j]);
    const V ra = radius(a.h, r[0][j], r[1][j], r[2][j]);
    const V rb = radius(b.h, g[0][j], g[1][j], g[2][j]);
    separated =
        either(separated, apart(dot(ca, b.u[j]), ra, dot(cb, b.u[j]), rb, tolScale * lengthB[j]));
    if (done(separated)) return separated;
  }
  // The edge axes u_i x v_j (Eigen's cross), skipped where the two are parallel: intersect.hpp's
  // crossAxis, |L| > tolerance * (|u_i| |v_j|).
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 9
    for (int j = 0; j < 3; ++j) {
      const V* u = a.u[i];
      const V* v = b.u[j];
      const V axis[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
      const V length = sqrtOf(dot(axis, axis));
      const auto skew = greater(length, q.tolerance * (q.length[i] * lengthB[j]));
      const V ra = radius(a.h, dot(a.u[0], axis), dot(a.u[1], axis), dot(a.u[2], axis));
      const V rb = radius(b.h, dot(b.u[0], axis), dot(b.u[1], axis), dot(b.u[2], axis));
      separated = either(
          separated, both(skew, apart(dot(ca, axis), ra, dot(cb, axis), rb, tolScale * length)));
      if (done(separated)) return separated;
    }
  return separated;
}

std::size_t ObbOverlapsObbs(const ObbQuery& query, const ObbsView& v, std::uint32_t* out) {
  using D = hn::ScalableTag<float>;
  using V = hn::Vec<D>;
  const D d;
  const QueryLanes<V> q = queryLanes<V>(query, [d](float x) { return hn::Set(d, x); });
  return selectIndices(v.padded, out, [&](D, std::size_t i) {
    BoxLanes<V> b;
    for (int k = 0; k < 3; ++k) {
      b.c[k] = hn::Load(d, v[fields::Obb::center + k] + i);
      b.h[k] = hn::Load(d, v[fields::Obb::half + k] + i);
      for (int j = 0; j < 3; ++j) b.u[j][k] = hn::Load(d, v[fields::Obb::axis + 3 * j + k] + i);
    }
    // Lanes past the end start as separated: no padding value is inert for the SAT.
    const auto padding = hn::Not(hn::FirstN(d, v.count > i ? v.count - i : 0));
    const auto allSeparated = [d](hn::Mask<D> m) { return hn::AllTrue(d, m); };
    return hn::Not(satSeparated(q, b, padding, allSeparated));
  });
}

// The baseline: the same SAT as a plain loop over the boxes, every axis, no early exit. A block's
// answers go to an array first, so that the loop computing them carries no dependence between
// iterations (a compacting store would stop the vectoriser), and are compacted after. This file is
// compiled with -fno-math-errno (src/CMakeLists.txt), without which GCC keeps std::sqrt a call
// that may set errno and vectorises nothing; the square roots are the same IEEE ones.
std::size_t ObbOverlapsObbsAutovec(const ObbQuery& query, const ObbsView& v, std::uint32_t* out) {
  const QueryLanes<float> q = queryLanes<float>(query, [](float x) { return x; });
  constexpr std::size_t kBlock = 256;
  std::size_t count = 0;
  for (std::size_t start = 0; start < v.count; start += kBlock) {
    const std::size_t n = std::min(kBlock, v.count - start);
    bool keep[kBlock];
    for (std::size_t e = 0; e < n; ++e) {
      const std::size_t i = start + e;
      BoxLanes<float> b;
#pragma GCC unroll 3
      for (int k = 0; k < 3; ++k) {
        b.c[k] = v[fields::Obb::center + k][i];
        b.h[k] = v[fields::Obb::half + k][i];
#pragma GCC unroll 3
        for (int j = 0; j < 3; ++j) b.u[j][k] = v[fields::Obb::axis + 3 * j + k][i];
      }
      keep[e] = !satSeparated(q, b, false, [](bool) { return false; });
    }
    for (std::size_t e = 0; e < n; ++e) {
      out[count] = static_cast<std::uint32_t>(start + e);
      count += keep[e];
    }
  }
  return count;
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(ObbOverlapsObbs, obbOverlapsObbs);
SIMDPHYS_EXPORT(ObbOverlapsObbsAutovec, obbOverlapsObbsAutovec);
}  // namespace simdphys::simd
#endif

// Batch forms of the 3D shape tests: one shape against a stream, a vector of elements at a time.
// Each mirrors the arithmetic of its scalar function in geometry3d/ (same order, no fusion), so
// the paths agree exactly.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/batch3d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "simd/kernels.hpp"
#include "simdphys/geometry3d/raycast.hpp"  // differenceOfProducts: the exact edge fallback

HWY_BEFORE_NAMESPACE();
namespace simdphys::simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "simd/compress-inl.hpp"
#include "simd/watertight-inl.hpp"

// Eigen sums a 3-vector's terms as x + (y + z) (its unrolled reduction halves the range), so
// squaredNorm and dot are written in that order here.
template <class V>
V dot3(V ax, V ay, V az, V bx, V by, V bz) {
  return hn::Add(hn::Mul(ax, bx), hn::Add(hn::Mul(ay, by), hn::Mul(az, bz)));
}
template <class V>
V squaredLength(V x, V y, V z) {
  return dot3(x, y, z, x, y, z);
}

// intersect.hpp's closed test with its tolerance: |c1 - c2| <= reach + tol (|c1 - c2| + reach).
template <class D, class V>
auto withinReach(D d, V distance, V reach, float tolerance) {
  return hn::Le(distance, hn::Add(reach, hn::Mul(hn::Set(d, tolerance), hn::Add(distance, reach))));
}

std::size_t SphereOverlapsSpheres(const SphereQuery& s, const SpheresView& v, std::uint32_t* out) {
  return selectIndices(v.padded, out, [&](auto d, std::size_t i) {
    const auto dx = hn::Sub(hn::Load(d, v.x + i), hn::Set(d, s.x));
    const auto dy = hn::Sub(hn::Load(d, v.y + i), hn::Set(d, s.y));
    const auto dz = hn::Sub(hn::Load(d, v.z + i), hn::Set(d, s.z));
    const auto reach = hn::Add(hn::Set(d, s.r), hn::Load(d, v.r + i));
    // Padding has radius -inf, so a reach of -inf, which no distance is within.
    return withinReach(d, hn::Sqrt(squaredLength(dx, dy, dz)), reach, s.tolerance);
  });
}

// The point of box i closest to p, per axis: p clamped to [min, max].
template <class D>
auto clampTo(D d, float p, const float* lo, const float* hi, std::size_t i) {
  return hn::Min(hn::Max(hn::Set(d, p), hn::Load(d, lo + i)), hn::Load(d, hi + i));
}

std::size_t SphereOverlapsBoxes(const SphereQuery& s, const BoxesView& v, std::uint32_t* out) {
  return selectIndices(v.padded, out, [&](auto d, std::size_t i) {
    const auto dx = hn::Sub(hn::Set(d, s.x), clampTo(d, s.x, v.minX, v.maxX, i));
    const auto dy = hn::Sub(hn::Set(d, s.y), clampTo(d, s.y, v.minY, v.maxY, i));
    const auto dz = hn::Sub(hn::Set(d, s.z), clampTo(d, s.z, v.minZ, v.maxZ, i));
    // Padding boxes are empty (min > max), which no valid box is; their infinite distance alone
    // would pass the tolerance test (inf <= inf).
    const auto real = hn::Le(hn::Load(d, v.minX + i), hn::Load(d, v.maxX + i));
    return hn::And(
        real, withinReach(d, hn::Sqrt(squaredLength(dx, dy, dz)), hn::Set(d, s.r), s.tolerance));
  });
}

std::size_t PointInBoxes(float x, float y, float z, const BoxesView& v, std::uint32_t* out) {
  return selectIndices(v.padded, out, [&](auto d, std::size_t i) {
    auto in = [&](float p, const float* lo, const float* hi) {
      const auto q = hn::Set(d, p);
      return hn::And(hn::Le(hn::Load(d, lo + i), q), hn::Le(q, hn::Load(d, hi + i)));
    };
    return hn::And(in(x, v.minX, v.maxX), hn::And(in(y, v.minY, v.maxY), in(z, v.minZ, v.maxZ)));
  });
}

void ClosestPointsOnBoxes(float x, float y, float z, const BoxesView& v, float* cx, float* cy,
                          float* cz) {
  const hn::ScalableTag<float> d;
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    hn::Store(clampTo(d, x, v.minX, v.maxX, i), d, cx + i);
    hn::Store(clampTo(d, y, v.minY, v.maxY, i), d, cy + i);
    hn::Store(clampTo(d, z, v.minZ, v.maxZ, i), d, cz + i);
  }
}

// Keeps, lane by lane, the smallest t seen and its index (strictly smaller: the first index wins
// a tie within a lane), then reduces across lanes with ties to the smaller index.
template <class D>
class ClosestHit {
 public:
  explicit ClosestHit(D d)
      : t_(hn::Set(d, std::numeric_limits<float>::infinity())), index_(hn::Set(du(d), kNoHit)) {}

  template <class M>
  void offer(D d, std::size_t i, M hit, hn::Vec<D> t) {
    const auto better = hn::And(hit, hn::Lt(t, t_));
    t_ = hn::IfThenElse(better, t, t_);
    const auto index = hn::Add(hn::Iota(du(d), 0), hn::Set(du(d), std::uint32_t(i)));
    index_ = hn::IfThenElse(hn::RebindMask(du(d), better), index, index_);
  }

  StreamHit result(D d) const {
    alignas(64) float t[hn::MaxLanes(D())];
    alignas(64) std::uint32_t index[hn::MaxLanes(D())];
    hn::Store(t_, d, t);
    hn::Store(index_, du(d), index);
    StreamHit best{kNoHit, std::numeric_limits<float>::infinity()};
    for (std::size_t k = 0; k < hn::Lanes(d); ++k)
      if (index[k] != kNoHit && (t[k] < best.t || (t[k] == best.t && index[k] < best.index)))
        best = {index[k], t[k]};
    return best;
  }

 private:
  static hn::RebindToUnsigned<D> du(D) { return {}; }
  hn::Vec<D> t_;
  hn::Vec<hn::RebindToUnsigned<D>> index_;
};

// The slab test of geometry3d/raycast.hpp: near and far faces chosen by the sign bit of the
// direction, (face - o) / d, a NaN (origin on a face plane, direction 0) bounds nothing.
StreamHit RayClosestBox(const RayQuery& r, const BoxesView& v) {
  const hn::ScalableTag<float> d;
  const float o[3] = {r.ox, r.oy, r.oz}, dir[3] = {r.dx, r.dy, r.dz};
  const float* lo[3] = {v.minX, v.minY, v.minZ};
  const float* hi[3] = {v.maxX, v.maxY, v.maxZ};
  const float *nearFace[3], *farFace[3];
  for (int a = 0; a < 3; ++a) {
    const bool negative = std::signbit(dir[a]);
    nearFace[a] = negative ? hi[a] : lo[a];
    farFace[a] = negative ? lo[a] : hi[a];
  }
  ClosestHit closest(d);
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    auto enter = hn::Set(d, -std::numeric_limits<float>::infinity());
    auto exit = hn::Set(d, std::numeric_limits<float>::infinity());
    for (int a = 0; a < 3; ++a) {
      const auto oa = hn::Set(d, o[a]), da = hn::Set(d, dir[a]);
      const auto tNear = hn::Div(hn::Sub(hn::Load(d, nearFace[a] + i), oa), da);
      const auto tFar = hn::Div(hn::Sub(hn::Load(d, farFace[a] + i), oa), da);
      enter = hn::IfThenElse(hn::Gt(tNear, enter), tNear, enter);
      exit = hn::IfThenElse(hn::Lt(tFar, exit), tFar, exit);
    }
    const auto zero = hn::Zero(d), tMax = hn::Set(d, r.tMax);
    const auto fromOutside = hn::Ge(enter, zero);
    const auto t = hn::Add(hn::IfThenElse(fromOutside, enter, exit), zero);  // -0 becomes +0
    const auto hit = hn::And(hn::Le(enter, exit), hn::And(hn::Ge(t, zero), hn::Le(t, tMax)));
    closest.offer(d, i, hit, t);
  }
  return closest.result(d);
}

// The sphere test of geometry3d/raycast.hpp, step for step: the chord's half-length from the
// distance of the centre to the line, the entry as (c0 / dd) / (b + f) to avoid cancellation.
StreamHit RayClosestSphere(const RayQuery& r, const SpheresView& v) {
  const hn::ScalableTag<float> d;
  const auto dx = hn::Set(d, r.dx), dy = hn::Set(d, r.dy), dz = hn::Set(d, r.dz);
  const auto dd = squaredLength(dx, dy, dz);
  ClosestHit closest(d);
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    const auto ex = hn::Sub(hn::Load(d, v.x + i), hn::Set(d, r.ox));
    const auto ey = hn::Sub(hn::Load(d, v.y + i), hn::Set(d, r.oy));
    const auto ez = hn::Sub(hn::Load(d, v.z + i), hn::Set(d, r.oz));
    const auto radius = hn::Load(d, v.r + i);
    const auto r2 = hn::Mul(radius, radius);
    const auto c0 = hn::Sub(squaredLength(ex, ey, ez), r2);
    const auto b = hn::Div(dot3(ex, ey, ez, dx, dy, dz), dd);
    auto mx = hn::Sub(ex, hn::Mul(b, dx)), my = hn::Sub(ey, hn::Mul(b, dy)),
         mz = hn::Sub(ez, hn::Mul(b, dz));
    const auto k = hn::Div(dot3(mx, my, mz, dx, dy, dz), dd);
    mx = hn::Sub(mx, hn::Mul(k, dx)), my = hn::Sub(my, hn::Mul(k, dy)),
    mz = hn::Sub(mz, hn::Mul(k, dz));
    const auto h2 = hn::Sub(r2, squaredLength(mx, my, mz));
    const auto zero = hn::Zero(d);
    const auto c0dd = hn::Div(c0, dd);
    // Outside (c0 > 0): the entry, if the sphere is ahead (b > 0) and the line meets it.
    const auto fOut = hn::Sqrt(hn::Div(h2, dd));
    const auto tOut = hn::Div(c0dd, hn::Add(b, fOut));
    const auto hitOut = hn::And(hn::Gt(c0, zero), hn::And(hn::Gt(b, zero), hn::Ge(h2, zero)));
    // Inside (c0 < 0): the exit, always ahead. On the surface (c0 == 0): t = 0.
    const auto fIn = hn::Sqrt(hn::Div(hn::Max(h2, zero), dd));
    const auto tIn =
        hn::IfThenElse(hn::Ge(b, zero), hn::Add(b, fIn), hn::Div(c0dd, hn::Sub(b, fIn)));
    auto t = hn::IfThenElse(hn::Gt(c0, zero), tOut, hn::IfThenElse(hn::Lt(c0, zero), tIn, zero));
    // Padding has radius -inf: excluded by the radius test, which no real sphere fails.
    const auto valid = hn::And(hn::Or(hitOut, hn::Le(c0, zero)), hn::Ge(radius, zero));
    closest.offer(d, i, hn::And(valid, hn::Le(t, hn::Set(d, r.tMax))), t);
  }
  return closest.result(d);
}

// raycast.hpp's intersectTriangle, lane per triangle (watertight-inl.hpp).
StreamHit RayClosestTriangle(const WatertightQuery& r, const TrianglesView& v) {
  const hn::ScalableTag<float> d;
  ClosestHit closest(d);
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    hn::Vec<decltype(d)> t;
    const auto hit = watertightHits(
        d, r, r.tMax, [&](int q, int k) { return hn::Load(d, v.v[q][k] + i); }, t);
    closest.offer(d, i, hit, t);
  }
  return closest.result(d);
}

}  // namespace HWY_NAMESPACE
}  // namespace simdphys::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace simdphys::simd {
HWY_EXPORT(SphereOverlapsSpheres);
HWY_EXPORT(SphereOverlapsBoxes);
HWY_EXPORT(PointInBoxes);
HWY_EXPORT(ClosestPointsOnBoxes);
HWY_EXPORT(RayClosestBox);
HWY_EXPORT(RayClosestSphere);
HWY_EXPORT(RayClosestTriangle);

StreamHit rayClosestTriangle(const WatertightQuery& ray, const TrianglesView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestTriangle)(ray, v);
}

StreamHit rayClosestBox(const RayQuery& ray, const BoxesView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestBox)(ray, v);
}
StreamHit rayClosestSphere(const RayQuery& ray, const SpheresView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestSphere)(ray, v);
}

std::size_t sphereOverlapsSpheres(const SphereQuery& s, const SpheresView& v, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(SphereOverlapsSpheres)(s, v, out);
}
std::size_t sphereOverlapsBoxes(const SphereQuery& s, const BoxesView& v, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(SphereOverlapsBoxes)(s, v, out);
}
std::size_t pointInBoxes(float x, float y, float z, const BoxesView& v, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(PointInBoxes)(x, y, z, v, out);
}
void closestPointsOnBoxes(float x, float y, float z, const BoxesView& v, float* cx, float* cy,
                          float* cz) {
  HWY_DYNAMIC_DISPATCH(ClosestPointsOnBoxes)(x, y, z, v, cx, cy, cz);
}
}  // namespace simdphys::simd
#endif

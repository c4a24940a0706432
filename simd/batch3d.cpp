// Batch forms of the 3D shape tests: one shape against a stream, a vector of elements at a time,
// and beside them their plain-loop baselines. Each mirrors the arithmetic of its scalar function
// in geometry3d/ (same order, no fusion), so the paths agree exactly.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/batch3d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

// ray_slab-inl.hpp names the slab constants of traversal_ray.hpp.
#include "core/traversal_ray.hpp"
#include "simd/export.hpp"
#include "simd/kernels.hpp"
#include "simdphys/detail/float_math.hpp"  // differenceOfProducts: the exact edge fallback

// watertight-inl.hpp names the helper by its old place in raycast.hpp.
namespace simdphys::simd::detail::rays {
using simdphys::detail::differenceOfProducts;
}

SIMDPHYS_TARGET_BEGIN();

#include "simd/compress-inl.hpp"
#include "simd/watertight-inl.hpp"
// The one ray-box slab test (clipSlab), for vectors of boxes and, through the one-float lane
// declared first, for the plain-loop baseline.
#include "core/scalar_lanes-inl.hpp"

#include "core/ray_slab-inl.hpp"

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
    const auto dx = hn::Sub(hn::Load(d, v[fields::Sphere::x] + i), hn::Set(d, s.x));
    const auto dy = hn::Sub(hn::Load(d, v[fields::Sphere::y] + i), hn::Set(d, s.y));
    const auto dz = hn::Sub(hn::Load(d, v[fields::Sphere::z] + i), hn::Set(d, s.z));
    const auto reach = hn::Add(hn::Set(d, s.r), hn::Load(d, v[fields::Sphere::r] + i));
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
    const auto dx =
        hn::Sub(hn::Set(d, s.x), clampTo(d, s.x, v[fields::Box::minX], v[fields::Box::maxX], i));
    const auto dy =
        hn::Sub(hn::Set(d, s.y), clampTo(d, s.y, v[fields::Box::minY], v[fields::Box::maxY], i));
    const auto dz =
        hn::Sub(hn::Set(d, s.z), clampTo(d, s.z, v[fields::Box::minZ], v[fields::Box::maxZ], i));
    // Padding boxes are empty (min > max), which no valid box is; their infinite distance alone
    // would pass the tolerance test (inf <= inf).
    const auto real =
        hn::Le(hn::Load(d, v[fields::Box::minX] + i), hn::Load(d, v[fields::Box::maxX] + i));
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
    return hn::And(in(x, v[fields::Box::minX], v[fields::Box::maxX]),
                   hn::And(in(y, v[fields::Box::minY], v[fields::Box::maxY]),
                           in(z, v[fields::Box::minZ], v[fields::Box::maxZ])));
  });
}

void ClosestPointsOnBoxes(float x, float y, float z, const BoxesView& v, float* cx, float* cy,
                          float* cz) {
  const hn::ScalableTag<float> d;
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    hn::Store(clampTo(d, x, v[fields::Box::minX], v[fields::Box::maxX], i), d, cx + i);
    hn::Store(clampTo(d, y, v[fields::Box::minY], v[fields::Box::maxY], i), d, cy + i);
    hn::Store(clampTo(d, z, v[fields::Box::minZ], v[fields::Box::maxZ], i), d, cz + i);
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

  ElementHit result(D d) const {
    alignas(64) float t[hn::MaxLanes(D())];
    alignas(64) std::uint32_t index[hn::MaxLanes(D())];
    hn::Store(t_, d, t);
    hn::Store(index_, du(d), index);
    ElementHit best;  // a miss
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
// direction, (face - o) / d, each clipping (-inf, inf) by clipSlab's comparisons, so that a NaN
// (origin on a face plane, direction 0) bounds nothing.
ElementHit RayClosestBox(const RayQuery& r, const BoxesView& v) {
  const hn::ScalableTag<float> d;
  const float o[3] = {r.ox, r.oy, r.oz}, dir[3] = {r.dx, r.dy, r.dz};
  const float* lo[3] = {v[fields::Box::minX], v[fields::Box::minY], v[fields::Box::minZ]};
  const float* hi[3] = {v[fields::Box::maxX], v[fields::Box::maxY], v[fields::Box::maxZ]};
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
      clipSlab<false>(tNear, tFar, enter, exit);
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
ElementHit RayClosestSphere(const RayQuery& r, const SpheresView& v) {
  const hn::ScalableTag<float> d;
  const auto dx = hn::Set(d, r.dx), dy = hn::Set(d, r.dy), dz = hn::Set(d, r.dz);
  const auto dd = squaredLength(dx, dy, dz);
  ClosestHit closest(d);
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    const auto ex = hn::Sub(hn::Load(d, v[fields::Sphere::x] + i), hn::Set(d, r.ox));
    const auto ey = hn::Sub(hn::Load(d, v[fields::Sphere::y] + i), hn::Set(d, r.oy));
    const auto ez = hn::Sub(hn::Load(d, v[fields::Sphere::z] + i), hn::Set(d, r.oz));
    const auto radius = hn::Load(d, v[fields::Sphere::r] + i);
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
ElementHit RayClosestTriangle(const WatertightQuery& r, const TrianglesView& v) {
  const hn::ScalableTag<float> d;
  ClosestHit closest(d);
  for (std::size_t i = 0; i < v.padded; i += hn::Lanes(d)) {
    hn::Vec<decltype(d)> t;
    const auto hit = watertightHits(
        d, r, r.tMax,
        [&](int q, int k) { return hn::Load(d, v[fields::Triangle::vertex + 3 * q + k] + i); }, t);
    closest.offer(d, i, hit, t);
  }
  return closest.result(d);
}

// ---- baselines -----------------------------------------------------------------------------
// The same forms as plain loops over the elements, left to the compiler's auto-vectoriser and
// compiled for each target like the kernels: same arithmetic, same answers; only the SIMD
// formulation differs.

float length3(float x, float y, float z) { return std::sqrt(x * x + (y * y + z * z)); }

// Indices of the elements that pass `test`, written without a branch on the result.
template <class Test>
std::size_t select(std::size_t count, std::uint32_t* out, Test test) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < count; ++i) {
    out[n] = std::uint32_t(i);
    n += test(i);
  }
  return n;
}

std::size_t SphereOverlapsSpheresAutovec(const SphereQuery& s, const SpheresView& v,
                                         std::uint32_t* out) {
  return select(v.count, out, [&](std::size_t i) {
    const float distance = length3(v[fields::Sphere::x][i] - s.x, v[fields::Sphere::y][i] - s.y,
                                   v[fields::Sphere::z][i] - s.z);
    const float reach = s.r + v[fields::Sphere::r][i];
    return distance <= reach + s.tolerance * (distance + reach);
  });
}

std::size_t SphereOverlapsBoxesAutovec(const SphereQuery& s, const BoxesView& v,
                                       std::uint32_t* out) {
  return select(v.count, out, [&](std::size_t i) {
    const float dx =
        s.x - std::min(std::max(s.x, v[fields::Box::minX][i]), v[fields::Box::maxX][i]);
    const float dy =
        s.y - std::min(std::max(s.y, v[fields::Box::minY][i]), v[fields::Box::maxY][i]);
    const float dz =
        s.z - std::min(std::max(s.z, v[fields::Box::minZ][i]), v[fields::Box::maxZ][i]);
    const float distance = length3(dx, dy, dz);
    return distance <= s.r + s.tolerance * (distance + s.r);
  });
}

std::size_t PointInBoxesAutovec(float x, float y, float z, const BoxesView& v, std::uint32_t* out) {
  return select(v.count, out, [&](std::size_t i) {
    return (v[fields::Box::minX][i] <= x) & (x <= v[fields::Box::maxX][i]) &
           (v[fields::Box::minY][i] <= y) & (y <= v[fields::Box::maxY][i]) &
           (v[fields::Box::minZ][i] <= z) & (z <= v[fields::Box::maxZ][i]);
  });
}

void ClosestPointsOnBoxesAutovec(float x, float y, float z, const BoxesView& v, float* cx,
                                 float* cy, float* cz) {
  for (std::size_t i = 0; i < v.count; ++i) {
    cx[i] = std::min(std::max(x, v[fields::Box::minX][i]), v[fields::Box::maxX][i]);
    cy[i] = std::min(std::max(y, v[fields::Box::minY][i]), v[fields::Box::maxY][i]);
    cz[i] = std::min(std::max(z, v[fields::Box::minZ][i]), v[fields::Box::maxZ][i]);
  }
}

ElementHit RayClosestBoxAutovec(const RayQuery& r, const BoxesView& v) {
  const float o[3] = {r.ox, r.oy, r.oz}, dir[3] = {r.dx, r.dy, r.dz};
  const float* lo[3] = {v[fields::Box::minX], v[fields::Box::minY], v[fields::Box::minZ]};
  const float* hi[3] = {v[fields::Box::maxX], v[fields::Box::maxY], v[fields::Box::maxZ]};
  ElementHit best;  // a miss
  for (std::size_t i = 0; i < v.count; ++i) {
    float enter = -std::numeric_limits<float>::infinity();
    float exit = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
      const bool negative = std::signbit(dir[a]);
      const float tNear = ((negative ? hi[a][i] : lo[a][i]) - o[a]) / dir[a];
      const float tFar = ((negative ? lo[a][i] : hi[a][i]) - o[a]) / dir[a];
      clipSlab<false>(tNear, tFar, enter, exit);
    }
    const float t = (enter >= 0 ? enter : exit) + 0.0f;
    if (enter <= exit && t >= 0 && t <= r.tMax && t < best.t) best = {std::uint32_t(i), t};
  }
  return best;
}

ElementHit RayClosestSphereAutovec(const RayQuery& r, const SpheresView& v) {
  const float dd = r.dx * r.dx + (r.dy * r.dy + r.dz * r.dz);
  ElementHit best;  // a miss
  for (std::size_t i = 0; i < v.count; ++i) {
    const float ex = v[fields::Sphere::x][i] - r.ox, ey = v[fields::Sphere::y][i] - r.oy,
                ez = v[fields::Sphere::z][i] - r.oz;
    const float r2 = v[fields::Sphere::r][i] * v[fields::Sphere::r][i];
    const float c0 = (ex * ex + (ey * ey + ez * ez)) - r2;
    const float b = (ex * r.dx + (ey * r.dy + ez * r.dz)) / dd;
    float mx = ex - b * r.dx, my = ey - b * r.dy, mz = ez - b * r.dz;
    const float k = (mx * r.dx + (my * r.dy + mz * r.dz)) / dd;
    mx -= k * r.dx, my -= k * r.dy, mz -= k * r.dz;
    const float h2 = r2 - (mx * mx + (my * my + mz * mz));
    float t = 0;
    bool hit = c0 <= 0;
    if (c0 > 0) {
      const float f = std::sqrt(h2 / dd);
      t = (c0 / dd) / (b + f);
      hit = b > 0 && h2 >= 0;
    } else if (c0 < 0) {
      const float f = std::sqrt(std::max(h2, 0.0f) / dd);
      t = b >= 0 ? b + f : (c0 / dd) / (b - f);
    }
    if (hit && t <= r.tMax && t < best.t) best = {std::uint32_t(i), t};
  }
  return best;
}

// raycast.hpp's intersectTriangle per element: plain products, recomputed exactly only where one
// rounds to zero.
ElementHit RayClosestTriangleAutovec(const WatertightQuery& r, const TrianglesView& v) {
  const float origin[3] = {r.ox, r.oy, r.oz};
  const int k[3] = {r.kx, r.ky, r.kz};
  ElementHit best;  // a miss
  for (std::size_t i = 0; i < v.count; ++i) {
    float px[3], py[3], pz[3];
    for (int q = 0; q < 3; ++q) {
      pz[q] = v[fields::Triangle::vertex + 3 * q + k[2]][i] - origin[k[2]];
      px[q] = (v[fields::Triangle::vertex + 3 * q + k[0]][i] - origin[k[0]]) - r.sx * pz[q];
      py[q] = (v[fields::Triangle::vertex + 3 * q + k[1]][i] - origin[k[1]]) - r.sy * pz[q];
    }
    float u = px[2] * py[1] - py[2] * px[1];
    float w1 = px[0] * py[2] - py[0] * px[2];
    float w2 = px[1] * py[0] - py[1] * px[0];
    if (u == 0 || w1 == 0 || w2 == 0) {
      u = simdphys::detail::differenceOfProducts(px[2], py[1], py[2], px[1]);
      w1 = simdphys::detail::differenceOfProducts(px[0], py[2], py[0], px[2]);
      w2 = simdphys::detail::differenceOfProducts(px[1], py[0], py[1], px[0]);
    }
    const bool anyNegative = u < 0 || w1 < 0 || w2 < 0;
    const bool anyPositive = u > 0 || w1 > 0 || w2 > 0;
    const float det = (u + w1) + w2;
    const float scaled = (u * (r.sz * pz[0]) + w1 * (r.sz * pz[1])) + w2 * (r.sz * pz[2]);
    const float t = (std::isfinite(scaled) ? scaled / det
                                           : u / det * (r.sz * pz[0]) + w1 / det * (r.sz * pz[1]) +
                                                 w2 / det * (r.sz * pz[2])) +
                    0.0f;
    if (!(anyNegative && anyPositive) && det != 0 && t >= 0 && t <= r.tMax && t < best.t)
      best = {std::uint32_t(i), t};
  }
  return best;
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(SphereOverlapsSpheres, sphereOverlapsSpheres);
SIMDPHYS_EXPORT(SphereOverlapsBoxes, sphereOverlapsBoxes);
SIMDPHYS_EXPORT(PointInBoxes, pointInBoxes);
SIMDPHYS_EXPORT(ClosestPointsOnBoxes, closestPointsOnBoxes);
SIMDPHYS_EXPORT(RayClosestBox, rayClosestBox);
SIMDPHYS_EXPORT(RayClosestSphere, rayClosestSphere);
SIMDPHYS_EXPORT(RayClosestTriangle, rayClosestTriangle);
SIMDPHYS_EXPORT(SphereOverlapsSpheresAutovec, sphereOverlapsSpheresAutovec);
SIMDPHYS_EXPORT(SphereOverlapsBoxesAutovec, sphereOverlapsBoxesAutovec);
SIMDPHYS_EXPORT(PointInBoxesAutovec, pointInBoxesAutovec);
SIMDPHYS_EXPORT(ClosestPointsOnBoxesAutovec, closestPointsOnBoxesAutovec);
SIMDPHYS_EXPORT(RayClosestBoxAutovec, rayClosestBoxAutovec);
SIMDPHYS_EXPORT(RayClosestSphereAutovec, rayClosestSphereAutovec);
SIMDPHYS_EXPORT(RayClosestTriangleAutovec, rayClosestTriangleAutovec);
}  // namespace simdphys::simd
#endif

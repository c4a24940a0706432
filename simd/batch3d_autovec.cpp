// Baselines for the benchmarks: the batch forms of batch3d.cpp as plain loops over the elements,
// left to the compiler's auto-vectoriser and compiled for each target like the kernels. Same
// arithmetic, same answers; only the SIMD formulation differs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/batch3d_autovec.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "simd/kernels.hpp"
#include "simdphys/geometry3d/raycast.hpp"  // differenceOfProducts

HWY_BEFORE_NAMESPACE();
namespace simdphys::simd {
namespace HWY_NAMESPACE {

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
    const float distance = length3(v.x[i] - s.x, v.y[i] - s.y, v.z[i] - s.z);
    const float reach = s.r + v.r[i];
    return distance <= reach + s.tolerance * (distance + reach);
  });
}

std::size_t SphereOverlapsBoxesAutovec(const SphereQuery& s, const BoxesView& v,
                                       std::uint32_t* out) {
  return select(v.count, out, [&](std::size_t i) {
    const float dx = s.x - std::min(std::max(s.x, v.minX[i]), v.maxX[i]);
    const float dy = s.y - std::min(std::max(s.y, v.minY[i]), v.maxY[i]);
    const float dz = s.z - std::min(std::max(s.z, v.minZ[i]), v.maxZ[i]);
    const float distance = length3(dx, dy, dz);
    return distance <= s.r + s.tolerance * (distance + s.r);
  });
}

std::size_t PointInBoxesAutovec(float x, float y, float z, const BoxesView& v, std::uint32_t* out) {
  return select(v.count, out, [&](std::size_t i) {
    return (v.minX[i] <= x) & (x <= v.maxX[i]) & (v.minY[i] <= y) & (y <= v.maxY[i]) &
           (v.minZ[i] <= z) & (z <= v.maxZ[i]);
  });
}

void ClosestPointsOnBoxesAutovec(float x, float y, float z, const BoxesView& v, float* cx,
                                 float* cy, float* cz) {
  for (std::size_t i = 0; i < v.count; ++i) {
    cx[i] = std::min(std::max(x, v.minX[i]), v.maxX[i]);
    cy[i] = std::min(std::max(y, v.minY[i]), v.maxY[i]);
    cz[i] = std::min(std::max(z, v.minZ[i]), v.maxZ[i]);
  }
}

StreamHit RayClosestBoxAutovec(const RayQuery& r, const BoxesView& v) {
  const float o[3] = {r.ox, r.oy, r.oz}, dir[3] = {r.dx, r.dy, r.dz};
  const float* lo[3] = {v.minX, v.minY, v.minZ};
  const float* hi[3] = {v.maxX, v.maxY, v.maxZ};
  StreamHit best{kNoHit, std::numeric_limits<float>::infinity()};
  for (std::size_t i = 0; i < v.count; ++i) {
    float enter = -std::numeric_limits<float>::infinity();
    float exit = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a) {
      const bool negative = std::signbit(dir[a]);
      const float tNear = ((negative ? hi[a][i] : lo[a][i]) - o[a]) / dir[a];
      const float tFar = ((negative ? lo[a][i] : hi[a][i]) - o[a]) / dir[a];
      enter = tNear > enter ? tNear : enter;
      exit = tFar < exit ? tFar : exit;
    }
    const float t = (enter >= 0 ? enter : exit) + 0.0f;
    if (enter <= exit && t >= 0 && t <= r.tMax && t < best.t) best = {std::uint32_t(i), t};
  }
  return best;
}

StreamHit RayClosestSphereAutovec(const RayQuery& r, const SpheresView& v) {
  const float dd = r.dx * r.dx + (r.dy * r.dy + r.dz * r.dz);
  StreamHit best{kNoHit, std::numeric_limits<float>::infinity()};
  for (std::size_t i = 0; i < v.count; ++i) {
    const float ex = v.x[i] - r.ox, ey = v.y[i] - r.oy, ez = v.z[i] - r.oz;
    const float r2 = v.r[i] * v.r[i];
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
StreamHit RayClosestTriangleAutovec(const WatertightQuery& r, const TrianglesView& v) {
  const float origin[3] = {r.ox, r.oy, r.oz};
  const int k[3] = {r.kx, r.ky, r.kz};
  StreamHit best{kNoHit, std::numeric_limits<float>::infinity()};
  for (std::size_t i = 0; i < v.count; ++i) {
    float px[3], py[3], pz[3];
    for (int q = 0; q < 3; ++q) {
      pz[q] = v.v[q][k[2]][i] - origin[k[2]];
      px[q] = (v.v[q][k[0]][i] - origin[k[0]]) - r.sx * pz[q];
      py[q] = (v.v[q][k[1]][i] - origin[k[1]]) - r.sy * pz[q];
    }
    float u = px[2] * py[1] - py[2] * px[1];
    float w1 = px[0] * py[2] - py[0] * px[2];
    float w2 = px[1] * py[0] - py[1] * px[0];
    if (u == 0 || w1 == 0 || w2 == 0) {
      u = detail::rays::differenceOfProducts(px[2], py[1], py[2], px[1]);
      w1 = detail::rays::differenceOfProducts(px[0], py[2], py[0], px[2]);
      w2 = detail::rays::differenceOfProducts(px[1], py[0], py[1], px[0]);
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

}  // namespace HWY_NAMESPACE
}  // namespace simdphys::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace simdphys::simd {
HWY_EXPORT(SphereOverlapsSpheresAutovec);
HWY_EXPORT(SphereOverlapsBoxesAutovec);
HWY_EXPORT(PointInBoxesAutovec);
HWY_EXPORT(ClosestPointsOnBoxesAutovec);
HWY_EXPORT(RayClosestBoxAutovec);
HWY_EXPORT(RayClosestSphereAutovec);
HWY_EXPORT(RayClosestTriangleAutovec);

std::size_t sphereOverlapsSpheresAutovec(const SphereQuery& s, const SpheresView& v,
                                         std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(SphereOverlapsSpheresAutovec)(s, v, out);
}
std::size_t sphereOverlapsBoxesAutovec(const SphereQuery& s, const BoxesView& v,
                                       std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(SphereOverlapsBoxesAutovec)(s, v, out);
}
std::size_t pointInBoxesAutovec(float x, float y, float z, const BoxesView& v, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(PointInBoxesAutovec)(x, y, z, v, out);
}
void closestPointsOnBoxesAutovec(float x, float y, float z, const BoxesView& v, float* cx,
                                 float* cy, float* cz) {
  HWY_DYNAMIC_DISPATCH(ClosestPointsOnBoxesAutovec)(x, y, z, v, cx, cy, cz);
}
StreamHit rayClosestBoxAutovec(const RayQuery& ray, const BoxesView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestBoxAutovec)(ray, v);
}
StreamHit rayClosestSphereAutovec(const RayQuery& ray, const SpheresView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestSphereAutovec)(ray, v);
}
StreamHit rayClosestTriangleAutovec(const WatertightQuery& ray, const TrianglesView& v) {
  return HWY_DYNAMIC_DISPATCH(RayClosestTriangleAutovec)(ray, v);
}
}  // namespace simdphys::simd
#endif

// W6: spheres and boxes against the six planes of a frustum. Streaming and memory bound: one pass,
// visible indices compacted with CompressStore. Sums are evaluated in the order of the scalar
// reference (scene.hpp) without fusing, so every path returns the same indices.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/cull.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/compress-inl.hpp"

// n.p + d, summed in the reference's order: ((nx x + ny y) + nz z) + d.
template <class D, class V>
V planeDistance(D d, const Planes& p, int k, V x, V y, V z) {
  auto dot = hn::Add(hn::Add(hn::Mul(hn::Set(d, p.nx[k]), x), hn::Mul(hn::Set(d, p.ny[k]), y)),
                     hn::Mul(hn::Set(d, p.nz[k]), z));
  return hn::Add(dot, hn::Set(d, p.d[k]));
}

std::size_t CullSpheres(const Planes& p, const SpheresView& s, std::uint32_t* out) {
  return selectIndices(s.padded, out, [&](auto d, std::size_t i) {
    const auto x = hn::Load(d, s[fields::Sphere::x] + i), y = hn::Load(d, s[fields::Sphere::y] + i),
               z = hn::Load(d, s[fields::Sphere::z] + i);
    const auto negR = hn::Neg(hn::Load(d, s[fields::Sphere::r] + i));
    auto keep = hn::Ge(planeDistance(d, p, 0, x, y, z), negR);
    for (int k = 1; k < 6; ++k) keep = hn::And(keep, hn::Ge(planeDistance(d, p, k, x, y, z), negR));
    return keep;
  });
}

std::size_t CullBounds(const Planes& p, const BoundsView& b, std::uint32_t* out) {
  return selectIndices(b.padded, out, [&](auto d, std::size_t i) {
    const auto x = hn::Load(d, b[fields::Bounds::cx] + i),
               y = hn::Load(d, b[fields::Bounds::cy] + i),
               z = hn::Load(d, b[fields::Bounds::cz] + i);
    const auto ex = hn::Load(d, b[fields::Bounds::ex] + i),
               ey = hn::Load(d, b[fields::Bounds::ey] + i),
               ez = hn::Load(d, b[fields::Bounds::ez] + i);
    auto visible = [&](int k) {
      auto reach = hn::Add(hn::Add(hn::Mul(hn::Set(d, std::abs(p.nx[k])), ex),
                                   hn::Mul(hn::Set(d, std::abs(p.ny[k])), ey)),
                           hn::Mul(hn::Set(d, std::abs(p.nz[k])), ez));
      return hn::Ge(hn::Add(planeDistance(d, p, k, x, y, z), reach), hn::Zero(d));
    };
    auto keep = visible(0);
    for (int k = 1; k < 6; ++k) keep = hn::And(keep, visible(k));
    return keep;
  });
}

// Baselines: the same tests as plain loops, compiled for this target and left to the compiler.
std::size_t CullSpheresAutovec(const Planes& p, const SpheresView& s, std::uint32_t* out) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < s.padded; ++i) {
    bool visible = true;
    for (int k = 0; k < 6; ++k)
      visible &= p.nx[k] * s[fields::Sphere::x][i] + p.ny[k] * s[fields::Sphere::y][i] +
                     p.nz[k] * s[fields::Sphere::z][i] + p.d[k] >=
                 -s[fields::Sphere::r][i];
    out[count] = static_cast<std::uint32_t>(i);
    count += visible;
  }
  return count;
}

std::size_t CullBoundsAutovec(const Planes& p, const BoundsView& b, std::uint32_t* out) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < b.padded; ++i) {
    bool visible = true;
    for (int k = 0; k < 6; ++k) {
      float dist = p.nx[k] * b[fields::Bounds::cx][i] + p.ny[k] * b[fields::Bounds::cy][i] +
                   p.nz[k] * b[fields::Bounds::cz][i] + p.d[k];
      float reach = std::abs(p.nx[k]) * b[fields::Bounds::ex][i] +
                    std::abs(p.ny[k]) * b[fields::Bounds::ey][i] +
                    std::abs(p.nz[k]) * b[fields::Bounds::ez][i];
      visible &= dist + reach >= 0.0f;
    }
    out[count] = static_cast<std::uint32_t>(i);
    count += visible;
  }
  return count;
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(CullSpheres, cullSpheres);
SIMDPHYS_EXPORT(CullBounds, cullBounds);
SIMDPHYS_EXPORT(CullSpheresAutovec, cullSpheresAutovec);
SIMDPHYS_EXPORT(CullBoundsAutovec, cullBoundsAutovec);
}  // namespace simdphys::simd
#endif

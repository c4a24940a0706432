// W6: spheres and boxes against the six planes of a frustum. Streaming and memory bound: one pass,
// visible indices compacted with CompressStore. Sums are evaluated in the order of the scalar
// reference (scene.hpp) without fusing, so every path returns the same indices.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/cull.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace simdphys::simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
    const auto x = hn::Load(d, s.x + i), y = hn::Load(d, s.y + i), z = hn::Load(d, s.z + i);
    const auto negR = hn::Neg(hn::Load(d, s.r + i));
    auto keep = hn::Ge(planeDistance(d, p, 0, x, y, z), negR);
    for (int k = 1; k < 6; ++k) keep = hn::And(keep, hn::Ge(planeDistance(d, p, k, x, y, z), negR));
    return keep;
  });
}

std::size_t CullBounds(const Planes& p, const BoundsView& b, std::uint32_t* out) {
  return selectIndices(b.padded, out, [&](auto d, std::size_t i) {
    const auto x = hn::Load(d, b.cx + i), y = hn::Load(d, b.cy + i), z = hn::Load(d, b.cz + i);
    const auto ex = hn::Load(d, b.ex + i), ey = hn::Load(d, b.ey + i), ez = hn::Load(d, b.ez + i);
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
      visible &= p.nx[k] * s.x[i] + p.ny[k] * s.y[i] + p.nz[k] * s.z[i] + p.d[k] >= -s.r[i];
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
      float dist = p.nx[k] * b.cx[i] + p.ny[k] * b.cy[i] + p.nz[k] * b.cz[i] + p.d[k];
      float reach =
          std::abs(p.nx[k]) * b.ex[i] + std::abs(p.ny[k]) * b.ey[i] + std::abs(p.nz[k]) * b.ez[i];
      visible &= dist + reach >= 0.0f;
    }
    out[count] = static_cast<std::uint32_t>(i);
    count += visible;
  }
  return count;
}

}  // namespace HWY_NAMESPACE
}  // namespace simdphys::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace simdphys::simd {
HWY_EXPORT(CullSpheres);
HWY_EXPORT(CullBounds);
HWY_EXPORT(CullSpheresAutovec);
HWY_EXPORT(CullBoundsAutovec);

std::size_t cullSpheres(const Planes& p, const SpheresView& s, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(CullSpheres)(p, s, out);
}
std::size_t cullBounds(const Planes& p, const BoundsView& b, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(CullBounds)(p, b, out);
}
std::size_t cullSpheresAutovec(const Planes& p, const SpheresView& s, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(CullSpheresAutovec)(p, s, out);
}
std::size_t cullBoundsAutovec(const Planes& p, const BoundsView& b, std::uint32_t* out) {
  return HWY_DYNAMIC_DISPATCH(CullBoundsAutovec)(p, b, out);
}
}  // namespace simdphys::simd
#endif

// A ray as the BVH walks take it, prepared once per ray and shared by the reference path (src/)
// and the SIMD kernels (simd/bvh_ray.cpp), so both test the same boxes and triangles with the
// same numbers: the slab test's origin and inverse direction, and the watertight triangle test's
// shear (Woop, Benthin, Wald 2013; raycast.hpp's WatertightRay, computed the same way).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

#include "core/view.hpp"
#include "simdphys/stream_fields.hpp"

namespace simdphys::detail {

// Node boxes are tested as t = (face - origin) * inverse per axis, the near face chosen by the
// sign bit of the direction. Each t carries at most a few roundings (the difference, the
// reciprocal, the product: below 3 ulp), so the entry is scaled down and the exit up by 2^-20
// (about 8 ulp) before they are compared (Ize, "Robust BVH Ray Traversal", JCGT 2013): a box the
// ray touches in exact arithmetic is never culled, which watertightness needs at shared edges
// that lie on node faces. A direction component of 0 gives an infinite inverse; with the origin
// exactly on that face the product is 0 * inf = NaN, which bounds nothing (as raycast.hpp's slab
// test), since the box then contains the whole line on that axis.
inline constexpr float kEnterScale = 1.0f - 0x1p-20f;
inline constexpr float kExitScale = 1.0f + 0x1p-20f;

struct TraversalRay {
  // The watertight test's frame (the fields of simd::WatertightQuery): origin, the axes kx, ky,
  // kz (kz the direction's largest component) and the shear sx, sy, sz.
  float ox, oy, oz;
  int kx, ky, kz;
  float sx, sy, sz;
  float tMax;
  // The slab test's: origin, 1 / direction, and its sign bit (the near face is the max face).
  float origin[3], inverse[3];
  bool negative[3];
  bool finiteInverse;  // no direction component is zero, so no slab product can be NaN
};

// The fields the slab test reads: origin, inverse, negative, finiteInverse, tMax.
inline void setSlabs(TraversalRay& r, float ox, float oy, float oz, float dx, float dy, float dz,
                     float tMax) {
  const float o[3] = {ox, oy, oz}, d[3] = {dx, dy, dz};
  for (int a = 0; a < 3; ++a) {
    r.origin[a] = o[a];
    r.inverse[a] = 1.0f / d[a];
    r.negative[a] = std::signbit(d[a]);
  }
  r.finiteInverse =
      std::isfinite(r.inverse[0]) && std::isfinite(r.inverse[1]) && std::isfinite(r.inverse[2]);
  r.tMax = tMax;
}

// Always inlined: the kernels call it per ray, and an out-of-line copy is compiled for the
// baseline instruction set only (and measured at a tenth of the traversal's time).
[[gnu::always_inline]] inline TraversalRay traversalRay(float ox, float oy, float oz, float dx,
                                                        float dy, float dz, float tMax) {
  TraversalRay r;
  // WatertightRay's frame: kz the first axis of largest |d|; kx, ky swapped for a negative d[kz]
  // so the triangle's winding does not flip.
  const float d[3] = {dx, dy, dz};
  int kz = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(d[a]) > std::abs(d[kz])) kz = a;
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  if (d[kz] < 0) std::swap(kx, ky);
  r.ox = ox, r.oy = oy, r.oz = oz;
  r.kx = kx, r.ky = ky, r.kz = kz;
  r.sx = d[kx] / d[kz];
  r.sy = d[ky] / d[kz];
  r.sz = 1.0f / d[kz];
  setSlabs(r, ox, oy, oz, dx, dy, dz, tMax);
  return r;
}

// Ray i of a ray view (fields::Ray), as both paths read a ray stream.
[[gnu::always_inline]] inline TraversalRay traversalRay(const core::View<fields::Ray>& rays,
                                                        std::size_t i) {
  using R = fields::Ray;
  return traversalRay(rays[R::origin][i], rays[R::origin + 1][i], rays[R::origin + 2][i],
                      rays[R::direction][i], rays[R::direction + 1][i], rays[R::direction + 2][i],
                      rays[R::tMax][i]);
}

}  // namespace simdphys::detail

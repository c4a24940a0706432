// A ray as the mesh traversal takes it, prepared once per ray and shared by the reference path
// (src/mesh/) and the SIMD kernels (simd/bvh_ray.cpp), so both test the same boxes and triangles
// with the same numbers.
#pragma once

#include <cmath>
#include <limits>

#include "simd/kernels.hpp"
#include "simdphys/geometry3d/raycast.hpp"

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
  WatertightRay watertight;     // the scalar triangle test's precomputation
  simd::WatertightQuery query;  // the same, as the kernels take it
  float origin[3], inverse[3];
  bool negative[3];    // sign bit of the direction: the near face is the max face
  bool finiteInverse;  // no direction component is zero, so no slab product can be NaN
  float tMax;
};

// The fields the node test reads: origin, inverse, negative, finiteInverse, tMax.
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
  r.watertight = WatertightRay(Vec3f(ox, oy, oz), Vec3f(dx, dy, dz));
  const WatertightRay& w = r.watertight;
  r.query = {ox, oy, oz, w.kx, w.ky, w.kz, w.sx, w.sy, w.sz, tMax};
  setSlabs(r, ox, oy, oz, dx, dy, dz, tMax);
  return r;
}

}  // namespace simdphys::detail

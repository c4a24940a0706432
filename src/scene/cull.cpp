// Culling a stream against a frustum: the scalar per-object test on the reference path (the book's,
// scene.hpp), the W6 kernels otherwise; both return the same indices.
#include "src/core/on_path.hpp"
#include "src/views.hpp"

namespace simdphys {

std::size_t cull(const Frustum& f, const SphereStream& s, std::vector<std::uint32_t>& visible) {
  validate(f, "cull(SphereStream)");
  return selectOnPath(
      view(s), visible,
      [&](std::uint32_t i) {
        const Sphere sphere = s[i];
        return f.intersectsSphere(sphere.center, sphere.radius);
      },
      [&](const auto& v, std::uint32_t* out) { return simd::cullSpheres(planes(f), v, out); });
}

std::size_t cull(const Frustum& f, const BoundsStream& b, std::vector<std::uint32_t>& visible) {
  validate(f, "cull(BoundsStream)");
  return selectOnPath(
      view(b), visible,
      [&](std::uint32_t i) {
        using F = fields::Bounds;
        return f.intersectsBox({b.field(F::cx)[i], b.field(F::cy)[i], b.field(F::cz)[i]},
                               {b.field(F::ex)[i], b.field(F::ey)[i], b.field(F::ez)[i]});
      },
      [&](const auto& v, std::uint32_t* out) { return simd::cullBounds(planes(f), v, out); });
}

}  // namespace simdphys

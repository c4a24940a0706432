#include "../reference/cull.hpp"
#include "../views.hpp"

namespace simdphys {
namespace {

template <class Kernel>
std::size_t compacted(std::size_t padded, std::vector<std::uint32_t>& visible, Kernel kernel) {
  visible.resize(padded);  // CompressStore may write whole vectors past the count
  visible.resize(kernel(visible.data()));
  return visible.size();
}

}  // namespace

std::size_t cull(const Frustum& f, const SphereStream& s, std::vector<std::uint32_t>& visible) {
  validate(f, "cull(SphereStream)");
  if (referencePathActive())
    return reference::cullSpheres(f, s.x().view(), s.y().view(), s.z().view(), s.r().view(),
                                  visible);
  return compacted(s.padded(), visible,
                   [&](std::uint32_t* out) { return simd::cullSpheres(planes(f), view(s), out); });
}

std::size_t cull(const Frustum& f, const BoundsStream& b, std::vector<std::uint32_t>& visible) {
  validate(f, "cull(BoundsStream)");
  if (referencePathActive())
    return reference::cullBoxes(f, b.cx().view(), b.cy().view(), b.cz().view(), b.ex().view(),
                                b.ey().view(), b.ez().view(), visible);
  return compacted(b.padded(), visible,
                   [&](std::uint32_t* out) { return simd::cullBounds(planes(f), view(b), out); });
}

}  // namespace simdphys

// Camera frustum and culling (book chapter 13): the six planes, the single tests, and the flat
// batch culls of sphere and box streams.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "simdphys/geometry3d.hpp"

namespace simdphys {

// Six planes, normals pointing inwards: a point p is inside when n.p + d >= 0 for all of them.
template <class T>
struct FrustumT {
  enum Side { kNear, kFar, kLeft, kRight, kBottom, kTop };
  std::array<PlaneT<T>, 6> planes;

  // The planes of a view-projection matrix (column vectors, clip depth [0, 1]; see
  // docs/conventions.md), Gribb and Hartmann's method: each plane is a sum or difference of
  // rows of the matrix, normalised. Throws Error if a plane is degenerate or not finite.
  static FrustumT fromMatrix(const Mat4<T>& viewProj);

  template <class U>
  FrustumT<U> cast() const {
    FrustumT<U> f;
    for (int i = 0; i < 6; ++i) f.planes[i] = {planes[i].normal.template cast<U>(), U(planes[i].d)};
    return f;
  }

  // Conservative tests: true when no single plane has the shape wholly outside. The sums are
  // written out in the order the SIMD kernels use, so both paths round identically.
  bool intersectsSphere(const Vec3<T>& center, T radius) const {
    for (const PlaneT<T>& p : planes) {
      T dist = p.normal.x() * center.x() + p.normal.y() * center.y() + p.normal.z() * center.z();
      if (!(dist + p.d >= -radius)) return false;
    }
    return true;
  }
  bool intersectsBox(const Vec3<T>& center, const Vec3<T>& halfExtents) const {
    for (const PlaneT<T>& p : planes) {
      const Vec3<T>& n = p.normal;
      T dist = n.x() * center.x() + n.y() * center.y() + n.z() * center.z();
      T reach = std::abs(n.x()) * halfExtents.x() + std::abs(n.y()) * halfExtents.y() +
                std::abs(n.z()) * halfExtents.z();
      if (!((dist + p.d) + reach >= 0)) return false;
    }
    return true;
  }
};
using Frustum = FrustumT<float>;
using Frustumd = FrustumT<double>;

// Throws Error naming `where` and the plane unless every plane is valid (validate(Plane): finite,
// unit normal). The culls call it once, at entry: a NaN normal or an infinite d would otherwise
// cull visible objects silently.
template <class T>
void validate(const FrustumT<T>& f, std::string_view where);

// Writes to `visible` the indices, ascending, of the spheres / boxes that intersect the frustum
// (the conservative test above) and returns their number. Runs on the active path. Throws Error
// on an invalid frustum (validate(Frustum)).
std::size_t cull(const Frustum& frustum, const SphereStream& spheres,
                 std::vector<std::uint32_t>& visible);
std::size_t cull(const Frustum& frustum, const BoundsStream& boxes,
                 std::vector<std::uint32_t>& visible);

}  // namespace simdphys

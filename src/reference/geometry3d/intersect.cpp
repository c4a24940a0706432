// geometry3d/intersect.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/intersect-inl.hpp"

namespace simdphys::detail {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT_DETAIL(T)                               \
  template bool boxesIntersect(const SatBox<T>& a, const SatBox<T>& b);                   \
  template bool trianglesIntersect(std::array<Vec3<T>, 3> v1, std::array<Vec3<T>, 3> v2); \
  template std::array<Vec3<T>, 3> relative(const TriangleT<T>& t, const Vec3<T>& origin);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT_DETAIL(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT_DETAIL(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT_DETAIL

}  // namespace simdphys::detail

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(T)                                \
  template bool intersects(const SphereT<T>& a, const SphereT<T>& b);               \
  template bool intersects(const SphereT<T>& sphere, const AabbT<T>& box);          \
  template bool intersects(const AabbT<T>& box, const SphereT<T>& sphere);          \
  template bool intersects(const SphereT<T>& sphere, const ObbT<T>& box);           \
  template bool intersects(const ObbT<T>& box, const SphereT<T>& sphere);           \
  template bool intersects(const SphereT<T>& sphere, const PlaneT<T>& plane);       \
  template bool intersects(const PlaneT<T>& plane, const SphereT<T>& sphere);       \
  template bool intersects(const AabbT<T>& a, const AabbT<T>& b);                   \
  template bool intersects(const AabbT<T>& a, const ObbT<T>& b);                    \
  template bool intersects(const ObbT<T>& b, const AabbT<T>& a);                    \
  template bool intersects(const AabbT<T>& box, const PlaneT<T>& plane);            \
  template bool intersects(const PlaneT<T>& plane, const AabbT<T>& box);            \
  template bool intersects(const ObbT<T>& a, const ObbT<T>& b);                     \
  template bool intersects(const ObbT<T>& box, const PlaneT<T>& plane);             \
  template bool intersects(const PlaneT<T>& plane, const ObbT<T>& box);             \
  template bool intersects(const PlaneT<T>& a, const PlaneT<T>& b);                 \
  template bool intersects(const TriangleT<T>& triangle, const SphereT<T>& sphere); \
  template bool intersects(const SphereT<T>& sphere, const TriangleT<T>& triangle); \
  template bool intersects(const TriangleT<T>& triangle, const AabbT<T>& box);      \
  template bool intersects(const AabbT<T>& box, const TriangleT<T>& triangle);      \
  template bool intersects(const TriangleT<T>& triangle, const ObbT<T>& box);       \
  template bool intersects(const ObbT<T>& box, const TriangleT<T>& triangle);       \
  template bool intersects(const TriangleT<T>& triangle, const PlaneT<T>& plane);   \
  template bool intersects(const PlaneT<T>& plane, const TriangleT<T>& triangle);   \
  template bool intersects(const TriangleT<T>& a, const TriangleT<T>& b);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT

}  // namespace simdphys

// geometry3d/intersect.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/intersect-inl.hpp"
#include "src/reference/instantiate.hpp"

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

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(T)                 \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, SphereT, AabbT)     \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, SphereT, ObbT)      \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, SphereT, PlaneT)    \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, TriangleT, SphereT) \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, AabbT, ObbT)        \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, AabbT, PlaneT)      \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, TriangleT, AabbT)   \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, ObbT, PlaneT)       \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, TriangleT, ObbT)    \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, TriangleT, PlaneT)  \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, SphereT)       \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, ObbT)          \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, PlaneT)        \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, TriangleT)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_INTERSECT

}  // namespace simdphys

// geometry3d/raycast.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/raycast-inl.hpp"
#include "src/reference/instantiate.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(T)                                         \
  template std::optional<RayHitT<T>> raycast(const SphereT<T>& sphere, const RayT<T>& ray, \
                                             detail::NoDeduce<T> tMax);                    \
  template std::optional<RayHitT<T>> raycast(const AabbT<T>& box, const RayT<T>& ray,      \
                                             detail::NoDeduce<T> tMax);                    \
  template std::optional<RayHitT<T>> raycast(const ObbT<T>& box, const RayT<T>& ray,       \
                                             detail::NoDeduce<T> tMax);                    \
  template std::optional<RayHitT<T>> raycast(const PlaneT<T>& plane, const RayT<T>& ray,   \
                                             detail::NoDeduce<T> tMax);                    \
  template std::optional<RayHitT<T>> raycast(                                              \
      const TriangleT<T>& tri, const WatertightRayT<T>& ray, detail::NoDeduce<T> tMax);    \
  template std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const RayT<T>& ray,  \
                                             detail::NoDeduce<T> tMax);                    \
  SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, SphereT)                                         \
  SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, AabbT)                                           \
  SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, ObbT)                                            \
  SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, PlaneT)                                          \
  SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, TriangleT)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST

}  // namespace simdphys

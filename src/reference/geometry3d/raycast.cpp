// geometry3d/raycast.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/raycast-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(T)                                             \
  template std::optional<RayHitT<T>> raycast(const SphereT<T>& sphere, const RayT<T>& ray,     \
                                             detail::NoDeduce<T> tMax);                        \
  template std::optional<RayHitT<T>> raycast(const AabbT<T>& box, const RayT<T>& ray,          \
                                             detail::NoDeduce<T> tMax);                        \
  template std::optional<RayHitT<T>> raycast(const ObbT<T>& box, const RayT<T>& ray,           \
                                             detail::NoDeduce<T> tMax);                        \
  template std::optional<RayHitT<T>> raycast(const PlaneT<T>& plane, const RayT<T>& ray,       \
                                             detail::NoDeduce<T> tMax);                        \
  template std::optional<RayHitT<T>> raycast(                                                  \
      const TriangleT<T>& tri, const WatertightRayT<T>& ray, detail::NoDeduce<T> tMax);        \
  template std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const RayT<T>& ray,      \
                                             detail::NoDeduce<T> tMax);                        \
  template std::optional<RayHitT<T>> linecast(const SphereT<T>& sphere, const SegmentT<T>& s); \
  template std::optional<RayHitT<T>> linecast(const AabbT<T>& box, const SegmentT<T>& s);      \
  template std::optional<RayHitT<T>> linecast(const ObbT<T>& box, const SegmentT<T>& s);       \
  template std::optional<RayHitT<T>> linecast(const PlaneT<T>& plane, const SegmentT<T>& s);   \
  template std::optional<RayHitT<T>> linecast(const TriangleT<T>& tri, const SegmentT<T>& s);  \
  template bool linetest(const SphereT<T>& sphere, const SegmentT<T>& s);                      \
  template bool linetest(const AabbT<T>& box, const SegmentT<T>& s);                           \
  template bool linetest(const ObbT<T>& box, const SegmentT<T>& s);                            \
  template bool linetest(const PlaneT<T>& plane, const SegmentT<T>& s);                        \
  template bool linetest(const TriangleT<T>& tri, const SegmentT<T>& s);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_RAYCAST

}  // namespace simdphys

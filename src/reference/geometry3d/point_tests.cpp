// geometry3d/point_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/point_tests-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(T)                                             \
  template bool contains(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point);        \
  template bool contains(const AabbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);             \
  template bool contains(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);              \
  template bool contains(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point);          \
  template bool contains(const SegmentT<T>& segment, const detail::NoDeduce<Vec3<T>>& point);      \
  template bool contains(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point);              \
  template bool contains(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point);    \
  template Vec3<T> closestPoint(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point); \
  template Vec3<T> closestPoint(const AabbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);      \
  template Vec3<T> closestPoint(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point);       \
  template Vec3<T> closestPoint(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point);   \
  template Vec3<T> closestPoint(const SegmentT<T>& segment,                                        \
                                const detail::NoDeduce<Vec3<T>>& point);                           \
  template Vec3<T> closestPoint(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point);       \
  template Vec3<T> closestPoint(const TriangleT<T>& triangle,                                      \
                                const detail::NoDeduce<Vec3<T>>& point);                           \
  template Vec3<T> barycentric(const TriangleT<T>& triangle,                                       \
                               const detail::NoDeduce<Vec3<T>>& point);                            \
  template SegmentClosestPointsT<T> closestPoints(const SegmentT<T>& first,                        \
                                                  const SegmentT<T>& second);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS

}  // namespace simdphys

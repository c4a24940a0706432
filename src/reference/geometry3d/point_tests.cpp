// geometry3d/point_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/point_tests-inl.hpp"
#include "src/reference/instantiate.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(T)                      \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, SphereT, Vec3)                      \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, AabbT, Vec3)                        \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, ObbT, Vec3)                         \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, PlaneT, Vec3)                       \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, SegmentT, Vec3)                     \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, RayT, Vec3)                         \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, TriangleT, Vec3)                    \
  template Vec3<T> barycentric(const TriangleT<T>& triangle,                \
                               const detail::NoDeduce<Vec3<T>>& point);     \
  template SegmentClosestPointsT<T> closestPoints(const SegmentT<T>& first, \
                                                  const SegmentT<T>& second);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_POINT_TESTS

}  // namespace simdphys

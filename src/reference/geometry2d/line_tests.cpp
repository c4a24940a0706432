// geometry2d/line_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/line_tests-inl.hpp"
#include "src/reference/instantiate.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(T)                                        \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, Segment2T, CircleT)                         \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, Segment2T, RectT)                           \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, Segment2T, OrientedRectT)                   \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const CircleT<T>& shape); \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const RectT<T>& shape);   \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const OrientedRectT<T>& shape);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS

}  // namespace simdphys

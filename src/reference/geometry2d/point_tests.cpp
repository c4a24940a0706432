// geometry2d/point_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/point_tests-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(T)                                             \
  template bool contains(const Segment2T<T>& segment, const detail::NoDeduce<Vec2<T>>& point);     \
  template bool contains(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point);        \
  template bool contains(const RectT<T>& rect, const detail::NoDeduce<Vec2<T>>& point);            \
  template bool contains(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point);     \
  template Vec2<T> closestPoint(const Segment2T<T>& segment,                                       \
                                const detail::NoDeduce<Vec2<T>>& point);                           \
  template Vec2<T> closestPoint(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point); \
  template Vec2<T> closestPoint(const RectT<T>& rect, const detail::NoDeduce<Vec2<T>>& point);     \
  template Vec2<T> closestPoint(const OrientedRectT<T>& box,                                       \
                                const detail::NoDeduce<Vec2<T>>& point);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS

}  // namespace simdphys

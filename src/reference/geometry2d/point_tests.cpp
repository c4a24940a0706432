// geometry2d/point_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/point_tests-inl.hpp"
#include "src/reference/instantiate.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(T)   \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, Segment2T, Vec2) \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, CircleT, Vec2)   \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, RectT, Vec2)     \
  SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, OrientedRectT, Vec2)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_POINT_TESTS

}  // namespace simdphys

// geometry2d/line_tests.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/line_tests-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(T)                                    \
  template bool intersects(const Segment2T<T>& s, const CircleT<T>& c);                  \
  template bool intersects(const CircleT<T>& c, const Segment2T<T>& s);                  \
  template bool intersects(const Segment2T<T>& s, const RectT<T>& r);                    \
  template bool intersects(const RectT<T>& r, const Segment2T<T>& s);                    \
  template bool intersects(const Segment2T<T>& s, const OrientedRectT<T>& b);            \
  template bool intersects(const OrientedRectT<T>& b, const Segment2T<T>& s);            \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const CircleT<T>& c); \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const RectT<T>& r);   \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const OrientedRectT<T>& b);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_LINE_TESTS

}  // namespace simdphys

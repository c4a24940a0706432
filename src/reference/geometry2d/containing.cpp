// geometry2d/containing.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/containing-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_CONTAINING(T)                                              \
  template RectT<T> containingRect(std::span<const Vec2<T>> points);                               \
  template RectT<T> containingRect(const std::vector<Vec2<T>>& points);                            \
  template CircleT<T> containingCircle(std::span<const Vec2<T>> points);                           \
  template CircleT<T> containingCircle(const std::vector<Vec2<T>>& points);                        \
  template void validate(const BoundingShape2T<T>& shape, std::string_view where);                 \
  template RectT<T> boundingRect(const BoundingShape2T<T>& shape);                                 \
  template bool contains(const BoundingShape2T<T>& shape, const detail::NoDeduce<Vec2<T>>& point); \
  template std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const BoundingShape2T<T>& shape);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_CONTAINING(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_CONTAINING(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_CONTAINING

}  // namespace simdphys

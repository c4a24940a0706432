// geometry2d/collisions.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "src/reference/instantiate.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(T)                          \
  template Manifold2T<T> flipped(Manifold2T<T> m);                             \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, CircleT, RectT)               \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, CircleT, OrientedRectT)       \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, CircleT)                 \
  SIMDPHYS_INSTANTIATE_PAIR(T, bool, intersects, RectT, OrientedRectT)         \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, bool, intersects, OrientedRectT)           \
  SIMDPHYS_INSTANTIATE_PAIR(T, Manifold2T<T>, collide, CircleT, RectT)         \
  SIMDPHYS_INSTANTIATE_PAIR(T, Manifold2T<T>, collide, CircleT, OrientedRectT) \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, Manifold2T<T>, collide, CircleT)           \
  SIMDPHYS_INSTANTIATE_PAIR(T, Manifold2T<T>, collide, RectT, OrientedRectT)   \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, Manifold2T<T>, collide, RectT)             \
  SIMDPHYS_INSTANTIATE_SAME_KIND(T, Manifold2T<T>, collide, OrientedRectT)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS

}  // namespace simdphys

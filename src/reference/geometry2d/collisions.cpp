// geometry2d/collisions.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry2d/collisions-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(T)                             \
  template Manifold2T<T> flipped(Manifold2T<T> m);                                \
  template bool intersects(const CircleT<T>& a, const CircleT<T>& b);             \
  template bool intersects(const CircleT<T>& c, const RectT<T>& r);               \
  template bool intersects(const RectT<T>& r, const CircleT<T>& c);               \
  template bool intersects(const CircleT<T>& c, const OrientedRectT<T>& b);       \
  template bool intersects(const OrientedRectT<T>& b, const CircleT<T>& c);       \
  template bool intersects(const RectT<T>& a, const RectT<T>& b);                 \
  template bool overlaps(const RectT<T>& a, const RectT<T>& b);                   \
  template bool intersects(const RectT<T>& r, const OrientedRectT<T>& b);         \
  template bool intersects(const OrientedRectT<T>& b, const RectT<T>& r);         \
  template bool intersects(const OrientedRectT<T>& a, const OrientedRectT<T>& b); \
  template Manifold2T<T> collide(const CircleT<T>& a, const CircleT<T>& b);       \
  template Manifold2T<T> collide(const CircleT<T>& c, const RectT<T>& r);         \
  template Manifold2T<T> collide(const RectT<T>& r, const CircleT<T>& c);         \
  template Manifold2T<T> collide(const CircleT<T>& c, const OrientedRectT<T>& b); \
  template Manifold2T<T> collide(const OrientedRectT<T>& b, const CircleT<T>& c); \
  template Manifold2T<T> collide(const RectT<T>& a, const RectT<T>& b);           \
  template Manifold2T<T> collide(const RectT<T>& r, const OrientedRectT<T>& b);   \
  template Manifold2T<T> collide(const OrientedRectT<T>& b, const RectT<T>& r);   \
  template Manifold2T<T> collide(const OrientedRectT<T>& a, const OrientedRectT<T>& b);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_COLLISIONS

}  // namespace simdphys

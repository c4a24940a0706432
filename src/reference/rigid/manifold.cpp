// The manifolds of rigid/manifold.hpp, compiled for float and double.
#include "src/reference/rigid/box_box-inl.hpp"
#include "src/reference/rigid/hull-inl.hpp"
#include "src/reference/rigid/manifold-inl.hpp"
#include "src/reference/rigid/triangle-inl.hpp"

namespace simdphys {

#define SIMDPHYS_MANIFOLDS(T)                                                      \
  template ManifoldT<T> collide(const SphereT<T>&, const SphereT<T>&, T);          \
  template ManifoldT<T> collide(const SphereT<T>&, const ObbT<T>&, T);             \
  template ManifoldT<T> collide(const ObbT<T>&, const ObbT<T>&, T);                \
  template ManifoldT<T> collide(const SphereT<T>&, const PlaneT<T>&, T);           \
  template ManifoldT<T> collide(const ObbT<T>&, const PlaneT<T>&, T);              \
  template ManifoldT<T> collide(const SphereT<T>&, const TriangleT<T>&, T);        \
  template ManifoldT<T> collide(const ObbT<T>&, const TriangleT<T>&, T, unsigned); \
  template ManifoldT<T> collide(const PlacedHullT<T>&, const SphereT<T>&, T);      \
  template ManifoldT<T> collide(const PlacedHullT<T>&, const ObbT<T>&, T);         \
  template ManifoldT<T> collide(const PlacedHullT<T>&, const PlacedHullT<T>&, T);  \
  template ManifoldT<T> collide(const PlacedHullT<T>&, const PlaneT<T>&, T);       \
  template ManifoldT<T> collide(const PlacedHullT<T>&, const TriangleT<T>&, T, unsigned);
SIMDPHYS_MANIFOLDS(float)
SIMDPHYS_MANIFOLDS(double)
#undef SIMDPHYS_MANIFOLDS

}  // namespace simdphys

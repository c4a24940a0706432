// geometry3d/support.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/support-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT(T)                                             \
  template Vec3<T> support(const SphereT<T>& s, const detail::NoDeduce<Vec3<T>>& direction);   \
  template Vec3<T> support(const AabbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction);     \
  template Vec3<T> support(const ObbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction);      \
  template Vec3<T> support(const TriangleT<T>& t, const detail::NoDeduce<Vec3<T>>& direction); \
  template Vec3<T> support(const SegmentT<T>& s, const detail::NoDeduce<Vec3<T>>& direction);  \
  template Vec3<T> support(const ConvexHullT<T>& h, const detail::NoDeduce<Vec3<T>>& direction);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT

}  // namespace simdphys

namespace simdphys::detail {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT_DETAIL(T)                                         \
  template Vec3<T> coreSupport(const SphereT<T>& s, const Vec3<T>&, const Vec3<T>& origin);       \
  template T coreRadius(const SphereT<T>& s);                                                     \
  template Vec3<T> referencePoint(const SphereT<T>& s);                                           \
  template Vec3<T> coreSupport(const AabbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin);       \
  template Vec3<T> referencePoint(const AabbT<T>& b);                                             \
  template Vec3<T> coreSupport(const ObbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin);        \
  template Vec3<T> referencePoint(const ObbT<T>& b);                                              \
  template Vec3<T> coreSupport(const TriangleT<T>& t, const Vec3<T>& d, const Vec3<T>& origin);   \
  template Vec3<T> referencePoint(const TriangleT<T>& t);                                         \
  template Vec3<T> coreSupport(const SegmentT<T>& s, const Vec3<T>& d, const Vec3<T>& origin);    \
  template Vec3<T> referencePoint(const SegmentT<T>& s);                                          \
  template Vec3<T> coreSupport(const ConvexHullT<T>& h, const Vec3<T>& d, const Vec3<T>& origin); \
  template Vec3<T> referencePoint(const ConvexHullT<T>& h);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT_DETAIL(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT_DETAIL(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_SUPPORT_DETAIL

}  // namespace simdphys::detail

// geometry3d/gjk.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/gjk-inl.hpp"

namespace simdphys::detail {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_GJK_DETAIL(T)                                          \
  template GjkRun<T> runGjk(const CorePair<T>& cores, const Vec3<T>& origin, Vec3<T> towardB); \
  template GjkResultT<T> gjkDistance(const Cores<T>& shapes);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_GJK_DETAIL(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_GJK_DETAIL(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_GJK_DETAIL

}  // namespace simdphys::detail

// geometry3d/epa.hpp, compiled once: its function templates for float and double.
#include "src/reference/geometry3d/epa-inl.hpp"

namespace simdphys::detail {

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_EPA_DETAIL(T)                                \
  template EpaCoreResult<T> epaCore(const CorePair<T>& cores, const Vec3<T>& origin, \
                                    const GjkRun<T>& run, const Vec3<T>& towardB);   \
  template std::optional<PenetrationT<T>> epa(const Cores<T>& shapes);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_EPA_DETAIL(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_EPA_DETAIL(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_EPA_DETAIL

}  // namespace simdphys::detail

// scene/frustum.hpp, compiled once: the frustum's construction and validation for float and
// double.
#include "simdphys/scene/frustum.hpp"

#include <cmath>
#include <string>

namespace simdphys {

template <class T>
FrustumT<T> FrustumT<T>::fromMatrix(const Mat4<T>& m) {
  const Vec4<T> r0 = m.row(0), r1 = m.row(1), r2 = m.row(2), r3 = m.row(3);
  // Clip space: -w <= x, y <= w and 0 <= z <= w.
  const std::array<Vec4<T>, 6> rows = {r2, r3 - r2, r3 + r0, r3 - r0, r3 + r1, r3 - r1};
  FrustumT f;
  for (int i = 0; i < 6; ++i) {
    // Divided by its largest |component| first, so the normal's length neither overflows nor
    // underflows whatever the matrix's scale (a matrix times 1e20 or 1e-25 gives the same planes).
    const T largest = rows[i].cwiseAbs().maxCoeff();
    const Vec4<T> r = rows[i] / largest;
    const T len = r.template head<3>().norm();
    const PlaneT<T> plane{r.template head<3>() / len, r.w() / len};
    if (!(largest > 0) || !std::isfinite(largest) || !(len > 0) || !plane.normal.allFinite() ||
        !std::isfinite(plane.d))
      throw Error("Frustum::fromMatrix: plane " + std::to_string(i) +
                  " is degenerate or not finite (is the matrix a view-projection?)");
    f.planes[i] = plane;
  }
  return f;
}

template <class T>
void validate(const FrustumT<T>& f, std::string_view where) {
  for (int i = 0; i < 6; ++i)
    validate(f.planes[i], std::string(where) + ": frustum plane " + std::to_string(i));
}

#define SIMDPHYS_INSTANTIATE_SCENE_FRUSTUM(T)                     \
  template FrustumT<T> FrustumT<T>::fromMatrix(const Mat4<T>& m); \
  template void validate(const FrustumT<T>& f, std::string_view where);
SIMDPHYS_INSTANTIATE_SCENE_FRUSTUM(float)
SIMDPHYS_INSTANTIATE_SCENE_FRUSTUM(double)
#undef SIMDPHYS_INSTANTIATE_SCENE_FRUSTUM

}  // namespace simdphys

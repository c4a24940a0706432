// math.hpp, compiled once: its larger function templates for float and double.
#include "src/reference/math-inl.hpp"

namespace simdphys {

#define SIMDPHYS_INSTANTIATE_MATH(T)                                                           \
  template Mat3<T> rotationX(T angle);                                                         \
  template Mat3<T> rotationY(T angle);                                                         \
  template Mat3<T> rotationZ(T angle);                                                         \
  template Mat3<T> eulerToMatrix(T pitch, detail::NoDeduce<T> yaw, detail::NoDeduce<T> roll);  \
  template Mat4<T> perspective(T fovY, detail::NoDeduce<T> aspect, detail::NoDeduce<T> zNear,  \
                               detail::NoDeduce<T> zFar);                                      \
  template Mat4<T> orthographic(T left, detail::NoDeduce<T> right, detail::NoDeduce<T> bottom, \
                                detail::NoDeduce<T> top, detail::NoDeduce<T> zNear,            \
                                detail::NoDeduce<T> zFar);                                     \
  template bool nearlyEqual(T a, detail::NoDeduce<T> b, detail::NoDeduce<T> relTol,            \
                            detail::NoDeduce<T> absTol);                                       \
  template Vec3<T> detail::matrixToEuler(const Mat3<T>& r);                                    \
  template Mat4<T> detail::transform(const Vec3<T>& s, const Mat3<T>& r, const Vec3<T>& t);    \
  template Mat4<T> detail::transform(const Vec3<T>& scale, const Quat<T>& q,                   \
                                     const Vec3<T>& translation);                              \
  template Vec3<T> detail::transformPoint(const Mat4<T>& m, const Vec3<T>& p);                 \
  template Vec3<T> detail::transformDirection(const Mat4<T>& m, const Vec3<T>& d);             \
  template Mat4<T> detail::lookAt(const Vec3<T>& e, const Vec3<T>& t, const Vec3<T>& u);       \
  template Vec3<T> detail::unproject(const Vec3<T>& w, const Vec4<T>& vp, const Mat4<T>& inv); \
  template ScreenRay<T> detail::screenToRay(T px, T py, const Vec4<T>& viewport,               \
                                            const Mat4<T>& view, const Mat4<T>& projection);
SIMDPHYS_INSTANTIATE_MATH(float)
SIMDPHYS_INSTANTIATE_MATH(double)
#undef SIMDPHYS_INSTANTIATE_MATH

}  // namespace simdphys

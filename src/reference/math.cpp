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
  template Mat3<T> detail::axisAngle(const Vec3<T>& axis, T angle);                            \
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

// The square matrices (2x2 to 4x4) and vectors (2D, 3D) of each scalar.
#define SIMDPHYS_INSTANTIATE_MATH_MATRIX(T, N)                                      \
  template T detail::matrixMinor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row, \
                                 Eigen::Index col);                                 \
  template T detail::cofactor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row,    \
                              Eigen::Index col);                                    \
  template Eigen::Matrix<T, N, N> detail::cofactorMatrix(const Eigen::Matrix<T, N, N>& m);
#define SIMDPHYS_INSTANTIATE_MATH_VECTOR(T, N)                                              \
  template Eigen::Matrix<T, N, 1> detail::project(                                          \
      const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& onto, const char* fn); \
  template Eigen::Matrix<T, N, 1> detail::reflect(const Eigen::Matrix<T, N, 1>& v,          \
                                                  const Eigen::Matrix<T, N, 1>& normal);    \
  template T detail::angleBetween(const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& b);
#define SIMDPHYS_INSTANTIATE_MATH_SIZES(T) \
  SIMDPHYS_INSTANTIATE_MATH_MATRIX(T, 2)   \
  SIMDPHYS_INSTANTIATE_MATH_MATRIX(T, 3)   \
  SIMDPHYS_INSTANTIATE_MATH_MATRIX(T, 4)   \
  SIMDPHYS_INSTANTIATE_MATH_VECTOR(T, 2)   \
  SIMDPHYS_INSTANTIATE_MATH_VECTOR(T, 3)
SIMDPHYS_INSTANTIATE_MATH_SIZES(float)
SIMDPHYS_INSTANTIATE_MATH_SIZES(double)
#undef SIMDPHYS_INSTANTIATE_MATH_SIZES
#undef SIMDPHYS_INSTANTIATE_MATH_VECTOR
#undef SIMDPHYS_INSTANTIATE_MATH_MATRIX

}  // namespace simdphys

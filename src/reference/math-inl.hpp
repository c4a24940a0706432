// The definitions of simdphys/math.hpp's functions (minors and cofactors, rotations, Euler
// angles, transforms, view and projection, picking, vector helpers) and the checks they share:
// included by math.cpp, which instantiates them for float and double, and by any file of src/ that
// wants them inlined.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

#include "simdphys/math.hpp"

namespace simdphys {

namespace detail {

// v / |v| for any finite non-zero v, whatever its magnitude: v is divided by its largest
// |component| first, so |v|^2 neither overflows nor underflows. `fallback` when v is zero or not
// finite. The library's one way to normalise a direction it is given.
template <class D>
Eigen::Matrix<typename D::Scalar, D::RowsAtCompileTime, 1> unitOr(
    const Eigen::MatrixBase<D>& v,
    const Eigen::Matrix<typename D::Scalar, D::RowsAtCompileTime, 1>& fallback) {
  using T = typename D::Scalar;
  const T m = v.cwiseAbs().maxCoeff();
  if (!(m > 0) || !std::isfinite(m)) return fallback;
  const Eigen::Matrix<T, D::RowsAtCompileTime, 1> s = v / m;
  return s / s.norm();
}

// direction / |direction| (unitOr: tiny and huge directions neither underflow nor overflow);
// zero (or NaN) gives zero.
template <class T>
Vec3<T> unitOrZero(const Vec3<T>& d) {
  return unitOr(d, Vec3<T>::Zero().eval());
}

// The power of two 2^-e that brings m into [0.5, 1) (or as near as float's exponents allow for a
// subnormal m); 1 for m = 0 or not finite. Multiplying by it is exact (barring subnormal
// results), so a computation on rescaled values gives the bits of the unscaled one wherever that
// one does not overflow or underflow: the way to compute products of lengths (|n|^2 ~ L^4,
// volumes ~ L^3) at any scale in the supported range.
template <std::floating_point T>
T inversePowerOfTwo(T m) {
  if (!(m > 0) || !std::isfinite(m)) return T(1);
  int e = 0;
  (void)std::frexp(m, &e);
  // Clamped so that 2^-e and 2^e are normal numbers.
  return std::ldexp(T(1), -std::clamp(e, std::numeric_limits<T>::min_exponent,
                                      std::numeric_limits<T>::max_exponent - 2));
}

template <class T>
std::string str(T x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

[[noreturn]] inline void fail(const char* fn, const std::string& what) {
  throw Error(std::string(fn) + ": " + what);
}

template <std::floating_point T>
void requireFinite(T x, const char* fn, const char* name) {
  if (!std::isfinite(x)) fail(fn, std::string(name) + " is not finite (" + str(x) + ")");
}

template <class D>
void requireFinite(const Eigen::MatrixBase<D>& v, const char* fn, const char* name) {
  if (!v.allFinite()) fail(fn, std::string(name) + " has a non-finite component");
}

// Divides by the largest |component|: the result has the same direction and norm in [1, sqrt(n)],
// so its dot products and norms neither underflow nor overflow, whatever the magnitude of v.
template <class D>
ColumnOf<D> rescaled(const Eigen::MatrixBase<D>& v, const char* fn, const char* name) {
  static_assert(D::ColsAtCompileTime == 1, "a column vector is expected");
  static_assert(std::is_floating_point_v<typename D::Scalar>, "float or double expected");
  requireFinite(v, fn, name);
  const typename D::Scalar m = v.cwiseAbs().maxCoeff();
  if (m == 0) fail(fn, std::string(name) + " is the zero vector");
  return v / m;
}

template <class D>
ColumnOf<D> normalized(const Eigen::MatrixBase<D>& v, const char* fn, const char* name) {
  const ColumnOf<D> s = rescaled(v, fn, name);
  return s / s.norm();
}

// A view or projection matrix must come out finite, and the entries that make it invertible
// non-zero: parameters in range can still overflow or underflow one (aspect 1e-40 gives
// f / aspect = inf, an extent of 1e-40 an inverse that overflows).
template <class T>
bool usableMatrix(const Mat4<T>& m, std::initializer_list<std::pair<int, int>> nonZero) {
  bool ok = m.allFinite();
  for (const auto& [row, col] : nonZero) ok = ok && m(row, col) != 0;
  return ok;
}
inline constexpr char kUnusable[] =
    ": the matrix would have a non-finite or vanishing entry (a parameter too large or too small "
    "for the scalar type)";

template <class T>
void requireViewport(const Vec4<T>& viewport, const char* fn) {
  requireFinite(viewport, fn, "viewport");
  if (!(viewport[2] > 0 && viewport[3] > 0))
    fail(fn, "viewport width and height must be positive, got " + str(viewport[2]) + " x " +
                 str(viewport[3]));
}

template <int N>
void requireIndex(Eigen::Index row, Eigen::Index col, const char* fn) {
  if (row < 0 || row >= N || col < 0 || col >= N)
    fail(fn, "(row " + str(row) + ", col " + str(col) + ") is outside a " + str(N) + "x" + str(N) +
                 " matrix");
}

// Determinant of m without row r and column c; r and c are already checked. The submatrix is at
// most 3x3, whose determinant Eigen writes out in closed form (no pivoting, no division), so
// the result is a plain polynomial in the entries and exact for small integers.
template <class T, int N>
T minorUnchecked(const Eigen::Matrix<T, N, N>& m, Eigen::Index r, Eigen::Index c) {
  if constexpr (N == 2) {
    return m(1 - r, 1 - c);
  } else {
    Eigen::Matrix<T, N - 1, N - 1> sub;
    for (Eigen::Index i = 0, si = 0; i < N; ++i) {
      if (i == r) continue;
      for (Eigen::Index j = 0, sj = 0; j < N; ++j) {
        if (j == c) continue;
        sub(si, sj++) = m(i, j);
      }
      ++si;
    }
    return sub.determinant();
  }
}

template <class T, int N>
T cofactorUnchecked(const Eigen::Matrix<T, N, N>& m, Eigen::Index r, Eigen::Index c) {
  const T mi = minorUnchecked(m, r, c);
  return (r + c) % 2 == 0 ? mi : -mi;
}

template <std::floating_point T>
Vec3<T> matrixToEuler(const Mat3<T>& r) {
  // Row 1 of Ry*Rx*Rz is (cos(p) sin(r), cos(p) cos(r), -sin(p)).
  const T cosPitch = std::sqrt(r(1, 0) * r(1, 0) + r(1, 1) * r(1, 1));
  const T pitch = std::atan2(-r(1, 2), cosPitch);
  const T roll =
      cosPitch > 16 * std::numeric_limits<T>::epsilon() ? std::atan2(r(1, 0), r(1, 1)) : T(0);
  // Column 0 of R * Rz(roll)^T = Ry(yaw) * Rx(pitch) is (cos(yaw), 0, -sin(yaw)).
  const T cr = std::cos(roll), sr = std::sin(roll);
  const T yaw = std::atan2(sr * r(2, 1) - cr * r(2, 0), cr * r(0, 0) - sr * r(0, 1));
  return Vec3<T>(pitch, yaw, roll);
}

template <std::floating_point T>
Mat4<T> transform(const Vec3<T>& s, const Mat3<T>& r, const Vec3<T>& t) {
  Mat4<T> m = Mat4<T>::Identity();
  m.template topLeftCorner<3, 3>() = r * s.asDiagonal();
  m.template topRightCorner<3, 1>() = t;
  return m;
}

template <std::floating_point T>
Mat4<T> transform(const Vec3<T>& scale, const Quat<T>& q, const Vec3<T>& translation) {
  const Vec4<T> unit = detail::normalized(q.coeffs(), "transform", "rotation quaternion");
  return transform(scale, Quat<T>(unit).toRotationMatrix(), translation);
}

template <std::floating_point T>
Vec3<T> transformPoint(const Mat4<T>& m, const Vec3<T>& p) {
  const Vec4<T> h = m * p.homogeneous();
  const bool affine = m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1;
  if (affine) return h.template head<3>();
  return h.template head<3>() / h.w();
}

template <std::floating_point T>
Vec3<T> transformDirection(const Mat4<T>& m, const Vec3<T>& d) {
  return m.template topLeftCorner<3, 3>() * d;
}

template <std::floating_point T>
Mat4<T> lookAt(const Vec3<T>& e, const Vec3<T>& t, const Vec3<T>& u) {
  detail::requireFinite(e, "lookAt", "eye");
  detail::requireFinite(t, "lookAt", "target");
  detail::requireFinite(u, "lookAt", "up");
  if (e == t) detail::fail("lookAt", "eye and target coincide");
  const Vec3<T> forward = detail::normalized(t - e, "lookAt", "target - eye");
  const Vec3<T> side = forward.cross(detail::normalized(u, "lookAt", "up"));
  // |side| = sin(angle between up and forward); the cross product's own rounding is ~3 epsilon,
  // so below a few times that the side direction would be noise.
  const T sinAngle = side.norm();
  if (sinAngle <= 16 * std::numeric_limits<T>::epsilon())
    detail::fail("lookAt", "up is parallel to the view direction");
  const Vec3<T> right = side / sinAngle;
  const Vec3<T> trueUp = right.cross(forward);
  Mat4<T> m;
  m << right.transpose(), -right.dot(e),   //
      trueUp.transpose(), -trueUp.dot(e),  //
      -forward.transpose(), forward.dot(e), 0, 0, 0, 1;
  // The rotation is unit; only the translation (dot products with eye) can overflow.
  if (!detail::usableMatrix(m, {}))
    detail::fail("lookAt", std::string("eye is too far from the origin") + detail::kUnusable);
  return m;
}

template <std::floating_point T>
Vec3<T> unproject(const Vec3<T>& w, const Vec4<T>& vp, const Mat4<T>& inv) {
  detail::requireViewport(vp, "unproject");
  const Vec4<T> ndc(2 * (w.x() - vp[0]) / vp[2] - 1,  // x right
                    1 - 2 * (w.y() - vp[1]) / vp[3],  // pixel y grows down, NDC y up
                    w.z(), 1);
  const Vec4<T> h = inv * ndc;
  return h.template head<3>() / h.w();
}

template <std::floating_point T>
ScreenRay<T> screenToRay(T px, T py, const Vec4<T>& viewport, const Mat4<T>& view,
                         const Mat4<T>& projection) {
  const Mat4<T> inv = (Mat4<T>(projection) * Mat4<T>(view)).inverse();
  const Vec3<T> nearPoint = unproject(Vec3<T>(px, py, 0), viewport, inv);
  const Vec3<T> farPoint = unproject(Vec3<T>(px, py, 1), viewport, inv);
  if (!nearPoint.allFinite() || !farPoint.allFinite())
    detail::fail("screenToRay",
                 "the pixel does not unproject to a finite point (non-finite pixel, "
                 "or singular view or projection)");
  return {nearPoint, detail::normalized(farPoint - nearPoint, "screenToRay", "far - near")};
}

template <class T, int N>
T matrixMinor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row, Eigen::Index col) {
  requireIndex<N>(row, col, "matrixMinor");
  return minorUnchecked(m, row, col);
}

template <class T, int N>
T cofactor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row, Eigen::Index col) {
  requireIndex<N>(row, col, "cofactor");
  return cofactorUnchecked(m, row, col);
}

template <class T, int N>
Eigen::Matrix<T, N, N> cofactorMatrix(const Eigen::Matrix<T, N, N>& m) {
  Eigen::Matrix<T, N, N> c;
  for (Eigen::Index i = 0; i < N; ++i)
    for (Eigen::Index j = 0; j < N; ++j) c(i, j) = cofactorUnchecked(m, i, j);
  return c;
}

template <std::floating_point T>
Mat3<T> axisAngle(const Vec3<T>& axis, T angle) {
  const Vec3<T> k = normalized(axis, "axisAngle", "axis");
  requireFinite(angle, "axisAngle", "angle");
  const T c = std::cos(angle), s = std::sin(angle);
  Mat3<T> cross;  // cross * v == k x v
  cross << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  // Rodrigues: keeps the part along k, turns the perpendicular part by angle.
  return c * Mat3<T>::Identity() + s * cross + (1 - c) * k * k.transpose();
}

template <class T, int N>
Eigen::Matrix<T, N, 1> project(const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& onto,
                               const char* fn) {
  const Eigen::Matrix<T, N, 1> d = rescaled(onto, fn, "onto");
  return d * (a.dot(d) / d.squaredNorm());
}

template <class T, int N>
Eigen::Matrix<T, N, 1> reflect(const Eigen::Matrix<T, N, 1>& v,
                               const Eigen::Matrix<T, N, 1>& normal) {
  const Eigen::Matrix<T, N, 1> n = rescaled(normal, "reflect", "normal");
  return v - (2 * v.dot(n) / n.squaredNorm()) * n;
}

template <class T, int N>
T angleBetween(const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& b) {
  const Eigen::Matrix<T, N, 1> ua = rescaled(a, "angleBetween", "a");
  const Eigen::Matrix<T, N, 1> ub = rescaled(b, "angleBetween", "b");
  if constexpr (N == 3) {
    return std::atan2(ua.cross(ub).norm(), ua.dot(ub));
  } else {
    return std::atan2(std::abs(ua.x() * ub.y() - ua.y() * ub.x()), ua.dot(ub));
  }
}

}  // namespace detail

template <std::floating_point T>
Mat3<T> rotationX(T angle) {
  const T c = std::cos(angle), s = std::sin(angle);
  Mat3<T> r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

template <std::floating_point T>
Mat3<T> rotationY(T angle) {
  const T c = std::cos(angle), s = std::sin(angle);
  Mat3<T> r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

template <std::floating_point T>
Mat3<T> rotationZ(T angle) {
  const T c = std::cos(angle), s = std::sin(angle);
  Mat3<T> r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

template <std::floating_point T>
Mat3<T> eulerToMatrix(T pitch, detail::NoDeduce<T> yaw, detail::NoDeduce<T> roll) {
  return rotationY(yaw) * rotationX(pitch) * rotationZ(roll);
}

template <std::floating_point T>
Mat4<T> perspective(T fovY, detail::NoDeduce<T> aspect, detail::NoDeduce<T> zNear,
                    detail::NoDeduce<T> zFar) {
  if (!(fovY > 0 && fovY < std::numbers::pi_v<T>))
    detail::fail("perspective", "fovY must be in (0, pi) radians, got " + detail::str(fovY));
  if (!(aspect > 0 && std::isfinite(aspect)))
    detail::fail("perspective", "aspect must be positive and finite, got " + detail::str(aspect));
  if (!(zNear > 0 && std::isfinite(zNear)))
    detail::fail("perspective", "zNear must be positive and finite, got " + detail::str(zNear));
  if (!(zFar > zNear && std::isfinite(zFar)))
    detail::fail("perspective", "zFar must be finite and greater than zNear, got zNear " +
                                    detail::str(zNear) + ", zFar " + detail::str(zFar));
  const T f = 1 / std::tan(fovY / 2);
  Mat4<T> m = Mat4<T>::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = zFar / (zNear - zFar);
  m(2, 3) = zNear * m(2, 2);  // = -zNear zFar / (zFar - zNear); makes depth(zNear) exactly 0
  m(3, 2) = -1;               // w = distance in front of the camera
  if (!detail::usableMatrix(m, {{0, 0}, {1, 1}, {2, 2}, {2, 3}}))
    detail::fail("perspective", "fovY " + detail::str(fovY) + ", aspect " + detail::str(aspect) +
                                    ", zNear " + detail::str(zNear) + ", zFar " +
                                    detail::str(zFar) + detail::kUnusable);
  return m;
}

template <std::floating_point T>
Mat4<T> orthographic(T left, detail::NoDeduce<T> right, detail::NoDeduce<T> bottom,
                     detail::NoDeduce<T> top, detail::NoDeduce<T> zNear, detail::NoDeduce<T> zFar) {
  detail::requireFinite(left, "orthographic", "left");
  detail::requireFinite(right, "orthographic", "right");
  detail::requireFinite(bottom, "orthographic", "bottom");
  detail::requireFinite(top, "orthographic", "top");
  detail::requireFinite(zNear, "orthographic", "zNear");
  detail::requireFinite(zFar, "orthographic", "zFar");
  if (!(right > left)) detail::fail("orthographic", "empty x range: right <= left");
  if (!(top > bottom)) detail::fail("orthographic", "empty y range: top <= bottom");
  if (!(zFar > zNear)) detail::fail("orthographic", "empty depth range: zFar <= zNear");
  Mat4<T> m = Mat4<T>::Identity();
  m(0, 0) = 2 / (right - left);
  m(1, 1) = 2 / (top - bottom);
  m(2, 2) = -1 / (zFar - zNear);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -zNear / (zFar - zNear);
  if (!detail::usableMatrix(m, {{0, 0}, {1, 1}, {2, 2}}))
    detail::fail("orthographic", "left " + detail::str(left) + ", right " + detail::str(right) +
                                     ", bottom " + detail::str(bottom) + ", top " +
                                     detail::str(top) + ", zNear " + detail::str(zNear) +
                                     ", zFar " + detail::str(zFar) + detail::kUnusable);
  return m;
}

template <std::floating_point T>
bool nearlyEqual(T a, detail::NoDeduce<T> b, detail::NoDeduce<T> relTol,
                 detail::NoDeduce<T> absTol) {
  if (a == b) return true;
  if (!std::isfinite(a) || !std::isfinite(b)) return false;  // else inf <= eps * inf passes
  return std::abs(a - b) <= std::max(absTol, relTol * std::max(std::abs(a), std::abs(b)));
}

}  // namespace simdphys

// simdphys math: the Eigen types the library speaks and the helpers Eigen lacks (minors,
// cofactors and the adjugate, rotations from angles, Euler angles, transforms, view and
// projection matrices, picking, robust vector helpers).
// The conventions are fixed once in docs/conventions.md: right-handed, +y up, column vectors,
// view looks down -z, clip depth in [0, 1], pixel (0,0) top-left with y down, radians.
//
// Everything is a template on the scalar type (float or double); the larger bodies are compiled
// once for both in src/reference/math.cpp. Vector and matrix parameters accept any Eigen
// expression of the right size and scalar (e.g. Vec3f::UnitZ(), a - b); scalar parameters take
// their type from the first one. Bad input throws simdphys::Error.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>
#include <type_traits>

#include "simdphys/core.hpp"

namespace simdphys {

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using Vec4 = Eigen::Matrix<T, 4, 1>;
template <class T>
using Mat2 = Eigen::Matrix<T, 2, 2>;
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template <class T>
using Mat4 = Eigen::Matrix<T, 4, 4>;
template <class T>
using Quat = Eigen::Quaternion<T>;

using Vec2f = Vec2<float>;
using Vec3f = Vec3<float>;
using Vec4f = Vec4<float>;
using Mat2f = Mat2<float>;
using Mat3f = Mat3<float>;
using Mat4f = Mat4<float>;
using Quatf = Quat<float>;

using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;
using Vec4d = Vec4<double>;
using Mat2d = Mat2<double>;
using Mat3d = Mat3<double>;
using Mat4d = Mat4<double>;
using Quatd = Quat<double>;

// The relative tolerance of the geometry tests, 2D and 3D: a distance or gap up to
// kGeometryTolerance * scale counts as zero (a point on a shape, shapes touching), the scale
// stated per function. 16 eps is 1.9e-6 in float and 3.6e-15 in double: at least four times the
// rounding error of each computation it is used in (a few dot or cross products of offsets, or a
// rotation into a local frame: 2-4 eps times the scale).
template <class T>
inline constexpr T kGeometryTolerance = T(16) * std::numeric_limits<T>::epsilon();

// The supported range (docs/architecture.md), the same in float and double. Coordinates, sizes
// and distances are at most kMaxCoordinate in magnitude, so a squared length of a difference of
// two points (at most 3 * (2e18)^2 = 1.2e37) stays finite in float; computations inside the range
// must not overflow (products of two squared lengths would: they are scaled first). Scale
// factors that get inverted (transform scales, projection extents) lie in [kMinScale,
// kMaxCoordinate], so their inverses stay in range and their squares (1e-36) are normal floats.
// Directions and normals that the library normalises may have any finite non-zero length (they
// are scaled before their length is taken). Values enter through validate(), the streams,
// meshes, transforms and files, which reject anything outside the range with an Error.
inline constexpr float kMaxCoordinate = 1e18f;
inline constexpr float kMinScale = 1e-18f;

// A world-space ray through a pixel (see screenToRay).
template <class T>
struct ScreenRay {
  Vec3<T> origin;     // on the near plane
  Vec3<T> direction;  // unit length, away from the camera
};

namespace detail {

// Keeps trailing scalar arguments from taking part in deduction, so perspective(1.0f, 1.5, ...)
// is a float call rather than a deduction conflict.
template <class T>
using NoDeduce = std::type_identity_t<T>;

template <class D>
using ColumnOf = Eigen::Matrix<typename D::Scalar, D::RowsAtCompileTime, 1>;

// A fixed-size square matrix of 2x2 to 4x4, as the minor and cofactor functions take.
template <class D>
using SquareOf = Eigen::Matrix<typename D::Scalar, D::RowsAtCompileTime, D::ColsAtCompileTime>;

template <class D>
constexpr void requireSquare2To4() {
  static_assert(D::RowsAtCompileTime == D::ColsAtCompileTime && D::RowsAtCompileTime >= 2 &&
                    D::RowsAtCompileTime <= 4,
                "a fixed-size 2x2, 3x3 or 4x4 matrix is expected");
}

// The bodies of the functions below that take Eigen expressions: each function converts its
// arguments to plain vectors and matrices and calls one of these, compiled once for float and
// double (src/reference/math.cpp).
template <class T, int N>
T matrixMinor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row, Eigen::Index col);
template <class T, int N>
T cofactor(const Eigen::Matrix<T, N, N>& m, Eigen::Index row, Eigen::Index col);
template <class T, int N>
Eigen::Matrix<T, N, N> cofactorMatrix(const Eigen::Matrix<T, N, N>& m);
template <std::floating_point T>
Vec3<T> matrixToEuler(const Mat3<T>& r);
template <std::floating_point T>
Mat3<T> axisAngle(const Vec3<T>& axis, T angle);
template <std::floating_point T>
Mat4<T> transform(const Vec3<T>& s, const Mat3<T>& r, const Vec3<T>& t);
template <std::floating_point T>
Mat4<T> transform(const Vec3<T>& scale, const Quat<T>& q, const Vec3<T>& translation);
template <std::floating_point T>
Vec3<T> transformPoint(const Mat4<T>& m, const Vec3<T>& p);
template <std::floating_point T>
Vec3<T> transformDirection(const Mat4<T>& m, const Vec3<T>& d);
template <std::floating_point T>
Mat4<T> lookAt(const Vec3<T>& e, const Vec3<T>& t, const Vec3<T>& u);
template <std::floating_point T>
Vec3<T> unproject(const Vec3<T>& w, const Vec4<T>& vp, const Mat4<T>& inv);
template <std::floating_point T>
ScreenRay<T> screenToRay(T px, T py, const Vec4<T>& viewport, const Mat4<T>& view,
                         const Mat4<T>& projection);
// `fn` names the caller in the Error thrown for a zero or non-finite `onto`.
template <class T, int N>
Eigen::Matrix<T, N, 1> project(const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& onto,
                               const char* fn);
template <class T, int N>
Eigen::Matrix<T, N, 1> reflect(const Eigen::Matrix<T, N, 1>& v,
                               const Eigen::Matrix<T, N, 1>& normal);
template <class T, int N>
T angleBetween(const Eigen::Matrix<T, N, 1>& a, const Eigen::Matrix<T, N, 1>& b);
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Minors, cofactors and the adjugate of fixed-size 2x2, 3x3 and 4x4 matrices (book chapter 2).
// Eigen has the determinant and the inverse but not these. They need no division, so they stay
// defined where the inverse is not: adjugate(m) * m == det(m) * I holds for singular m too, and
// for a 3x3 A, cofactorMatrix(A) = det(A) A^-T maps cross products, (A u) x (A v) ==
// cofactorMatrix(A) (u x v): the normal matrix of A up to scale. Rows and columns count from 0;
// an out-of-range row or column throws Error.
// (Not named `minor`: glibc's <sys/sysmacros.h> defines a macro of that name.)

// Determinant of m with the given row and column removed.
template <class D>
typename D::Scalar matrixMinor(const Eigen::MatrixBase<D>& m, Eigen::Index row, Eigen::Index col) {
  detail::requireSquare2To4<D>();
  return detail::matrixMinor(detail::SquareOf<D>(m), row, col);
}

// (-1)^(row + col) times the minor: the factor of m(row, col) in the Laplace expansion of the
// determinant along that row or column.
template <class D>
typename D::Scalar cofactor(const Eigen::MatrixBase<D>& m, Eigen::Index row, Eigen::Index col) {
  detail::requireSquare2To4<D>();
  return detail::cofactor(detail::SquareOf<D>(m), row, col);
}

// The matrix of all cofactors: element (i, j) is cofactor(m, i, j).
template <class D>
detail::SquareOf<D> cofactorMatrix(const Eigen::MatrixBase<D>& m) {
  detail::requireSquare2To4<D>();
  return detail::cofactorMatrix(detail::SquareOf<D>(m));
}

// The transpose of the cofactor matrix: adjugate(m) * m == m * adjugate(m) == det(m) * I, so
// m^-1 = adjugate(m) / det(m) when det(m) != 0.
template <class D>
detail::SquareOf<D> adjugate(const Eigen::MatrixBase<D>& m) {
  return cofactorMatrix(m).transpose();
}

// ---------------------------------------------------------------------------------------------
// Rotations. Positive angles turn counter-clockwise when looking from the positive axis towards
// the origin (right-hand rule): rotationZ(pi/2) maps +x to +y.

template <std::floating_point T>
Mat3<T> rotationX(T angle);

template <std::floating_point T>
Mat3<T> rotationY(T angle);

template <std::floating_point T>
Mat3<T> rotationZ(T angle);

// R = Ry(yaw) * Rx(pitch) * Rz(roll): roll is applied first, yaw last.
template <std::floating_point T>
Mat3<T> eulerToMatrix(T pitch, detail::NoDeduce<T> yaw, detail::NoDeduce<T> roll);

// Inverse of eulerToMatrix for a rotation matrix: returns (pitch, yaw, roll) with pitch in
// [-pi/2, pi/2], yaw and roll in [-pi, pi]. At gimbal lock (cos(pitch) <= 16 epsilon) yaw and
// roll turn about the same axis and only their combination is defined: roll is set to 0 and
// yaw takes the whole turn. Yaw is solved after roll, from the matrix with roll removed, so
// eulerToMatrix(result) reproduces the input even near the lock.
template <class D>
Vec3<typename D::Scalar> matrixToEuler(const Eigen::MatrixBase<D>& rotation) {
  using T = typename D::Scalar;
  return detail::matrixToEuler<T>(rotation);
}

// Rotation by `angle` about `axis` (any length; normalised here). Throws on a zero or non-finite
// axis or a non-finite angle.
template <class D>
Mat3<typename D::Scalar> axisAngle(const Eigen::MatrixBase<D>& axis, typename D::Scalar angle) {
  using T = typename D::Scalar;
  return detail::axisAngle<T>(axis, angle);
}

// ---------------------------------------------------------------------------------------------
// Transforms. M = T * R * S: scale first, then rotate, then translate.

template <class DS, class DR, class DT>
Mat4<typename DS::Scalar> transform(const Eigen::MatrixBase<DS>& scale,
                                    const Eigen::MatrixBase<DR>& rotation,
                                    const Eigen::MatrixBase<DT>& translation) {
  using T = typename DS::Scalar;
  return detail::transform<T>(scale, rotation, translation);
}

// Same with a quaternion, normalised here (Eigen's toRotationMatrix assumes unit length).
// Throws on a zero or non-finite quaternion.
template <class DS, class Q, class DT>
Mat4<typename DS::Scalar> transform(const Eigen::MatrixBase<DS>& scale,
                                    const Eigen::QuaternionBase<Q>& rotation,
                                    const Eigen::MatrixBase<DT>& translation) {
  using T = typename DS::Scalar;
  return detail::transform<T>(scale, Quat<T>(rotation), translation);
}

// Applies m to the point p (w = 1). If m is affine (last row exactly 0 0 0 1) the result is used
// as is; otherwise m is projective and the result is divided by its w. Points with w = 0 (on the
// camera plane of a perspective matrix) come out non-finite.
template <class DM, class DP>
Vec3<typename DM::Scalar> transformPoint(const Eigen::MatrixBase<DM>& matrix,
                                         const Eigen::MatrixBase<DP>& point) {
  using T = typename DM::Scalar;
  return detail::transformPoint<T>(matrix, point);
}

// Applies m to the direction d (w = 0): translation is ignored. Normals need the inverse
// transpose of m's upper 3x3 instead when m scales non-uniformly.
template <class DM, class DD>
Vec3<typename DM::Scalar> transformDirection(const Eigen::MatrixBase<DM>& matrix,
                                             const Eigen::MatrixBase<DD>& direction) {
  using T = typename DM::Scalar;
  return detail::transformDirection<T>(matrix, direction);
}

// ---------------------------------------------------------------------------------------------
// View and projection (right-handed, the view looks down -z, clip depth in [0, 1]).

// World-to-view matrix of a camera at eye looking at target: target lands on the -z axis, up
// (any length, not necessarily perpendicular to the view direction) appears as +y. Throws if an
// input is non-finite, eye == target, up is zero or parallel to the view direction, or eye is so
// far out that the translation overflows.
template <class DE, class DT, class DU>
Mat4<typename DE::Scalar> lookAt(const Eigen::MatrixBase<DE>& eye,
                                 const Eigen::MatrixBase<DT>& target,
                                 const Eigen::MatrixBase<DU>& up) {
  using T = typename DE::Scalar;
  return detail::lookAt<T>(eye, target, up);
}

// View-to-clip matrix (as glm::perspectiveRH_ZO): the view point at distance zNear in front of
// the camera gets depth 0, at zFar depth 1; fovY is the full vertical field of view, aspect is
// width / height. Throws unless 0 < fovY < pi, aspect > 0, 0 < zNear < zFar, all finite, and the
// matrix's entries come out finite and non-zero (no aspect of 1e-40).
template <std::floating_point T>
Mat4<T> perspective(T fovY, detail::NoDeduce<T> aspect, detail::NoDeduce<T> zNear,
                    detail::NoDeduce<T> zFar);

// View-to-clip matrix of the box [left, right] x [bottom, top] x [-zFar, -zNear] (as
// glm::orthoRH_ZO): the box maps onto [-1, 1]^2 x [0, 1]. Throws on a non-finite bound or an
// empty range (right <= left, top <= bottom, zFar <= zNear), or ranges whose matrix entries
// overflow or vanish; to mirror an axis, scale instead.
template <std::floating_point T>
Mat4<T> orthographic(T left, detail::NoDeduce<T> right, detail::NoDeduce<T> bottom,
                     detail::NoDeduce<T> top, detail::NoDeduce<T> zNear, detail::NoDeduce<T> zFar);

// ---------------------------------------------------------------------------------------------
// Picking. Window coordinates are (px, py, depth): pixels from the top-left corner of the
// window, y down, the centre of pixel (i, j) at (i + 0.5, j + 0.5); depth in [0, 1] as in clip
// space (other depths extrapolate). The viewport is (x, y, width, height) in the same pixels.

// World point whose projection by viewProj (= inverse of inverseViewProj) lands at windowPoint.
// Throws on a non-finite viewport or one with width or height <= 0.
template <class DW, class DV, class DM>
Vec3<typename DW::Scalar> unproject(const Eigen::MatrixBase<DW>& windowPoint,
                                    const Eigen::MatrixBase<DV>& viewport,
                                    const Eigen::MatrixBase<DM>& inverseViewProj) {
  using T = typename DW::Scalar;
  return detail::unproject<T>(windowPoint, viewport, inverseViewProj);
}

// World ray through the window point (px, py) (continuous pixel coordinates as for unproject):
// the origin is on the near plane, the direction points away from the camera. Works for
// perspective and orthographic projections. Throws on a bad viewport, or if the point does not
// unproject to a finite point (non-finite pixel, singular view or projection).
template <class DV, class DW, class DP>
ScreenRay<typename DV::Scalar> screenToRay(typename DV::Scalar px, typename DV::Scalar py,
                                           const Eigen::MatrixBase<DV>& viewport,
                                           const Eigen::MatrixBase<DW>& view,
                                           const Eigen::MatrixBase<DP>& projection) {
  using T = typename DV::Scalar;
  return detail::screenToRay<T>(px, py, viewport, view, projection);
}

// ---------------------------------------------------------------------------------------------
// Vector helpers, for 2D and 3D vectors. Only the direction argument (onto, normal) is
// validated: it must be finite and non-zero, of any length. They are rescaled internally, so
// tiny or huge vectors work where the naive formulas underflow or overflow.

// The part of a along onto.
template <class DA, class DB>
detail::ColumnOf<DA> project(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& onto) {
  return detail::project<typename DA::Scalar, DA::RowsAtCompileTime>(a, onto, "project");
}

// The part of a perpendicular to onto: project(a, onto) + reject(a, onto) == a.
template <class DA, class DB>
detail::ColumnOf<DA> reject(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& onto) {
  return a - detail::project<typename DA::Scalar, DA::RowsAtCompileTime>(a, onto, "reject");
}

// v mirrored in the plane (line in 2D) with the given normal; the normal need not be unit length
// (the book's Reflection assumes it is).
template <class DV, class DN>
detail::ColumnOf<DV> reflect(const Eigen::MatrixBase<DV>& v, const Eigen::MatrixBase<DN>& normal) {
  return detail::reflect<typename DV::Scalar, DV::RowsAtCompileTime>(v, normal);
}

// Unsigned angle in [0, pi] between a and b, as atan2(|a x b|, a . b): accurate to a few ulp
// for all angles, where acos(a . b / |a||b|) loses half the digits near 0 and pi. Throws on a
// zero or non-finite vector.
template <class DA, class DB>
typename DA::Scalar angleBetween(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  static_assert(DA::SizeAtCompileTime == 2 || DA::SizeAtCompileTime == 3, "2D or 3D vectors");
  return detail::angleBetween<typename DA::Scalar, DA::SizeAtCompileTime>(a, b);
}

// Tolerant comparison: |a - b| <= max(absTol, relTol * max(|a|, |b|)). The defaults (epsilon for
// both) are the book's CMP. Equal values (including equal infinities) compare equal; otherwise
// an infinity or a NaN never does.
template <std::floating_point T>
bool nearlyEqual(T a, detail::NoDeduce<T> b,
                 detail::NoDeduce<T> relTol = std::numeric_limits<T>::epsilon(),
                 detail::NoDeduce<T> absTol = std::numeric_limits<T>::epsilon());

// Same for vectors and matrices, on Euclidean (Frobenius) norms rather than per component as in
// the book: the test does not depend on the orientation of the axes.
template <class DA, class DB>
bool nearlyEqual(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b,
                 typename DA::Scalar relTol = std::numeric_limits<typename DA::Scalar>::epsilon(),
                 typename DA::Scalar absTol = std::numeric_limits<typename DA::Scalar>::epsilon()) {
  if (a == b) return true;
  if (!a.allFinite() || !b.allFinite()) return false;
  return (a - b).norm() <= std::max(absTol, relTol * std::max(a.norm(), b.norm()));
}

}  // namespace simdphys

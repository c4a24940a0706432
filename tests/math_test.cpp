// Tests of include/simdphys/math.hpp, in float and in double. Every expected value is worked by
// hand (the derivation is in the comment beside it); every tolerance says why it is what it is.
// "eps" is the machine epsilon of the scalar type: 1.19e-7 (float), 2.22e-16 (double); an ulp of
// a value in [2^k, 2^(k+1)) is 2^k eps.
#include "simdphys/math.hpp"

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "typed.hpp"

#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace simdphys {
namespace {

template <class T>
constexpr T kEps = std::numeric_limits<T>::epsilon();
template <class T>
constexpr T kPi = std::numbers::pi_v<T>;
template <class T>
constexpr T kNaN = std::numeric_limits<T>::quiet_NaN();
template <class T>
constexpr T kInf = std::numeric_limits<T>::infinity();

using test::closeTo;
using test::ScalarName;
using test::Scalars;
using test::v2;
using test::v3;
using test::v4;

template <class T>
class Matrices : public ::testing::Test {};
template <class T>
class Rotations : public ::testing::Test {};
template <class T>
class Transforms : public ::testing::Test {};
template <class T>
class Camera : public ::testing::Test {};
template <class T>
class Picking : public ::testing::Test {};
template <class T>
class Vectors : public ::testing::Test {};
template <class T>
class Compare : public ::testing::Test {};
TYPED_TEST_SUITE(Matrices, Scalars, ScalarName);
TYPED_TEST_SUITE(Rotations, Scalars, ScalarName);
TYPED_TEST_SUITE(Transforms, Scalars, ScalarName);
TYPED_TEST_SUITE(Camera, Scalars, ScalarName);
TYPED_TEST_SUITE(Picking, Scalars, ScalarName);
TYPED_TEST_SUITE(Vectors, Scalars, ScalarName);
TYPED_TEST_SUITE(Compare, Scalars, ScalarName);

// ---------------------------------------------------------------------------------------------
// Types and storage

TEST(Aliases, AreEigenTypesInColumnMajorStorage) {
  static_assert(std::is_same_v<Vec2f, Eigen::Vector2f>);
  static_assert(std::is_same_v<Vec3f, Eigen::Vector3f>);
  static_assert(std::is_same_v<Vec4d, Eigen::Vector4d>);
  static_assert(std::is_same_v<Mat3f, Eigen::Matrix3f>);
  static_assert(std::is_same_v<Mat4d, Eigen::Matrix4d>);
  static_assert(std::is_same_v<Quatf, Eigen::Quaternionf>);
  static_assert(std::is_same_v<Mat2<double>, Eigen::Matrix2d>);
  static_assert((Mat4f::Flags & Eigen::RowMajorBit) == 0);
  // Column vectors: the translation lives in the last column, element (row 0, column 3) is the
  // 13th stored float (index 12) in column-major order.
  Mat4f m = Mat4f::Identity();
  m(0, 3) = 5;
  EXPECT_EQ(m.data()[12], 5.0f);
  EXPECT_EQ(transformPoint(m, Vec3f(1, 2, 3)), Vec3f(6, 2, 3));  // exact: 1 + 5
}

// ---------------------------------------------------------------------------------------------
// Minors, cofactors and the adjugate

// Draws count N x N matrices with entries uniform in [-1, 1] plus `diagonal` on the diagonal,
// from a fixed seed; drawn in double and rounded, so float and double see the same matrices.
template <class T, int N>
std::vector<Eigen::Matrix<T, N, N>> randomMatrices(int count, double diagonal = 0) {
  std::mt19937 rng(20240 + N);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Eigen::Matrix<T, N, N>> out(count);
  for (auto& m : out) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) m(i, j) = T(u(rng) + (i == j ? diagonal : 0));
  }
  return out;
}

constexpr int factorial(int n) { return n <= 1 ? 1 : n * factorial(n - 1); }

TYPED_TEST(Matrices, HandWorked3x3) {
  using T = TypeParam;
  Mat3<T> m;
  m << 3, 0, 2,  //
      2, 0, -2,  //
      0, 1, 1;
  // Minor (i, j): delete row i and column j, take the 2x2 determinant |a b; c d| = ad - bc.
  //   M00 = |0 -2; 1  1| = 0 + 2  =   2   M01 = |2 -2; 0  1| = 2 - 0 = 2   M02 = |2 0; 0 1| = 2
  //   M10 = |0  2; 1  1| = 0 - 2  =  -2   M11 = |3  2; 0  1| = 3 - 0 = 3   M12 = |3 0; 0 1| = 3
  //   M20 = |0  2; 0 -2| = 0 - 0  =   0   M21 = |3  2; 2 -2| = -6 - 4 = -10 M22 = |3 0; 2 0| = 0
  // Cofactors flip the sign where i + j is odd (01, 10, 12, 21, all non-zero here, so every
  // flip is checked): C = [2 -2 2; 2 3 -3; 0 10 0]. The adjugate is C transposed (m is not
  // symmetric, so the transpose is checked too): [2 2 0; -2 3 10; 2 -3 0]. det m, along row 0:
  // 3*2 + 0*(-2) + 2*2 = 10. adj * m: row 0 of adj, (2 2 0), times column 0 of m, (3 2 0), is
  // 10; times column 2, (2 -2 1), is 4 - 4 = 0; and so on: 10 I.
  // All values are small integers made by products and differences of small integers: exact in
  // float and double, so compared with ==.
  Mat3<T> minors, cofactors, adj;
  minors << 2, 2, 2, -2, 3, 3, 0, -10, 0;
  cofactors << 2, -2, 2, 2, 3, -3, 0, 10, 0;
  adj << 2, 2, 0, -2, 3, 10, 2, -3, 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(matrixMinor(m, i, j), minors(i, j)) << "row " << i << " col " << j;
      EXPECT_EQ(cofactor(m, i, j), cofactors(i, j)) << "row " << i << " col " << j;
    }
  }
  EXPECT_EQ(cofactorMatrix(m), cofactors);
  EXPECT_EQ(adjugate(m), adj);
  EXPECT_EQ(m.determinant(), T(10));
  EXPECT_EQ(Mat3<T>(adjugate(m) * m), Mat3<T>(10 * Mat3<T>::Identity()));
  // Any Eigen expression is accepted: the transpose's adjugate is the adjugate's transpose.
  EXPECT_EQ(adjugate(m.transpose()), Mat3<T>(adj.transpose()));
}

TYPED_TEST(Matrices, HandWorked2x2And4x4) {
  using T = TypeParam;
  // 2x2 [a b; c d]: each minor is the one entry left, M = [d c; b a]; C = [d -c; -b a];
  // adj = [d -b; -c a]. With a, b, c, d = 4, 7, 2, 6: det = 24 - 14 = 10.
  Mat2<T> m2, adj2;
  m2 << 4, 7, 2, 6;
  adj2 << 6, -7, -2, 4;
  EXPECT_EQ(matrixMinor(m2, 0, 0), T(6));
  EXPECT_EQ(matrixMinor(m2, 0, 1), T(2));
  EXPECT_EQ(cofactor(m2, 0, 1), T(-2));
  EXPECT_EQ(cofactor(m2, 1, 0), T(-7));
  EXPECT_EQ(adjugate(m2), adj2);
  EXPECT_EQ(Mat2<T>(adjugate(m2) * m2), Mat2<T>(10 * Mat2<T>::Identity()));
  // 4x4 upper triangular U (diagonal 1 2 3 4, ones above): det = 24. A minor that deletes row
  // i and column i leaves a triangular matrix: M00 = 2*3*4 = 24, M33 = 1*2*3 = 6. Deleting row
  // 2 and column 1 leaves [1 1 1; 0 1 1; 0 0 4], triangular: M21 = 4, so C21 = -4. Deleting
  // row 3 and column 0 leaves [1 1 1; 2 1 1; 0 3 1]: 1(1 - 3) - 1(2 - 0) + 1(6 - 0) = 2, so
  // C30 = -2. Cross-check with U^-1 by back substitution: column 3 solves U x = e3:
  // x3 = 1/4, x2 = -x3/3 = -1/12, x1 = -(x2 + x3)/2 = -1/12, x0 = -(x1 + x2 + x3) = -1/12; and
  // column 2: x2 = 1/3, x1 = -1/6. So adj(0, 3) = C30 = 24 * (-1/12) = -2 and
  // adj(1, 2) = C21 = 24 * (-1/6) = -4. Small integers again: exact.
  Mat4<T> u;
  u << 1, 1, 1, 1,  //
      0, 2, 1, 1,   //
      0, 0, 3, 1,   //
      0, 0, 0, 4;
  EXPECT_EQ(matrixMinor(u, 0, 0), T(24));
  EXPECT_EQ(matrixMinor(u, 3, 3), T(6));
  EXPECT_EQ(matrixMinor(u, 2, 1), T(4));
  EXPECT_EQ(cofactor(u, 2, 1), T(-4));
  EXPECT_EQ(matrixMinor(u, 3, 0), T(2));
  EXPECT_EQ(cofactor(u, 3, 0), T(-2));
  EXPECT_EQ(adjugate(u)(0, 3), T(-2));
  EXPECT_EQ(adjugate(u)(1, 2), T(-4));
  EXPECT_EQ(Mat4<T>(adjugate(u) * u), Mat4<T>(24 * Mat4<T>::Identity()));
}

TYPED_TEST(Matrices, SingularMatricesHaveAnAdjugate) {
  using T = TypeParam;
  // [1 2 3; 4 5 6; 7 8 9] has det 0 (row 2 - row 1 = row 1 - row 0) and no inverse, but its
  // cofactors exist: C00 = 45 - 48 = -3, C01 = -(36 - 42) = 6, C02 = 32 - 35 = -3,
  // C10 = -(18 - 24) = 6, C11 = 9 - 21 = -12, C12 = -(8 - 14) = 6, C20 = 12 - 15 = -3,
  // C21 = -(6 - 12) = 6, C22 = 5 - 8 = -3; C is symmetric so adj = C, and adj * m = 0 * I
  // (row 0 of adj times column 0 of m: -3 + 24 - 21 = 0). Exact small integers.
  Mat3<T> m, adj;
  m << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  adj << -3, 6, -3, 6, -12, 6, -3, 6, -3;
  EXPECT_EQ(adjugate(m), adj);
  EXPECT_EQ(Mat3<T>(adjugate(m) * m), Mat3<T>::Zero());
  EXPECT_EQ(Mat3<T>(m * adjugate(m)), Mat3<T>::Zero());
}

template <class T, int N>
void checkAdjugateIdentity() {
  // adj(M) M - det(M) I is zero exactly; computed, each entry of either side is a sum of n!
  // products of n entries of size <= 1 (its Laplace expansion), and each product goes through
  // at most 3n roundings of u = eps/2, so each side is off by at most (3n/2) n! eps and their
  // difference by 3n n! eps. Allowed: 4 n n! eps (16, 72, 384 eps for n = 2, 3, 4; 4.6e-5 for
  // a 4x4 in float). Independent of conditioning: this is a polynomial identity, not a solve.
  // (Bounds for the worst case; over 1e5 such matrices the largest error seen is 6 eps.)
  const double tol = 4 * N * factorial(N) * kEps<T>;
  using M = Eigen::Matrix<T, N, N>;
  for (const M& m : randomMatrices<T, N>(200)) {
    const M expected = m.determinant() * M::Identity();
    EXPECT_TRUE(closeTo(adjugate(m) * m, expected, tol)) << "m:\n" << m;
    EXPECT_TRUE(closeTo(m * adjugate(m), expected, tol)) << "m:\n" << m;
  }
}

TYPED_TEST(Matrices, AdjugateTimesMatrixIsDeterminantTimesIdentity) {
  checkAdjugateIdentity<TypeParam, 2>();
  checkAdjugateIdentity<TypeParam, 3>();
  checkAdjugateIdentity<TypeParam, 4>();
}

template <class T, int N>
void checkAdjugateInverse() {
  // M = 2n I + R with |r| <= 1 is diagonally dominant: |diagonal| >= 2n - 1 against off-diagonal
  // row sums <= n - 1, so |det M| >= n^n, the entries of M^-1 are <= 1/n, and the absolute terms
  // of any k x k subdeterminant sum to at most (3n)^k (the product of absolute row sums). With at
  // most 3n roundings of u = eps/2 per term, a cofactor is off by <= (3n/2) eps (3n)^(n-1),
  // i.e. by (3/2) 3^(n-1) eps after dividing by det; det's relative error (3n/2) 3^n eps moves
  // the quotient (<= 1/n) by (3/2) 3^n eps: about 2 * 3^n eps in all. Eigen inverts n <= 4 with
  // the same closed-form cofactor formulas, so it is as far from the truth. Allowed:
  // 4 * 3^n eps (36, 108, 324 eps; 3.9e-5 for a 4x4 in float). (Worst case; over 1e5 such
  // matrices the largest difference seen is 0.62 eps.)
  double power = 1;
  for (int i = 0; i < N; ++i) power *= 3;
  const double tol = 4 * power * kEps<T>;
  using M = Eigen::Matrix<T, N, N>;
  for (const M& m : randomMatrices<T, N>(200, 2 * N)) {
    EXPECT_TRUE(closeTo(M(adjugate(m) / m.determinant()), M(m.inverse()), tol)) << "m:\n" << m;
  }
}

TYPED_TEST(Matrices, AdjugateOverDeterminantIsTheInverse) {
  checkAdjugateInverse<TypeParam, 2>();
  checkAdjugateInverse<TypeParam, 3>();
  checkAdjugateInverse<TypeParam, 4>();
}

using test::expectError;

TYPED_TEST(Matrices, RejectOutOfRangeRowOrColumn) {
  using T = TypeParam;
  const Mat2<T> m2 = Mat2<T>::Identity();
  const Mat3<T> m3 = Mat3<T>::Identity();
  const Mat4<T> m4 = Mat4<T>::Identity();
  expectError([&] { (void)matrixMinor(m3, 3, 0); },
              "matrixMinor: (row 3, col 0) is outside a 3x3 matrix");
  expectError([&] { (void)cofactor(m3, 0, -1); }, "cofactor: (row 0, col -1) is outside a 3x3");
  EXPECT_THROW((void)matrixMinor(m2, 2, 0), Error);
  EXPECT_THROW((void)matrixMinor(m2, 0, 2), Error);
  EXPECT_THROW((void)matrixMinor(m2, -1, 0), Error);
  EXPECT_THROW((void)cofactor(m2, 1, 2), Error);
  EXPECT_THROW((void)matrixMinor(m3, 0, 3), Error);
  EXPECT_THROW((void)matrixMinor(m3, -1, 1), Error);
  EXPECT_THROW((void)matrixMinor(m4, 4, 0), Error);
  EXPECT_THROW((void)matrixMinor(m4, 0, 4), Error);
  EXPECT_THROW((void)cofactor(m4, 4, 4), Error);
  EXPECT_THROW((void)cofactor(m4, -1, 3), Error);
  // The last valid index is accepted.
  EXPECT_EQ(matrixMinor(m2, 1, 1), T(1));
  EXPECT_EQ(matrixMinor(m3, 2, 2), T(1));
  EXPECT_EQ(cofactor(m4, 3, 3), T(1));
}

// ---------------------------------------------------------------------------------------------
// Rotations

TYPED_TEST(Rotations, QuarterTurnsFollowTheRightHandRule) {
  using T = TypeParam;
  const T h = kPi<T> / 2;
  const Vec3<T> x = Vec3<T>::UnitX(), y = Vec3<T>::UnitY(), z = Vec3<T>::UnitZ();
  // pi/2 is rounded by up to eps/2 (an ulp of 1.57 is eps), so cos comes out as about that and
  // sin as 1 within an ulp: 2 eps.
  const double tol = 2 * kEps<T>;
  EXPECT_TRUE(closeTo(rotationZ(h) * x, y, tol));   // x turns towards y about +z
  EXPECT_TRUE(closeTo(rotationZ(h) * y, -x, tol));  //
  EXPECT_TRUE(closeTo(rotationZ(h) * z, z, tol));   // the axis is fixed
  EXPECT_TRUE(closeTo(rotationX(h) * y, z, tol));   // y turns towards z about +x
  EXPECT_TRUE(closeTo(rotationX(h) * z, -y, tol));
  EXPECT_TRUE(closeTo(rotationY(h) * z, x, tol));  // z turns towards x about +y
  EXPECT_TRUE(closeTo(rotationY(h) * x, -z, tol));
}

TYPED_TEST(Rotations, HandWorkedAngles) {
  using T = TypeParam;
  const T r3 = std::sqrt(T(3)) / 2, r2 = std::sqrt(T(2)) / 2;
  // Angle rounded (<= eps/2 relative), sin/cos within an ulp, expected values within half an
  // ulp; all of magnitude <= 1: 4 eps.
  const double tol = 4 * kEps<T>;
  // Rz(pi/6) x = (cos 30, sin 30, 0).
  EXPECT_TRUE(closeTo(rotationZ(kPi<T> / 6) * Vec3<T>::UnitX(), Vec3<T>(r3, 0.5, 0), tol));
  // Rx(pi/3) y = (0, cos 60, sin 60).
  EXPECT_TRUE(closeTo(rotationX(kPi<T> / 3) * Vec3<T>::UnitY(), Vec3<T>(0, 0.5, r3), tol));
  // Ry(a) x = (cos a, 0, -sin a); a = -pi/4 gives (r2, 0, r2).
  EXPECT_TRUE(closeTo(rotationY(-kPi<T> / 4) * Vec3<T>::UnitX(), Vec3<T>(r2, 0, r2), tol));
}

TYPED_TEST(Rotations, AreOrthonormalWithDeterminantOne) {
  using T = TypeParam;
  // Each entry of R^T R is a 3-term dot of entries carrying about an ulp: <= 6 eps, and the
  // determinant a sum of products of such entries of total weight 1: 8 eps for both.
  const double tol = 8 * kEps<T>;
  for (const T a : {T(-3), T(-1.2), T(0), T(0.4), T(2.5)}) {
    for (const Mat3<T>& r : {rotationX(a), rotationY(a), rotationZ(a), eulerToMatrix(a, 2 * a, -a),
                             axisAngle(v3<T>(1, -2, 0.5), a)}) {
      EXPECT_TRUE(closeTo(r.transpose() * r, Mat3<T>::Identity(), tol)) << "angle " << a;
      EXPECT_TRUE(closeTo(r.determinant(), T(1), tol)) << "angle " << a;
    }
  }
}

TYPED_TEST(Rotations, EulerAppliesRollThenPitchThenYaw) {
  using T = TypeParam;
  const T h = kPi<T> / 2;
  // Quarter turns: roll (z) takes x to y, pitch (x) takes y to z, yaw (y) takes z to x, so x
  // ends at x. y: roll -> -x, pitch keeps -x, yaw -> +z. z: roll keeps z, pitch -> -y, yaw
  // keeps -y. Columns (x, z, -y). The reverse order Rz Rx Ry would send x to -x instead.
  Mat3<T> expected;
  expected << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  // Three products of matrices whose entries are exact but for cos(pi/2) ~ eps: 4 eps.
  EXPECT_TRUE(closeTo(eulerToMatrix(h, h, h), expected, 4 * kEps<T>));
  // One angle alone: the other two factors are exactly the identity (cos 0 = 1, sin 0 = 0), so
  // the product is exact.
  const T a = T(0.3);
  EXPECT_EQ(eulerToMatrix(a, T(0), T(0)), rotationX(a));
  EXPECT_EQ(eulerToMatrix(T(0), a, T(0)), rotationY(a));
  EXPECT_EQ(eulerToMatrix(T(0), T(0), a), rotationZ(a));
}

TYPED_TEST(Rotations, MatrixToEulerOfSingleAxisRotations) {
  using T = TypeParam;
  const T a = T(0.3);
  // Rx(a) has row 1 = (0, cos a, -sin a): pitch = atan2(sin a, cos a) = a, roll = atan2(0, .) = 0,
  // yaw = atan2(0, 1) = 0; likewise for y and z. atan2 of entries within an ulp: 4 eps.
  const double tol = 4 * kEps<T>;
  EXPECT_TRUE(closeTo(matrixToEuler(rotationX(a)), Vec3<T>(a, 0, 0), tol));
  EXPECT_TRUE(closeTo(matrixToEuler(rotationY(a)), Vec3<T>(0, a, 0), tol));
  EXPECT_TRUE(closeTo(matrixToEuler(rotationZ(a)), Vec3<T>(0, 0, a), tol));
}

TYPED_TEST(Rotations, MatrixToEulerInvertsEulerToMatrixAwayFromGimbalLock) {
  using T = TypeParam;
  for (const T pitch : {T(-1.5), T(-0.8), T(0), T(0.6), T(1.2), T(1.5)}) {
    // Entries of R carry ~3 eps; yaw and roll are read from entries of size cos(pitch), so
    // their error grows as 1/cos(pitch): 16 eps / cos(pitch) (at most 2.7e-5 float, 5e-14 double
    // for pitch = 1.5). Angles up to 3.1 add a few ulp of 3.1 (2 eps each).
    const double tol = 16 * kEps<T> / std::cos(pitch);
    for (const T yaw : {T(-3.0), T(-1.7), T(-0.4), T(0), T(0.9), T(2.2), T(3.1)}) {
      for (const T roll : {T(-3.0), T(-1.7), T(-0.4), T(0), T(0.9), T(2.2), T(3.1)}) {
        const Mat3<T> r = eulerToMatrix(pitch, yaw, roll);
        const Vec3<T> e = matrixToEuler(r);
        EXPECT_TRUE(closeTo(e, Vec3<T>(pitch, yaw, roll), tol))
            << "pitch " << pitch << " yaw " << yaw << " roll " << roll;
        // Rebuilding from the result is accurate whatever the pitch: 8 eps on entries <= 1.
        EXPECT_TRUE(closeTo(eulerToMatrix(e.x(), e.y(), e.z()), r, 8 * kEps<T>));
      }
    }
  }
  // Just outside the gimbal-lock threshold (cos(pitch) = 1e-5 > 16 eps even in float), yaw and
  // roll are ill-conditioned individually but the result still rebuilds the matrix: 8 eps.
  const Mat3<T> r = eulerToMatrix(kPi<T> / 2 - T(1e-5), T(0.7), T(-2.1));
  const Vec3<T> e = matrixToEuler(r);
  EXPECT_TRUE(closeTo(eulerToMatrix(e.x(), e.y(), e.z()), r, 8 * kEps<T>));
}

TYPED_TEST(Rotations, GimbalLockPutsTheWholeTurnInYaw) {
  using T = TypeParam;
  const T h = kPi<T> / 2;
  // At pitch = +pi/2, Rx maps z to -y, so Rx Rz(r) = Ry(-r) Rx and Ry(y) Rx Rz(r) = Ry(y - r) Rx:
  // only yaw - roll is defined; the convention is roll = 0, yaw = y - r = 0.7 - 0.2.
  // At pitch = -pi/2, Rx maps z to +y: yaw = y + r = 0.9.
  // Pitch: atan2(1, ~cos(pi/2) ~ eps) is pi/2 within an ulp; yaw: atan2 of entries within ~3 eps.
  // 8 eps for both.
  const double tol = 8 * kEps<T>;
  const Mat3<T> up = eulerToMatrix(h, T(0.7), T(0.2));
  EXPECT_TRUE(closeTo(matrixToEuler(up), Vec3<T>(h, T(0.5), 0), tol));
  const Mat3<T> down = eulerToMatrix(-h, T(0.7), T(0.2));
  EXPECT_TRUE(closeTo(matrixToEuler(down), Vec3<T>(-h, T(0.9), 0), tol));
  // The result rebuilds the matrix: 8 eps on entries <= 1.
  for (const Mat3<T>& r : {up, down}) {
    const Vec3<T> e = matrixToEuler(r);
    EXPECT_TRUE(closeTo(eulerToMatrix(e.x(), e.y(), e.z()), r, tol));
  }
  // The exact matrix of Rx(pi/2) (columns x, z, -y): cos(pitch) is exactly 0, the answer is
  // exactly (fl(pi/2), 0, 0).
  Mat3<T> exact;
  exact << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  EXPECT_EQ(matrixToEuler(exact), Vec3<T>(h, 0, 0));
}

TYPED_TEST(Rotations, AxisAngleHandWorked) {
  using T = TypeParam;
  // Angles rounded, sin/cos within an ulp, Rodrigues adds a few roundings on entries <= 1: 8 eps.
  const double tol = 8 * kEps<T>;
  // About +z (given with length 2) by pi/2: the same as Rz(pi/2), x -> y.
  EXPECT_TRUE(
      closeTo(axisAngle(v3<T>(0, 0, 2), kPi<T> / 2) * Vec3<T>::UnitX(), Vec3<T>::UnitY(), tol));
  // About the diagonal (1,1,1) by 2pi/3 the axes cycle x -> y -> z -> x. Rodrigues for x with
  // k = (1,1,1)/sqrt3, cos = -1/2, sin = sqrt3/2: -x/2 + (sqrt3/2)(k cross x) + (3/2)(k.x) k
  // = (-1/2, 0, 0) + (0, 1/2, -1/2) + (1/2, 1/2, 1/2) = (0, 1, 0).
  const Mat3<T> cycle = axisAngle(v3<T>(1, 1, 1), 2 * kPi<T> / 3);
  EXPECT_TRUE(closeTo(cycle * Vec3<T>::UnitX(), Vec3<T>::UnitY(), tol));
  EXPECT_TRUE(closeTo(cycle * Vec3<T>::UnitY(), Vec3<T>::UnitZ(), tol));
  EXPECT_TRUE(closeTo(cycle * Vec3<T>::UnitZ(), Vec3<T>::UnitX(), tol));
  // A zero angle is exactly the identity (cos 0 = 1, sin 0 = 0).
  EXPECT_EQ(axisAngle(v3<T>(3, -1, 2), T(0)), Mat3<T>::Identity());
}

TYPED_TEST(Rotations, AxisAngleAgreesWithEigenAngleAxis) {
  using T = TypeParam;
  for (const Vec3<T>& axis : {v3<T>(1, 2, 3), v3<T>(0, 0, -2), v3<T>(-1, 0.5, 0.25)}) {
    for (const T angle : {T(-2.5), T(0.1), T(1), T(3)}) {
      const Mat3<T> eigen = Eigen::AngleAxis<T>(angle, axis.normalized()).toRotationMatrix();
      // Two formulas for the same entries <= 1, each a few roundings: 8 eps.
      EXPECT_TRUE(closeTo(axisAngle(axis, angle), eigen, 8 * kEps<T>)) << "angle " << angle;
    }
  }
}

TYPED_TEST(Rotations, AxisAngleRejectsBadInput) {
  using T = TypeParam;
  EXPECT_THROW(axisAngle(Vec3<T>::Zero(), T(1)), Error);
  EXPECT_THROW(axisAngle(v3<T>(0, kNaN<T>, 1), T(1)), Error);
  EXPECT_THROW(axisAngle(v3<T>(kInf<T>, 0, 0), T(1)), Error);
  EXPECT_THROW(axisAngle(Vec3<T>::UnitZ(), kNaN<T>), Error);
  EXPECT_THROW(axisAngle(Vec3<T>::UnitZ(), kInf<T>), Error);
  // Tiny but non-zero axes are fine: normalisation rescales first.
  EXPECT_NO_THROW(axisAngle(v3<T>(0, 0, 1e-30), T(1)));
}

// ---------------------------------------------------------------------------------------------
// Transforms

TYPED_TEST(Transforms, ScaleThenRotateThenTranslate) {
  using T = TypeParam;
  const Vec3<T> s = v3<T>(2, 3, 4), t = v3<T>(1, 2, 3);
  const Mat4<T> m = transform(s, rotationZ(kPi<T> / 2), t);
  // (1,1,1) scaled -> (2,3,4), turned by Rz(90): (x, y) -> (-y, x) gives (-3,2,4), moved ->
  // (-2,4,7). Errors: cos(pi/2) ~ eps times values <= 4, plus roundings of results up to 7
  // (ulp 4 eps): 16 eps.
  const double tol = 16 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(m, v3<T>(1, 1, 1)), v3<T>(-2, 4, 7), tol));
  // A direction is scaled and turned, not moved.
  EXPECT_TRUE(closeTo(transformDirection(m, v3<T>(1, 1, 1)), v3<T>(-3, 2, 4), tol));
  // The translation is stored as is in the last column, the last row is exactly 0 0 0 1.
  EXPECT_EQ(Vec3<T>(m.template topRightCorner<3, 1>()), t);
  EXPECT_EQ(Vec4<T>(m.row(3).transpose()), v4<T>(0, 0, 0, 1));
}

TYPED_TEST(Transforms, QuaternionOverloadMatchesMatrixOverload) {
  using T = TypeParam;
  const Vec3<T> s = v3<T>(2, 3, 4), t = v3<T>(1, 2, 3);
  const Quat<T> q(Eigen::AngleAxis<T>(T(0.8), v3<T>(1, -1, 2).normalized()));
  const Mat4<T> expected = transform(s, axisAngle(v3<T>(1, -1, 2), T(0.8)), t);
  // Two routes to rotation entries <= 1 (a few ulp each), scaled by up to 4: 32 eps.
  EXPECT_TRUE(closeTo(transform(s, q, t), expected, 32 * kEps<T>));
  // A non-unit quaternion is normalised: scaling all coefficients by 3 changes nothing beyond
  // the rounding of the normalisation (an ulp on entries, scaled by 4): 32 eps.
  const Quat<T> q3(Vec4<T>(3 * q.coeffs()));
  EXPECT_TRUE(closeTo(transform(s, q3, t), expected, 32 * kEps<T>));
  EXPECT_THROW(transform(s, Quat<T>(0, 0, 0, 0), t), Error);
  EXPECT_THROW(transform(s, Quat<T>(kNaN<T>, 0, 0, 1), t), Error);
}

TYPED_TEST(Transforms, InverseUndoesTheTransform) {
  using T = TypeParam;
  const Vec3<T> s = v3<T>(0.5, 2, 3), t = v3<T>(10, -4, 2);
  const Mat3<T> r = axisAngle(v3<T>(1, -2, 0.5), T(0.7));
  const Mat4<T> m = transform(s, r, t);
  // By hand: (T R S)^-1 = S^-1 R^T T^-1, i.e. linear part S^-1 R^T, translation -S^-1 R^T t.
  Mat4<T> inv = Mat4<T>::Identity();
  const Mat3<T> linear = s.cwiseInverse().asDiagonal() * r.transpose();
  inv.template topLeftCorner<3, 3>() = linear;
  inv.template topRightCorner<3, 1>() = -linear * t;
  // The linear part has condition 3 / 0.5 = 6 and the translation reaches ~10 / 0.5 = 20; a
  // general 4x4 inverse loses about cond * magnitude * eps ~ 120 eps: 256 eps.
  const double tol = 256 * kEps<T>;
  EXPECT_TRUE(closeTo(m.inverse(), inv, tol));
  EXPECT_TRUE(closeTo(inv * m, Mat4<T>::Identity(), tol));
  for (const Vec3<T>& p : {v3<T>(0, 0, 0), v3<T>(1, 2, 3), v3<T>(-7, 0.25, 5)}) {
    EXPECT_TRUE(closeTo(transformPoint(inv, transformPoint(m, p)), p, tol));
    EXPECT_TRUE(closeTo(transformDirection(inv, transformDirection(m, p)), p, tol));
  }
}

TYPED_TEST(Transforms, PointsDivideByWOnlyForProjectiveMatrices) {
  using T = TypeParam;
  // Affine (last row 0 0 0 1): no divide; the sums are exact in binary.
  Mat4<T> affine = Mat4<T>::Identity();
  affine.template topRightCorner<3, 1>() = v3<T>(5, 6, 7);
  EXPECT_EQ(transformPoint(affine, v3<T>(1, 2, 3)), v3<T>(6, 8, 10));
  // Directions ignore translation, exactly.
  EXPECT_EQ(transformDirection(affine, v3<T>(1, 2, 3)), v3<T>(1, 2, 3));
  // Projective: diag(1,1,1,2) gives w = 2, so the point is halved (exact: a power of two).
  const Mat4<T> half = v4<T>(1, 1, 1, 2).asDiagonal();
  EXPECT_EQ(transformPoint(half, v3<T>(2, 4, -6)), v3<T>(1, 2, -3));
  // Projective with w = -z (a pinhole): (2, 4, -2) has w = 2 -> (1, 2, -1), exact.
  Mat4<T> pinhole = Mat4<T>::Identity();
  pinhole(3, 3) = 0;
  pinhole(3, 2) = -1;
  EXPECT_EQ(transformPoint(pinhole, v3<T>(2, 4, -2)), v3<T>(1, 2, -1));
}

// ---------------------------------------------------------------------------------------------
// View and projection

TYPED_TEST(Camera, LookAtFromPlusZTowardsTheOrigin) {
  using T = TypeParam;
  const Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  // forward = (0,0,-1), right = forward x up = (1,0,0), up = right x forward = (0,1,0): the
  // rotation is the identity and the view is a translation by (0,0,-5). All values are exact.
  Mat4<T> expected = Mat4<T>::Identity();
  expected(2, 3) = -5;
  EXPECT_TRUE(closeTo(view, expected, 0));
  EXPECT_TRUE(closeTo(transformPoint(view, Vec3<T>::Zero()), v3<T>(0, 0, -5), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 0, 5)), Vec3<T>::Zero(), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(1, 0, 0)), v3<T>(1, 0, -5), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 1, 0)), v3<T>(0, 1, -5), 0));
}

TYPED_TEST(Camera, LookAtAlongPlusX) {
  using T = TypeParam;
  const Mat4<T> view = lookAt(Vec3<T>::Zero(), v3<T>(1, 0, 0), v3<T>(0, 1, 0));
  // forward = +x, right = x cross y = +z, up = z cross x = +y; all exact.
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(2, 0, 0)), v3<T>(0, 0, -2), 0));  // ahead
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 0, 1)), v3<T>(1, 0, 0), 0));   // right
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 1, 0)), v3<T>(0, 1, 0), 0));   // up
}

TYPED_TEST(Camera, LookAtGeneralCamera) {
  using T = TypeParam;
  const Vec3<T> eye = v3<T>(1, 2, 3), target = v3<T>(4, 6, 3);
  // forward = (3,4,0)/5 = (0.6,0.8,0); right = forward x y = (0,0,0.6) -> (0,0,1);
  // up = right x forward = (-0.8, 0.6, 0). The target is 5 ahead.
  const Mat4<T> view = lookAt(eye, target, Vec3<T>::UnitY());
  // Values up to 6 (ulp 4 eps) through a 3-term dot and a translation, with 0.6 and 0.8
  // themselves rounded: a few ulp, 32 eps.
  const double tol = 32 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(view, target), v3<T>(0, 0, -5), tol));
  EXPECT_TRUE(closeTo(transformPoint(view, eye), Vec3<T>::Zero(), tol));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(1, 2, 4)), v3<T>(1, 0, 0), tol));  // eye + right
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0.2, 2.6, 3)), v3<T>(0, 1, 0), tol));  // + up
  // Rotation part orthonormal with det 1 (entries <= 1, a few roundings: 8 eps).
  const Mat3<T> r = view.template topLeftCorner<3, 3>();
  EXPECT_TRUE(closeTo(r * r.transpose(), Mat3<T>::Identity(), 8 * kEps<T>));
  EXPECT_TRUE(closeTo(r.determinant(), T(1), 8 * kEps<T>));
  // up need not be unit nor perpendicular to the view direction: only its plane matters. Same
  // matrix up to the roundings of normalising a different vector: tol as above.
  EXPECT_TRUE(closeTo(lookAt(eye, target, v3<T>(0, 7, 0)), view, tol));
  EXPECT_TRUE(closeTo(lookAt(eye, target, v3<T>(0.2, 1, 0)), view, tol));
  // Any Eigen expression is accepted.
  EXPECT_TRUE(closeTo(lookAt(eye, eye + v3<T>(3, 4, 0), 2 * Vec3<T>::UnitY()), view, tol));
}

TYPED_TEST(Camera, LookAtRejectsBadInput) {
  using T = TypeParam;
  const Vec3<T> eye = v3<T>(0, 0, 5), o = Vec3<T>::Zero(), y = Vec3<T>::UnitY();
  EXPECT_THROW(lookAt(eye, eye, y), Error);                   // eye == target
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 0, 1)), Error);        // up parallel to view
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 0, -3)), Error);       // up anti-parallel
  EXPECT_THROW(lookAt(eye, o, Vec3<T>::Zero()), Error);       // no up
  EXPECT_THROW(lookAt(v3<T>(kNaN<T>, 0, 5), o, y), Error);    // non-finite eye
  EXPECT_THROW(lookAt(eye, v3<T>(0, kInf<T>, 0), y), Error);  // non-finite target
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 1, kNaN<T>)), Error);  // non-finite up
  try {
    lookAt(eye, eye, y);
    ADD_FAILURE() << "lookAt(eye, eye, up) did not throw";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "lookAt: eye and target coincide");
  }
}

TYPED_TEST(Camera, PerspectiveHandWorked) {
  using T = TypeParam;
  // fovY = 90 deg: cot(45 deg) = 1. aspect 2, near 1, far 10:
  // m00 = 1/2, m11 = 1, m22 = far/(near-far) = -10/9, m23 = -near far/(far-near) = -10/9,
  // m32 = -1.
  const Mat4<T> p = perspective(kPi<T> / 2, T(2), T(1), T(10));
  Mat4<T> expected = Mat4<T>::Zero();
  expected(0, 0) = 0.5;
  expected(1, 1) = 1;
  expected(2, 2) = T(-10) / 9;
  expected(2, 3) = T(-10) / 9;
  expected(3, 2) = -1;
  // tan(pi/4) within an ulp or two, 10/9 rounded: entries <= 1.2 within 4 eps.
  EXPECT_TRUE(closeTo(p, expected, 4 * kEps<T>));

  // Near plane -> depth 0. z = m22 (-1) + m23 with m23 = 1 * m22: exact cancellation, unless the
  // compiler fuses a multiply-add, which leaves the rounding error of m22 (<= eps): 2 eps.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -1)), v3<T>(0, 0, 0), 2 * kEps<T>));
  // Far plane -> depth 1: z = (10/9) 10 - 10/9 = 10, w = 10. Roundings on values ~11 (ulp 8 eps)
  // divided by 10: 8 eps.
  const double tol = 8 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -10)), v3<T>(0, 0, 1), tol));
  // In between, depth = far (d - near) / (d (far - near)) at distance d = 2: 10/18 = 5/9.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -2)), v3<T>(0, 0, T(5) / 9), tol));
  // The frustum corners: at distance d the half-height is d tan(45 deg) = d and the half-width
  // 2d, so (2,1,-1) is the top-right near corner and (-20,-10,-10) the bottom-left far one.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(2, 1, -1)), v3<T>(1, 1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(20, 10, -10)), v3<T>(1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(-20, -10, -10)), v3<T>(-1, -1, 1), tol));
  // fovY = 60 deg: m11 = cot(30 deg) = sqrt3; within a few ulp of 1.7 (eps each): 8 eps.
  EXPECT_TRUE(closeTo(perspective(kPi<T> / 3, T(1), T(1), T(10))(1, 1), std::sqrt(T(3)), tol));
}

TYPED_TEST(Camera, PerspectiveRejectsBadInput) {
  using T = TypeParam;
  const T fov = T(1);
  for (const T bad : {T(0), T(-0.1), kPi<T>, T(4), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(bad, T(1), T(1), T(10)), Error) << "fovY " << bad;
  for (const T bad : {T(0), T(-1), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(fov, bad, T(1), T(10)), Error) << "aspect " << bad;
  for (const T bad : {T(0), T(-1), kNaN<T>})
    EXPECT_THROW(perspective(fov, T(1), bad, T(10)), Error) << "near " << bad;
  for (const T bad : {T(1), T(0.5), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(fov, T(1), T(1), bad), Error) << "far " << bad;
}

TYPED_TEST(Camera, OrthographicHandWorked) {
  using T = TypeParam;
  // Box x in [-2,4], y in [-1,3], view z in [-5,-1] (near 1, far 5):
  // m00 = 2/6, m03 = -(4-2)/6; m11 = 2/4, m13 = -(3-1)/4; m22 = -1/4, m23 = -1/4.
  const Mat4<T> o = orthographic(T(-2), T(4), T(-1), T(3), T(1), T(5));
  Mat4<T> expected = Mat4<T>::Identity();
  expected(0, 0) = T(1) / 3;
  expected(0, 3) = T(-1) / 3;
  expected(1, 1) = 0.5;
  expected(1, 3) = -0.5;
  expected(2, 2) = -0.25;
  expected(2, 3) = -0.25;
  // Entries <= 1 with one or two roundings: 4 eps; mapped points up to 4 through a 2-term sum:
  // 8 eps.
  EXPECT_TRUE(closeTo(o, expected, 4 * kEps<T>));
  const double tol = 8 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(-2, -1, -1)), v3<T>(-1, -1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(4, 3, -5)), v3<T>(1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(-2, 3, -5)), v3<T>(-1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(4, -1, -1)), v3<T>(1, -1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(1, 1, -3)), v3<T>(0, 0, 0.5), tol));  // centre
  // A negative near plane is allowed (the box reaches behind the camera): z = +5 -> 0, -5 -> 1.
  const Mat4<T> around = orthographic(T(-1), T(1), T(-1), T(1), T(-5), T(5));
  EXPECT_TRUE(closeTo(transformPoint(around, v3<T>(0, 0, 5)), v3<T>(0, 0, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(around, v3<T>(0, 0, -5)), v3<T>(0, 0, 1), tol));
}

TYPED_TEST(Camera, OrthographicRejectsEmptyRanges) {
  using T = TypeParam;
  const T a = T(-1), b = T(1);
  EXPECT_THROW(orthographic(b, b, a, b, a, b), Error);  // right == left
  EXPECT_THROW(orthographic(b, a, a, b, a, b), Error);  // right < left
  EXPECT_THROW(orthographic(a, b, b, b, a, b), Error);  // top == bottom
  EXPECT_THROW(orthographic(a, b, b, a, a, b), Error);  // top < bottom
  EXPECT_THROW(orthographic(a, b, a, b, b, b), Error);  // far == near
  EXPECT_THROW(orthographic(a, b, a, b, b, a), Error);  // far < near
  EXPECT_THROW(orthographic(kNaN<T>, b, a, b, a, b), Error);
  EXPECT_THROW(orthographic(a, kInf<T>, a, b, a, b), Error);
  EXPECT_THROW(orthographic(a, b, a, b, a, kNaN<T>), Error);
}

// ---------------------------------------------------------------------------------------------
// Picking

// The camera of the picking tests: at (0,0,5) looking at the origin, fovY 90 deg, aspect 4/3,
// near 1, far 10, in an 800 x 600 viewport whose top-left corner is at pixel (100, 50).
template <class T>
struct PickingScene {
  Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  Mat4<T> proj = perspective(kPi<T> / 2, T(4) / 3, T(1), T(10));
  Vec4<T> viewport = v4<T>(100, 50, 800, 600);
  Mat4<T> inverse = (proj * view).inverse();
};

// World values up to ~14 go through the inverse of proj * view (condition ~ far/near = 10) and
// a divide by w: about 10 * 14 * eps of error; 256 eps.
template <class T>
constexpr double kPickTol = 256 * kEps<T>;

TYPED_TEST(Picking, UnprojectHandWorked) {
  using T = TypeParam;
  const PickingScene<T> s;
  const double tol = kPickTol<T>;
  // The viewport centre (100 + 400, 50 + 300) is on the view axis: at depth 0 the near plane
  // (1 ahead of the eye: z = 4), at depth 1 the far plane (10 ahead: z = -5).
  EXPECT_TRUE(closeTo(unproject(v3<T>(500, 350, 0), s.viewport, s.inverse), v3<T>(0, 0, 4), tol));
  EXPECT_TRUE(closeTo(unproject(v3<T>(500, 350, 1), s.viewport, s.inverse), v3<T>(0, 0, -5), tol));
  // The viewport's top-left corner is the near plane's top-left corner: half-height
  // 1 tan(45 deg) = 1, half-width 4/3, so view (-4/3, 1, -1) = world (-4/3, 1, 4).
  EXPECT_TRUE(
      closeTo(unproject(v3<T>(100, 50, 0), s.viewport, s.inverse), v3<T>(-4.0 / 3, 1, 4), tol));
  // The bottom-right corner on the far plane: view (40/3, -10, -10) = world (40/3, -10, -5).
  EXPECT_TRUE(
      closeTo(unproject(v3<T>(900, 650, 1), s.viewport, s.inverse), v3<T>(40.0 / 3, -10, -5), tol));
}

TYPED_TEST(Picking, UnprojectInvertsProjection) {
  using T = TypeParam;
  const PickingScene<T> s;
  const Mat4<T> viewProj = s.proj * s.view;
  for (const Vec3<T>& world : {v3<T>(0.3, -0.2, 1), v3<T>(2, 1, -3), v3<T>(-5, -3, -4)}) {
    const Vec3<T> ndc = transformPoint(viewProj, world);
    // The window mapping of docs/conventions.md: x right from the viewport's left edge, y down
    // from its top edge, depth as is.
    const Vec3<T> window(s.viewport[0] + (ndc.x() + 1) / 2 * s.viewport[2],
                         s.viewport[1] + (1 - ndc.y()) / 2 * s.viewport[3], ndc.z());
    EXPECT_TRUE(closeTo(unproject(window, s.viewport, s.inverse), world, kPickTol<T>));
  }
}

TYPED_TEST(Picking, ScreenRayThroughTheCentrePixelIsTheViewAxis) {
  using T = TypeParam;
  // A 101 x 51 viewport: the centre pixel is (50, 25), its centre at (50.5, 25.5).
  const Vec4<T> viewport = v4<T>(0, 0, 101, 51);
  const Vec3<T> eye = v3<T>(1, 2, 3);
  const Mat4<T> view = lookAt(eye, v3<T>(4, 6, 3), Vec3<T>::UnitY());
  const Mat4<T> proj = perspective(T(1), T(101) / 51, T(0.5), T(50));
  const ScreenRay<T> ray = screenToRay(T(50.5), T(25.5), viewport, view, proj);
  // The view direction is (3,4,0)/5; the origin is half a unit along it from the eye.
  // The inverse of proj * view has a condition of about far/near = 100, so unprojected points
  // carry ~100 eps relative error: ~400 eps on the origin (magnitude ~4) and ~5000 eps on the
  // far point (magnitude ~50), which over the ray's length of ~50 tilts the direction by
  // ~100 eps. 512 eps for both.
  const double tol = 512 * kEps<T>;
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(1.3, 2.4, 3), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0.6, 0.8, 0), tol));
  EXPECT_TRUE(closeTo(ray.direction.norm(), T(1), 4 * kEps<T>));  // normalised: an ulp or two
}

TYPED_TEST(Picking, ScreenRayThroughACorner) {
  using T = TypeParam;
  // Camera at the origin looking down -z, fovY 90 deg, aspect 2, near 1: the window point (0,0)
  // (top-left corner of the 200 x 100 viewport) is the near-plane corner (-2, 1, -1).
  const Mat4<T> proj = perspective(kPi<T> / 2, T(2), T(1), T(100));
  const ScreenRay<T> ray =
      screenToRay(T(0), T(0), v4<T>(0, 0, 200, 100), Mat4<T>::Identity(), proj);
  // Far/near = 100 as above, values up to ~2 at the origin: 512 eps.
  const double tol = 512 * kEps<T>;
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(-2, 1, -1), tol));
  EXPECT_TRUE(closeTo(ray.direction, Vec3<T>(v3<T>(-2, 1, -1) / std::sqrt(T(6))), tol));
}

TYPED_TEST(Picking, ScreenRayOrthographic) {
  using T = TypeParam;
  // Camera at (0,0,5) looking at the origin; the box x in [-4,4], y in [-3,3], near 1, far 9,
  // shown in an 80 x 60 viewport: one pixel is 0.1 world units, every ray points along -z.
  const Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  const Mat4<T> proj = orthographic(T(-4), T(4), T(-3), T(3), T(1), T(9));
  const Vec4<T> viewport = v4<T>(0, 0, 80, 60);
  // Values up to ~5 through a well-conditioned inverse: 64 eps.
  const double tol = 64 * kEps<T>;
  // Window (0,0): top-left corner, view (-4, 3, -1) = world (-4, 3, 4).
  ScreenRay<T> ray = screenToRay(T(0), T(0), viewport, view, proj);
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(-4, 3, 4), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0, 0, -1), tol));
  // Window (60, 15): NDC (2*60/80 - 1, 1 - 2*15/60) = (0.5, 0.5), view (2, 1.5, -1).
  ray = screenToRay(T(60), T(15), viewport, view, proj);
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(2, 1.5, 4), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0, 0, -1), tol));
}

TYPED_TEST(Picking, RejectsBadInput) {
  using T = TypeParam;
  const PickingScene<T> s;
  const Vec3<T> w = v3<T>(500, 350, 0);
  EXPECT_THROW(unproject(w, v4<T>(0, 0, 0, 600), s.inverse), Error);   // zero width
  EXPECT_THROW(unproject(w, v4<T>(0, 0, 800, -1), s.inverse), Error);  // negative height
  EXPECT_THROW(unproject(w, v4<T>(kNaN<T>, 0, 800, 600), s.inverse), Error);
  EXPECT_THROW(screenToRay(T(1), T(1), v4<T>(0, 0, 800, 0), s.view, s.proj), Error);
  EXPECT_THROW(screenToRay(kNaN<T>, T(1), s.viewport, s.view, s.proj), Error);
  EXPECT_THROW(screenToRay(T(1), T(1), s.viewport, s.view, Mat4<T>::Zero()), Error);  // singular
}

// ---------------------------------------------------------------------------------------------
// Vector helpers

TYPED_TEST(Vectors, ProjectAndRejectHandWorked) {
  using T = TypeParam;
  // Every value here is a small dyadic rational, computed with a dot, a divide and a product
  // that are exact or within an ulp of values <= 4 (2 eps): 4 eps.
  const double tol = 4 * kEps<T>;
  // onto = (2,0,0) (not unit): the x part.
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(2, 0, 0)), v3<T>(3, 0, 0), tol));
  EXPECT_TRUE(closeTo(reject(v3<T>(3, 4, 0), v3<T>(2, 0, 0)), v3<T>(0, 4, 0), tol));
  // onto = (1,1,0): a.b = 7, |b|^2 = 2 -> 3.5 (1,1,0).
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(1, 1, 0)), v3<T>(3.5, 3.5, 0), tol));
  EXPECT_TRUE(closeTo(reject(v3<T>(3, 4, 0), v3<T>(1, 1, 0)), v3<T>(-0.5, 0.5, 0), tol));
  // 2D: (1,2) onto (1,1): 3/2 (1,1); the rest (-1/2, 1/2).
  EXPECT_TRUE(closeTo(project(v2<T>(1, 2), v2<T>(1, 1)), v2<T>(1.5, 1.5), tol));
  EXPECT_TRUE(closeTo(reject(v2<T>(1, 2), v2<T>(1, 1)), v2<T>(-0.5, 0.5), tol));
  // Directions of extreme magnitude: 1e-30 squared underflows in float, 1e30 squared
  // overflows, so a . b / |b|^2 would give NaN; rescaling keeps the exact answer.
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(1e-30, 0, 0)), v3<T>(3, 0, 0), tol));
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(0, 1e30, 0)), v3<T>(0, 4, 0), tol));
}

TYPED_TEST(Vectors, ProjectPlusRejectIsTheOriginal) {
  using T = TypeParam;
  const std::vector<Vec3<T>> vs = {v3<T>(1, 2, 3), v3<T>(-4, 0.5, 2), v3<T>(0.1, -7, 0.3)};
  for (const Vec3<T>& a : vs) {
    for (const Vec3<T>& b : vs) {
      // Components up to ~7 (ulp 4 eps) after a few roundings each: 32 eps.
      const double tol = 32 * kEps<T>;
      EXPECT_TRUE(closeTo(Vec3<T>(project(a, b) + reject(a, b)), a, tol));
      // The rejection is perpendicular to b: |reject . b| <= tol * |b|_1 (|b|_1 <= 7.4).
      EXPECT_TRUE(closeTo(reject(a, b).dot(b), T(0), tol * 8));
    }
  }
}

TYPED_TEST(Vectors, ReflectHandWorked) {
  using T = TypeParam;
  // Exact small values: 4 eps.
  const double tol = 4 * kEps<T>;
  // Bounce off the floor; the normal (0,2,0) is not unit: (1,-1,0) -> (1,1,0).
  EXPECT_TRUE(closeTo(reflect(v3<T>(1, -1, 0), v3<T>(0, 2, 0)), v3<T>(1, 1, 0), tol));
  // 2D: mirror in the line y = -x (normal (1,1)): (1,0) - 2 (1/2) (1,1) = (0,-1).
  EXPECT_TRUE(closeTo(reflect(v2<T>(1, 0), v2<T>(1, 1)), v2<T>(0, -1), tol));
  // Twice is the identity and the length is kept: values ~3, a few roundings: 16 eps.
  const Vec3<T> v = v3<T>(0.3, -2, 1.7), n = v3<T>(1, 2, -0.5);
  EXPECT_TRUE(closeTo(reflect(reflect(v, n), n), v, 16 * kEps<T>));
  EXPECT_TRUE(closeTo(reflect(v, n).norm(), v.norm(), 16 * kEps<T>));
}

TYPED_TEST(Vectors, ProjectRejectReflectRejectZeroDirections) {
  using T = TypeParam;
  const Vec3<T> a = v3<T>(1, 2, 3);
  EXPECT_THROW(project(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(reject(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(reflect(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(project(a, v3<T>(kNaN<T>, 1, 0)), Error);
  EXPECT_THROW(reflect(a, v3<T>(0, kInf<T>, 0)), Error);
  EXPECT_THROW(project(v2<T>(1, 2), Vec2<T>::Zero()), Error);
}

TYPED_TEST(Vectors, AngleBetweenHandWorked) {
  using T = TypeParam;
  // atan2 within an ulp, of exact or once-rounded arguments; angles <= pi (ulp 2 eps): 4 eps.
  const double tol = 4 * kEps<T>;
  const Vec3<T> x = Vec3<T>::UnitX();
  EXPECT_TRUE(closeTo(angleBetween(x, Vec3<T>::UnitY()), kPi<T> / 2, tol));
  EXPECT_TRUE(closeTo(angleBetween(x, Vec3<T>(-x)), kPi<T>, tol));
  EXPECT_TRUE(closeTo(angleBetween(x, x), T(0), tol));
  EXPECT_TRUE(closeTo(angleBetween(x, v3<T>(1, 1, 0)), kPi<T> / 4, tol));
  EXPECT_TRUE(closeTo(angleBetween(v2<T>(1, 0), v2<T>(0, -1)), kPi<T> / 2, tol));  // unsigned
  EXPECT_TRUE(closeTo(angleBetween(v2<T>(2, 0), v2<T>(-1, -1)), 3 * kPi<T> / 4, tol));
  // Extreme magnitudes: |a|^2 overflows (1e30) or underflows (1e-30) in float.
  EXPECT_TRUE(closeTo(angleBetween(v3<T>(1e30, 0, 0), v3<T>(1e30, 1e30, 0)), kPi<T> / 4, tol));
  EXPECT_TRUE(closeTo(angleBetween(v3<T>(1e-30, 0, 0), v3<T>(0, 0, 1e-30)), kPi<T> / 2, tol));
}

TYPED_TEST(Vectors, AngleBetweenNearlyParallelVectors) {
  using T = TypeParam;
  // a = (1,0,0) and b = (1,t,0) with t = 1e-4 (as stored in T) are exactly atan(t) apart,
  // 1e-4 - 1e-12/3. a x b = (0,0,t) and a . b = 1 are exact, so atan2 gives the answer within
  // an ulp or two: relative tolerance 4 eps, i.e. 4 eps * 1e-4.
  const T t = T(1e-4);
  const double exact = static_cast<double>(std::atan(static_cast<long double>(t)));
  const double tol = 4 * kEps<T> * exact;
  const Vec3<T> a = Vec3<T>::UnitX(), b = v3<T>(1, t, 0);
  EXPECT_TRUE(closeTo(angleBetween(a, b), T(exact), tol));
  // The same near pi: (1,0,0) and (-1,t,0) are pi - atan(t) apart (an ulp of pi is 2 eps).
  EXPECT_TRUE(closeTo(angleBetween(a, v3<T>(-1, t, 0)), T(std::numbers::pi - exact), 2 * kEps<T>));
  // acos(a . b / |a||b|) fails here: in float |b| = sqrt(1 + 1e-8) rounds to 1 and acos gives 0;
  // in double the rounding of the cosine (~1e-16) is amplified by 1/sin(angle) = 1e4.
  const T viaAcos = std::acos(a.dot(b) / (a.norm() * b.norm()));
  EXPECT_FALSE(closeTo(viaAcos, T(exact), tol));
}

TYPED_TEST(Vectors, AngleBetweenRejectsZeroAndNonFinite) {
  using T = TypeParam;
  EXPECT_THROW(angleBetween(Vec3<T>::Zero(), Vec3<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(Vec3<T>::UnitX(), Vec3<T>::Zero()), Error);
  EXPECT_THROW(angleBetween(Vec2<T>::Zero(), Vec2<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(v3<T>(kNaN<T>, 0, 0), Vec3<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(Vec3<T>::UnitX(), v3<T>(0, kInf<T>, 0)), Error);
}

// ---------------------------------------------------------------------------------------------
// Tolerant comparison

TYPED_TEST(Compare, ScalarsFollowTheBooksRule) {
  using T = TypeParam;
  const T eps = kEps<T>;
  // Defaults: |a - b| <= eps * max(1, |a|, |b|).
  EXPECT_TRUE(nearlyEqual(T(1), T(1) + eps));       // one ulp of 1
  EXPECT_FALSE(nearlyEqual(T(1), T(1) + 4 * eps));  // four ulp
  // Relative for large values: one ulp of 1000 is 512 eps <= 1000 eps; four are 2048 eps.
  const T k = T(1000);
  EXPECT_TRUE(nearlyEqual(k, std::nextafter(k, kInf<T>)));
  EXPECT_FALSE(nearlyEqual(k, k + 4 * 512 * eps));
  // Absolute near zero.
  EXPECT_TRUE(nearlyEqual(T(0), eps / 2));
  EXPECT_TRUE(nearlyEqual(eps / 4, -eps / 4));
  EXPECT_FALSE(nearlyEqual(T(0), T(1e-3)));
  // Explicit tolerances: 1% of 101 is 1.01 >= |100 - 101|, but < |100 - 102|.
  EXPECT_TRUE(nearlyEqual(T(100), T(101), T(0.01), T(0)));
  EXPECT_FALSE(nearlyEqual(T(100), T(102), T(0.01), T(0)));
  EXPECT_TRUE(nearlyEqual(T(0), T(0.5), T(0), T(0.5)));
  // Special values.
  EXPECT_FALSE(nearlyEqual(kNaN<T>, kNaN<T>));
  EXPECT_FALSE(nearlyEqual(T(1), kNaN<T>));
  EXPECT_TRUE(nearlyEqual(kInf<T>, kInf<T>));
  EXPECT_FALSE(nearlyEqual(kInf<T>, -kInf<T>));
  EXPECT_FALSE(nearlyEqual(std::numeric_limits<T>::max(), kInf<T>));
}

TYPED_TEST(Compare, VectorsCompareByNorm) {
  using T = TypeParam;
  // Norm-based: (1, 1e-9) and (1, 2e-9) differ by 1e-9 against a norm of 1, within relTol 1e-6;
  // compared component by component with a purely relative tolerance they would differ by 50%.
  EXPECT_TRUE(nearlyEqual(v2<T>(1, 1e-9), v2<T>(1, 2e-9), T(1e-6), T(0)));
  EXPECT_FALSE(nearlyEqual(v2<T>(1, 0), v2<T>(1, 1e-3), T(1e-6), T(0)));
  // Defaults as for scalars: 1 ulp of 1 in one component passes, 4 ulp fail.
  EXPECT_TRUE(nearlyEqual(v3<T>(1, 0, 0), Vec3<T>(v3<T>(1, 0, 0) + v3<T>(kEps<T>, 0, 0))));
  EXPECT_FALSE(nearlyEqual(v3<T>(1, 0, 0), Vec3<T>(v3<T>(1, 0, 0) + v3<T>(0, 4 * kEps<T>, 0))));
  // Matrices use the Frobenius norm (sqrt(3) for the 3x3 identity).
  Mat3<T> m = Mat3<T>::Identity();
  m(0, 1) = T(1e-3);
  EXPECT_TRUE(nearlyEqual(m, Mat3<T>::Identity(), T(1e-3)));
  EXPECT_FALSE(nearlyEqual(m, Mat3<T>::Identity(), T(1e-4)));
  EXPECT_FALSE(nearlyEqual(v2<T>(kNaN<T>, 0), v2<T>(kNaN<T>, 0)));
  EXPECT_TRUE(nearlyEqual(v2<T>(kInf<T>, 0), v2<T>(kInf<T>, 0)));
  EXPECT_FALSE(nearlyEqual(v2<T>(kInf<T>, 0), v2<T>(1, 0)));
}

}  // namespace
}  // namespace simdphys

// Tests of include/simdphys/math.hpp (types, minors and cofactors, rotations, transforms), in float
// and in double. Every expected value is worked by hand (the derivation is in the comment beside
// it); every tolerance says why it is what it is.
// "eps" is the machine epsilon of the scalar type: 1.19e-7 (float), 2.22e-16 (double); an ulp of
// a value in [2^k, 2^(k+1)) is 2^k eps.
#include "math_cases.hpp"

namespace simdphys {
namespace {

using namespace test;

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

}  // namespace
}  // namespace simdphys

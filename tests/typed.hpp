// Helpers of the suites typed over the scalar (float and double): the type list, its names, the
// vector builders and the tolerance assertions.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>

#include "simdphys/math.hpp"

namespace simdphys::test {

using Scalars = ::testing::Types<float, double>;

struct ScalarName {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};

template <class T>
Vec2<T> v2(double x, double y) {
  return Vec2<T>(T(x), T(y));
}
template <class T>
Vec3<T> v3(double x, double y, double z) {
  return Vec3<T>(T(x), T(y), T(z));
}
template <class T>
Vec4<T> v4(double x, double y, double z, double w) {
  return Vec4<T>(T(x), T(y), T(z), T(w));
}

// Largest absolute component difference (computed in double) <= tol; prints both sides if not.
template <class DA, class DB>
::testing::AssertionResult closeTo(const Eigen::MatrixBase<DA>& actual,
                                   const Eigen::MatrixBase<DB>& expected, double tol) {
  const double err =
      (actual.template cast<double>() - expected.template cast<double>()).cwiseAbs().maxCoeff();
  if (err <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "max |difference| " << err << " > tolerance " << tol << "\nactual:\n"
         << actual << "\nexpected:\n"
         << expected;
}

inline ::testing::AssertionResult closeTo(double actual, double expected, double tol) {
  const double err = std::abs(actual - expected);
  if (err <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "|" << actual << " - " << expected << "| = " << err << " > tolerance " << tol;
}

}  // namespace simdphys::test

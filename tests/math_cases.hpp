// Shared by the suites of include/simdphys/math.hpp (math_test.cpp, math_camera_test.cpp): the
// constants and fixtures of their tests, typed over float and double.
#pragma once

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "simdphys/math.hpp"
#include "typed.hpp"

#include <cmath>
#include <concepts>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace simdphys::test {

template <class T>
constexpr T kEps = std::numeric_limits<T>::epsilon();
template <class T>
constexpr T kPi = std::numbers::pi_v<T>;
template <class T>
constexpr T kNaN = std::numeric_limits<T>::quiet_NaN();
template <class T>
constexpr T kInf = std::numeric_limits<T>::infinity();

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

}  // namespace simdphys::test

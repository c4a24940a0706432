// Shared by the point, intersection and random-input suites of include/simdphys/geometry3d/
// (geometry3d_point_test.cpp, geometry3d_intersect_test.cpp, geometry3d_random_test.cpp): their
// fixtures, tolerances and the hand-built shapes they share. Tolerances: see
// geometry3d_point_test.cpp.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "expect_error.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "typed.hpp"
#include "workloads/workloads.hpp"

namespace simdphys::test {

template <class T>
constexpr double kEps = std::numeric_limits<T>::epsilon();
template <class T>
constexpr double kTol = double(kGeometryTolerance<T>);

template <class T>
class PointTests : public ::testing::Test {};
template <class T>
class SegmentPairs : public ::testing::Test {};
template <class T>
class Intersects : public ::testing::Test {};
template <class T>
class HardCases : public ::testing::Test {};
template <class T>
class Properties : public ::testing::Test {};
TYPED_TEST_SUITE(PointTests, Scalars, ScalarName);
TYPED_TEST_SUITE(SegmentPairs, Scalars, ScalarName);
TYPED_TEST_SUITE(Intersects, Scalars, ScalarName);
TYPED_TEST_SUITE(HardCases, Scalars, ScalarName);
TYPED_TEST_SUITE(Properties, Scalars, ScalarName);

// Both argument orders give `expected` (and so agree with each other); a failure names the
// arguments and both answers. A predicate function rather than two EXPECT_EQs expanded at each of
// the ~190 uses: that expansion, instrumented by the sanitizers, was most of this suite's build.
template <class A, class B>
::testing::AssertionResult intersectsBothWays(const char* ea, const char* eb, const char*,
                                              const A& a, const B& b, bool expected) {
  const bool ab = intersects(a, b), ba = intersects(b, a);
  if (ab == expected && ba == expected) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "expected " << expected << ": intersects(" << ea << ", " << eb << ") = " << ab
         << ", intersects(" << eb << ", " << ea << ") = " << ba;
}
#define EXPECT_INTERSECTS(a, b, expected) \
  EXPECT_PRED_FORMAT3(::simdphys::test::intersectsBothWays, a, b, expected)

// Rotation matrices with exact entries: a quarter turn about z (columns (0,1,0), (-1,0,0), z)
// and the 3-4-5 rotation about z (columns (0.6,0.8,0), (-0.8,0.6,0), z; 0.6 and 0.8 round).
template <class T>
Mat3<T> quarterTurnZ() {
  Mat3<T> m;
  m << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return m;
}
template <class T>
Mat3<T> rotation345() {
  Mat3<T> m;
  m << T(0.6), T(-0.8), 0, T(0.8), T(0.6), 0, 0, 0, 1;
  return m;
}

template <class T>
ObbT<T> cubeObb(const Vec3<T>& center, T half, const Mat3<T>& axes = Mat3<T>::Identity()) {
  return {center, Vec3<T>::Constant(half), axes};
}

// The unit cube [-1, 1]^3 and a cube of half size 1 standing on one of its edges so that this
// "ridge" edge, along u0 = (1,-1,0)/sqrt2, faces the cube's z edge through (1,1,0) across a gap
// g along w = (1,1,0)/sqrt2. Its other axes are u1 = (w + z)/sqrt2 = (1/2, 1/2, 1/sqrt2) and
// u2 = (z - w)/sqrt2 = (-1/2, -1/2, 1/sqrt2) (u0 x u1 = u2: right-handed). The ridge is the edge
// of support in direction -w: c - (u1 - u2) = c - sqrt2 w, so with c = (2 sqrt2 + g) w =
// (2 + g/sqrt2, 2 + g/sqrt2, 0) it lies on the plane w.p = sqrt2 + g, and the cube's z edge on
// w.p = sqrt2: the gap on the edge-edge axis z x u0 = w is g. Every other axis overlaps for
// g <= 1: on x, the ridge box spans 2 + g/sqrt2 -+ (1/sqrt2 + 1/2 + 1/2), min 1 + (g - 1)/sqrt2
// <= 1; on u1, the cube spans +-(1 + 1/sqrt2) and the ridge box 2 + g/sqrt2 -+ 1, min
// 1 + g/sqrt2 <= 1 + 1/sqrt2; u2 likewise; u0 and z contain both centers. So for 0 < g <= 1 the
// pair is separated by the edge-edge axis alone, touches for g = 0 (the ridge passes through
// (1,1,0)) and overlaps for g < 0.
template <class T>
ObbT<T> ridgeBox(double g) {
  const T r = T(1) / std::sqrt(T(2));
  Mat3<T> axes;
  axes.col(0) = Vec3<T>(r, -r, 0);
  axes.col(1) = Vec3<T>(T(0.5), T(0.5), r);
  axes.col(2) = Vec3<T>(T(-0.5), T(-0.5), r);
  const T c = T(2) + T(g) * r;
  return {Vec3<T>(c, c, 0), Vec3<T>::Constant(1), axes};
}

template <class T>
SegmentT<T> seg(const Vec3<T>& a, const Vec3<T>& b) {
  return {a, b};
}

}  // namespace simdphys::test

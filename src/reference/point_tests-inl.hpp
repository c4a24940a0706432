// The definitions of simdphys/point_tests.hpp (the point tests 2D and 3D share): included by the
// -inl.hpp of each dimension, whose point_tests.cpp instantiates them for its dimension.
#pragma once

#include <algorithm>

#include "simdphys/point_tests.hpp"

namespace simdphys {

namespace detail {

// The parameter in [0, 1] of the point of the segment from 0 to `d` closest to `r` (both relative
// to the segment's start); 0 for a zero-length segment (no division by zero).
template <class T, int N>
T segmentParameter(const VecN<T, N>& d, const NoDeduce<VecN<T, N>>& r) {
  const T dd = d.squaredNorm();
  if (!(dd > 0)) return T(0);
  return std::clamp(r.dot(d) / dd, T(0), T(1));
}

}  // namespace detail

template <class T, int N>
bool contains(const BoxN<T, N>& box, const detail::NoDeduce<VecN<T, N>>& point) {
  return (box.min.array() <= point.array()).all() && (point.array() <= box.max.array()).all();
}

template <class T, int N>
VecN<T, N> closestPoint(const SegmentN<T, N>& segment, const detail::NoDeduce<VecN<T, N>>& point) {
  const VecN<T, N> d = segment.end - segment.start;
  return segment.start + detail::segmentParameter<T>(d, point - segment.start) * d;
}

template <class T, int N>
VecN<T, N> closestPoint(const BallN<T, N>& ball, const detail::NoDeduce<VecN<T, N>>& point) {
  const VecN<T, N> offset = point - ball.center;
  const T distance = offset.norm();
  if (distance <= ball.radius) return point;
  return ball.center + offset * (ball.radius / distance);
}

template <class T, int N>
VecN<T, N> closestPoint(const BoxN<T, N>& box, const detail::NoDeduce<VecN<T, N>>& point) {
  return point.cwiseMax(box.min).cwiseMin(box.max);
}

}  // namespace simdphys

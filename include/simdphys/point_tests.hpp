// The point tests that are the same in 2D and 3D, on the shared primitives (primitives.hpp):
// containment in an axis-aligned box and the closest points of a segment, a ball and a box.
// geometry2d/point_tests.hpp and geometry3d/point_tests.hpp hold the rest, whose tolerances are
// per dimension. Compiled for float and double by the point_tests.cpp of each dimension.
#pragma once

#include "simdphys/primitives.hpp"

namespace simdphys {

// Closed box, exact: min <= p <= max on every axis (comparisons only, no rounding).
template <class T, int N>
bool contains(const BoxN<T, N>& box, const detail::NoDeduce<VecN<T, N>>& point);

// start + t (end - start), t the clamped projection parameter; the start for a zero-length one.
template <class T, int N>
VecN<T, N> closestPoint(const SegmentN<T, N>& segment, const detail::NoDeduce<VecN<T, N>>& point);

// The point of the solid ball closest to p: p itself when inside, else the boundary point towards
// p. A zero-radius ball gives its center. Never divides by zero (outside means |p - c| > r >= 0).
template <class T, int N>
VecN<T, N> closestPoint(const BallN<T, N>& ball, const detail::NoDeduce<VecN<T, N>>& point);

// p clamped to the box on each axis: exact.
template <class T, int N>
VecN<T, N> closestPoint(const BoxN<T, N>& box, const detail::NoDeduce<VecN<T, N>>& point);

}  // namespace simdphys

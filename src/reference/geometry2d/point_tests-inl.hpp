// The definitions of simdphys/geometry2d/point_tests.hpp (2D containment and closest points):
// included by point_tests.cpp, which instantiates them for float and double, and by any file of
// src/ that wants them inlined.
#pragma once

#include "simdphys/geometry2d/point_tests.hpp"
#include "src/reference/point_tests-inl.hpp"

namespace simdphys {

namespace detail::g2 {

// p in the local frame of an oriented rectangle: axes^T (p - center).
template <class T>
Vec2<T> toLocal(const OrientedRectT<T>& b, const Mat2<T>& axes, const Vec2<T>& p) {
  return axes.transpose() * (p - b.center);
}

}  // namespace detail::g2

template <class T>
bool contains(const Segment2T<T>& segment, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> d = segment.end - segment.start;
  const Vec2<T> r = point - segment.start;
  const T t = detail::segmentParameter(d, r);
  return (r - t * d).norm() <= kGeometry2dTolerance<T> * std::max(r.norm(), d.norm());
}

template <class T>
bool contains(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point) {
  const T distance = (point - circle.center).norm();
  return distance <= circle.radius + kGeometry2dTolerance<T> * std::max(distance, circle.radius);
}

template <class T>
bool contains(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> offset = point - box.center;
  const Vec2<T> local = box.axes().transpose() * offset;
  const T excess = (local.cwiseAbs() - box.halfExtents).maxCoeff();
  return excess <= kGeometry2dTolerance<T> * (offset.norm() + box.halfExtents.maxCoeff());
}

template <class T>
Vec2<T> closestPoint(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point) {
  const Mat2<T> axes = box.axes();
  const Vec2<T> local = detail::g2::toLocal(box, axes, point);
  const Vec2<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  if (clamped == local) return point;
  return box.center + axes * clamped;
}

}  // namespace simdphys

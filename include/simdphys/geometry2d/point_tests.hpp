// 2D point tests (the book's chapter 5, "point containment"): whether a shape contains a point
// and the point of a shape closest to a point. The tolerances mirror the 3D point tests: the
// axis-aligned rectangle is exact (comparisons only), the others allow
// kGeometry2dTolerance * scale with the scale stated per function.
//
// Where the book's code (Geometry2D.cpp) differs: PointOnLine compares the slope-intercept form
// y = mx + b, which divides by zero for vertical segments and tests the infinite line, not the
// segment; here a segment is a segment, at any angle. PointInCircle uses `<`, so a point on the
// circle is outside; here shapes are closed. Its closest points exist only for 3D shapes; here
// every 2D shape has one.
#pragma once

#include <algorithm>
#include <cmath>

#include "simdphys/geometry2d/primitives.hpp"

namespace simdphys {

namespace detail::g2 {

// The parameter in [0, 1] of the point of the segment from 0 to d closest to r (both relative to
// the segment's start); 0 for a zero-length segment.
template <class T>
T segmentParameter(const Vec2<T>& d, const Vec2<T>& r) {
  const T dd = d.squaredNorm();
  if (!(dd > 0)) return T(0);
  return std::clamp(r.dot(d) / dd, T(0), T(1));
}

// p in the local frame of an oriented rectangle: axes^T (p - center).
template <class T>
Vec2<T> toLocal(const OrientedRectT<T>& b, const Mat2<T>& axes, const Vec2<T>& p) {
  return axes.transpose() * (p - b.center);
}

}  // namespace detail::g2

// ---- containment ----------------------------------------------------------------------------

// On the segment: distance to it <= tolerance * max(|p - start|, length). A zero-length segment
// contains only its point.
template <class T>
bool contains(const Segment2T<T>& segment, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> d = segment.end - segment.start;
  const Vec2<T> r = point - segment.start;
  const T t = detail::g2::segmentParameter(d, r);
  return (r - t * d).norm() <= kGeometry2dTolerance<T> * std::max(r.norm(), d.norm());
}

// Closed disc: |p - c| <= r, within the tolerance times max(|p - c|, r). A zero-radius circle
// contains only its center.
template <class T>
bool contains(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point) {
  const T distance = (point - circle.center).norm();
  return distance <= circle.radius + kGeometry2dTolerance<T> * std::max(distance, circle.radius);
}

// Closed rectangle, exact: min <= p <= max on both axes.
template <class T>
bool contains(const RectT<T>& rect, const detail::NoDeduce<Vec2<T>>& point) {
  return (rect.min.array() <= point.array()).all() && (point.array() <= rect.max.array()).all();
}

// Closed oriented rectangle: |local| <= halfExtents on both axes, within the tolerance times
// |p - c| + the larger half extent (the rotation into the local frame rounds by about 2 eps |p -
// c|).
template <class T>
bool contains(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> offset = point - box.center;
  const Vec2<T> local = box.axes().transpose() * offset;
  const T excess = (local.cwiseAbs() - box.halfExtents).maxCoeff();
  return excess <= kGeometry2dTolerance<T> * (offset.norm() + box.halfExtents.maxCoeff());
}

// ---- closest points -------------------------------------------------------------------------

// start + t (end - start), t the clamped projection parameter; the start for a zero-length one.
template <class T>
Vec2<T> closestPoint(const Segment2T<T>& segment, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> d = segment.end - segment.start;
  return segment.start + detail::g2::segmentParameter<T>(d, point - segment.start) * d;
}

// The point of the solid disc closest to p: p itself when inside, else the boundary point towards
// p. Never divides by zero (outside means |p - c| > r >= 0).
template <class T>
Vec2<T> closestPoint(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point) {
  const Vec2<T> offset = point - circle.center;
  const T distance = offset.norm();
  if (distance <= circle.radius) return point;
  return circle.center + offset * (circle.radius / distance);
}

// p clamped to the rectangle on each axis: exact.
template <class T>
Vec2<T> closestPoint(const RectT<T>& rect, const detail::NoDeduce<Vec2<T>>& point) {
  return point.cwiseMax(rect.min).cwiseMin(rect.max);
}

// p clamped to the rectangle in its local frame; a point inside is returned unchanged (exactly).
template <class T>
Vec2<T> closestPoint(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point) {
  const Mat2<T> axes = box.axes();
  const Vec2<T> local = detail::g2::toLocal(box, axes, point);
  const Vec2<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  if (clamped == local) return point;
  return box.center + axes * clamped;
}

}  // namespace simdphys

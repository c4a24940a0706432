// The definitions of simdphys/geometry2d/line_tests.hpp (2D segment tests and raycasts): included
// by line_tests.cpp, which instantiates them for float and double, and by any file of src/ that
// wants them inlined.
#pragma once

#include "simdphys/geometry2d/line_tests.hpp"
#include "src/reference/geometry2d/point_tests-inl.hpp"

namespace simdphys {

namespace detail::g2 {

// Where the line 0 + t d, t in [0, tMax], first meets the axis-aligned box [lo, hi] (given
// relative to the line's origin) widened by `slack` on every side. `axis` is the slab entered
// last (the entered face), -1 when the origin is within the widened box.
template <class T>
struct SlabHit {
  T t;
  int axis;
  T sign;  // the entered face's outward normal is sign * e_axis
};

template <class T>
std::optional<SlabHit<T>> slabs(const Vec2<T>& d, const Vec2<T>& lo, const Vec2<T>& hi, T slack,
                                T tMax) {
  T tEnter = -std::numeric_limits<T>::infinity(), tExit = std::numeric_limits<T>::infinity();
  int axis = -1;
  for (int a = 0; a < 2; ++a) {
    const T low = lo[a] - slack, high = hi[a] + slack;
    if (d[a] == 0) {
      if (low > 0 || high < 0) return std::nullopt;  // outside this slab for every t
      continue;
    }
    T t1 = low / d[a], t2 = high / d[a];
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > tEnter) {
      tEnter = t1;
      axis = a;
    }
    tExit = std::min(tExit, t2);
  }
  if (tEnter > tExit || tExit < 0 || tEnter > tMax) return std::nullopt;
  if (tEnter <= 0) return SlabHit<T>{T(0), -1, T(0)};
  // The entered face itself (not the widened one), kept within the widened interval.
  const T face = d[axis] > 0 ? lo[axis] : hi[axis];
  const T t = std::clamp(face / d[axis], tEnter, tExit);
  return SlabHit<T>{t, axis, d[axis] > 0 ? T(-1) : T(1)};
}

// The widening of the slabs: the tolerance times the largest coordinate of the box relative to
// the origin (the subtractions and the rotation into a local frame round by a few eps of it).
template <class T>
T slabSlack(const Vec2<T>& lo, const Vec2<T>& hi) {
  return kGeometry2dTolerance<T> * lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).maxCoeff();
}

template <class T>
RayHit2T<T> insideHit(const Ray2T<T>& ray) {
  return {T(0), ray.origin, Vec2<T>(-ray.direction), true};
}

}  // namespace detail::g2

template <class T>
bool intersects(const Segment2T<T>& s, const CircleT<T>& c) {
  const Vec2<T> d = s.end - s.start, r = c.center - s.start;
  const T t = detail::segmentParameter(d, r);
  const T distance = (r - t * d).norm();
  return distance <= c.radius + kGeometry2dTolerance<T> * std::max({c.radius, r.norm(), d.norm()});
}

template <class T>
bool intersects(const Segment2T<T>& s, const RectT<T>& r) {
  const Vec2<T> lo = r.min - s.start, hi = r.max - s.start;
  return detail::g2::slabs<T>(s.end - s.start, lo, hi, detail::g2::slabSlack(lo, hi), T(1))
      .has_value();
}

template <class T>
bool intersects(const Segment2T<T>& s, const OrientedRectT<T>& b) {
  const Mat2<T> axes = b.axes();
  const Vec2<T> start = axes.transpose() * (s.start - b.center);
  const Vec2<T> d = axes.transpose() * (s.end - s.start);
  const Vec2<T> lo = -b.halfExtents - start, hi = b.halfExtents - start;
  return detail::g2::slabs<T>(d, lo, hi, detail::g2::slabSlack(lo, hi), T(1)).has_value();
}

template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const CircleT<T>& c) {
  if (contains(c, ray.origin)) return detail::g2::insideHit(ray);
  const Vec2<T> m = ray.origin - c.center;
  const T b = m.dot(ray.direction);
  if (b >= 0) return std::nullopt;                // outside and not moving towards the center
  const T miss = (m - b * ray.direction).norm();  // distance from the center to the line
  const T r = c.radius;
  if (miss > r + kGeometry2dTolerance<T> * (r + m.norm())) return std::nullopt;
  const T half = miss < r ? std::sqrt((r - miss) * (r + miss)) : T(0);
  const T t = std::max(T(0), -b - half);
  // A circle too small to have a direction at this distance (a point, at the resolution of m)
  // gets the inside convention's normal.
  const Vec2<T> outward = m + t * ray.direction;
  const T length = outward.norm();
  const Vec2<T> normal = length > kGeometry2dTolerance<T> * m.norm() ? Vec2<T>(outward / length)
                                                                     : Vec2<T>(-ray.direction);
  return RayHit2T<T>{t, ray.at(t), normal, false};
}

template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const RectT<T>& r) {
  const Vec2<T> lo = r.min - ray.origin, hi = r.max - ray.origin;
  const auto hit = detail::g2::slabs<T>(ray.direction, lo, hi, detail::g2::slabSlack(lo, hi),
                                        std::numeric_limits<T>::infinity());
  if (!hit) return std::nullopt;
  if (hit->axis < 0) return detail::g2::insideHit(ray);
  Vec2<T> normal = Vec2<T>::Zero();
  normal[hit->axis] = hit->sign;
  return RayHit2T<T>{hit->t, ray.at(hit->t), normal, false};
}

template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const OrientedRectT<T>& b) {
  const Mat2<T> axes = b.axes();
  const Vec2<T> origin = axes.transpose() * (ray.origin - b.center);
  const Vec2<T> d = axes.transpose() * ray.direction;
  const Vec2<T> lo = -b.halfExtents - origin, hi = b.halfExtents - origin;
  const auto hit = detail::g2::slabs<T>(d, lo, hi, detail::g2::slabSlack(lo, hi),
                                        std::numeric_limits<T>::infinity());
  if (!hit) return std::nullopt;
  if (hit->axis < 0) return detail::g2::insideHit(ray);
  return RayHit2T<T>{hit->t, ray.at(hit->t), hit->sign * axes.col(hit->axis), false};
}

}  // namespace simdphys

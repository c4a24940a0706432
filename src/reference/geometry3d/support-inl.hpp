// The definitions of simdphys/geometry3d/support.hpp (support functions of the primitives):
// included by support.cpp, which instantiates them for float and double, and by any file of src/
// that wants them inlined.
#pragma once

#include "simdphys/geometry3d/support.hpp"
#include "src/reference/math-inl.hpp"

namespace simdphys {

template <class T>
Vec3<T> support(const SphereT<T>& s, const detail::NoDeduce<Vec3<T>>& direction) {
  return s.center + s.radius * detail::unitOrZero<T>(direction);
}

template <class T>
Vec3<T> support(const AabbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction) {
  return Vec3<T>(direction[0] >= 0 ? b.max[0] : b.min[0], direction[1] >= 0 ? b.max[1] : b.min[1],
                 direction[2] >= 0 ? b.max[2] : b.min[2]);
}

template <class T>
Vec3<T> support(const ObbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction) {
  Vec3<T> p = b.center;
  for (int i = 0; i < 3; ++i) {
    const T h = b.axes.col(i).dot(direction) >= 0 ? b.halfExtents[i] : -b.halfExtents[i];
    p += h * b.axes.col(i);
  }
  return p;
}

template <class T>
Vec3<T> support(const TriangleT<T>& t, const detail::NoDeduce<Vec3<T>>& direction) {
  const T da = t.a.dot(direction), db = t.b.dot(direction), dc = t.c.dot(direction);
  if (da >= db && da >= dc) return t.a;
  return db >= dc ? t.b : t.c;
}

template <class T>
Vec3<T> support(const SegmentT<T>& s, const detail::NoDeduce<Vec3<T>>& direction) {
  return s.start.dot(direction) >= s.end.dot(direction) ? s.start : s.end;
}

template <class T>
Vec3<T> support(const ConvexHullT<T>& h, const detail::NoDeduce<Vec3<T>>& direction) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  std::size_t best = 0;
  T bestDot = h.points[0].dot(direction);
  for (std::size_t i = 1; i < h.points.size(); ++i) {
    const T d = h.points[i].dot(direction);
    if (d > bestDot) bestDot = d, best = i;
  }
  return h.points[best];
}

namespace detail {

template <class T>
Vec3<T> coreSupport(const SphereT<T>& s, const Vec3<T>&, const Vec3<T>& origin) {
  return s.center - origin;
}

template <class T>
T coreRadius(const SphereT<T>& s) {
  return s.radius;
}

template <class T>
Vec3<T> referencePoint(const SphereT<T>& s) {
  return s.center;
}

template <class T>
Vec3<T> coreSupport(const AabbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(b, d) - origin;  // every coordinate is data: one rounding
}

template <class T>
Vec3<T> referencePoint(const AabbT<T>& b) {
  return b.center();
}

template <class T>
Vec3<T> coreSupport(const ObbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin) {
  Vec3<T> p = b.center - origin;
  for (int i = 0; i < 3; ++i) {
    const T h = b.axes.col(i).dot(d) >= 0 ? b.halfExtents[i] : -b.halfExtents[i];
    p += h * b.axes.col(i);
  }
  return p;
}

template <class T>
Vec3<T> referencePoint(const ObbT<T>& b) {
  return b.center;
}

template <class T>
Vec3<T> coreSupport(const TriangleT<T>& t, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(TriangleT<T>{t.a - origin, t.b - origin, t.c - origin}, d);
}

template <class T>
Vec3<T> referencePoint(const TriangleT<T>& t) {
  return t.a;
}

template <class T>
Vec3<T> coreSupport(const SegmentT<T>& s, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(SegmentT<T>{s.start - origin, s.end - origin}, d);
}

template <class T>
Vec3<T> referencePoint(const SegmentT<T>& s) {
  return s.start;
}

template <class T>
Vec3<T> coreSupport(const ConvexHullT<T>& h, const Vec3<T>& d, const Vec3<T>& origin) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  Vec3<T> best = h.points[0] - origin;
  T bestDot = best.dot(d);
  for (std::size_t i = 1; i < h.points.size(); ++i) {
    const Vec3<T> p = h.points[i] - origin;
    const T dot = p.dot(d);
    if (dot > bestDot) bestDot = dot, best = p;
  }
  return best;
}

template <class T>
Vec3<T> referencePoint(const ConvexHullT<T>& h) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  return h.points[0];
}

}  // namespace detail

}  // namespace simdphys

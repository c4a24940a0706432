// The definitions of simdphys/geometry3d/intersect.hpp (3D shape-versus-shape tests): included by
// intersect.cpp, which instantiates them for float and double, and by any file of src/ that wants
// them inlined.
#pragma once

#include "simdphys/geometry3d/intersect.hpp"
#include "src/reference/geometry3d/point_tests-inl.hpp"
#include "src/reference/math-inl.hpp"

namespace simdphys {

namespace detail {

template <class T, std::size_t N>
bool lexicographicallyLess(const std::array<T, N>& a, const std::array<T, N>& b) {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
}

template <class T>
std::array<T, 9> numbers(const TriangleT<T>& t) {
  return {t.a.x(), t.a.y(), t.a.z(), t.b.x(), t.b.y(), t.b.z(), t.c.x(), t.c.y(), t.c.z()};
}

template <class T>
std::array<T, 4> numbers(const PlaneT<T>& p) {
  return {p.normal.x(), p.normal.y(), p.normal.z(), p.d};
}

// True when (b, a) is the canonical order of the pair.
template <class S>
bool swapToCanonical(const S& a, const S& b) {
  return lexicographicallyLess(numbers(b), numbers(a));
}

template <class T>
struct Interval {
  T min, max;
};

template <class T>
Interval<T> projectOnto(const SatBox<T>& box, const Vec3<T>& axis) {
  const T c = box.center.dot(axis);
  const T r = box.half[0] * std::abs(box.axes.col(0).dot(axis)) +
              box.half[1] * std::abs(box.axes.col(1).dot(axis)) +
              box.half[2] * std::abs(box.axes.col(2).dot(axis));
  return {c - r, c + r};
}

template <class T>
Interval<T> projectOnto(const std::array<Vec3<T>, 3>& v, const Vec3<T>& axis) {
  const T p0 = v[0].dot(axis), p1 = v[1].dot(axis), p2 = v[2].dot(axis);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}

// True when the two intervals on `axis` are apart by more than the tolerance; the axis is not
// normalised, so the tolerance is scaled by its length (see the header comment). The gap is
// max(b.min - a.max, a.min - b.max), compared side by side so that swapping a and b changes
// nothing even for a NaN (std::max is not symmetric there).
template <class T>
bool separatedOn(const Interval<T>& a, const Interval<T>& b, const Vec3<T>& axis, T scale) {
  const T tolerance = kGeometryTolerance<T> * scale * axis.norm();
  return b.min - a.max > tolerance || a.min - b.max > tolerance;
}

// Whether an edge-edge axis is long enough to test (see the header comment on parallel edges).
// |e1| |e2| is one product, so swapping e1 and e2 gives the same threshold bits.
template <class T>
bool crossAxis(const Vec3<T>& e1, const Vec3<T>& e2, Vec3<T>& axis) {
  axis = e1.cross(e2);
  return axis.norm() > kGeometryTolerance<T> * (e1.norm() * e2.norm());
}

template <class T>
bool boxesIntersect(const SatBox<T>& a, const SatBox<T>& b) {
  const T scale = (a.center.norm() + a.half.sum()) + (b.center.norm() + b.half.sum());
  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(a, axis), projectOnto(b, axis), axis, scale);
  };
  for (int i = 0; i < 3; ++i)
    if (separated(a.axes.col(i)) || separated(b.axes.col(i))) return false;
  Vec3<T> axis;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis<T>(a.axes.col(i), b.axes.col(j), axis) && separated(axis)) return false;
  return true;
}

// The three edges b - a, c - b, a - c of a triangle.
template <class T>
std::array<Vec3<T>, 3> edgesOf(const std::array<Vec3<T>, 3>& v) {
  return {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
}

// The triangle's normal, or false if it is degenerate (see degenerateTriangle).
template <class T>
bool properNormal(const std::array<Vec3<T>, 3>& e, Vec3<T>& normal) {
  normal = e[0].cross(e[1]);
  const T longest = std::max({e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()});
  return !degenerateTriangle(normal, longest);
}

// Scales the vertices v and the other vectors (all relative to the test's reference point) by one
// power of two so that every component is below 1. Exact (no rounding, barring underflow far
// below the tolerance), so the test's answer is that of the unscaled offsets; but the edge
// crosses (L^2), their norms (L^4 before the root) and projections on them (L^3) stay finite for
// shapes anywhere in the supported range: offsets of 2e18 would give 1e73 and report shapes at
// opposite ends of the range as intersecting (an infinite tolerance).
template <class T>
void toUnitScale(std::array<Vec3<T>, 3>& v, std::initializer_list<Vec3<T>*> others) {
  T m = 0;
  for (const Vec3<T>& x : v) m = std::max(m, x.cwiseAbs().maxCoeff());
  for (const Vec3<T>* x : others) m = std::max(m, x->cwiseAbs().maxCoeff());
  const T inverse = inversePowerOfTwo(m);
  for (Vec3<T>& x : v) x *= inverse;
  for (Vec3<T>* x : others) *x *= inverse;
}

// Triangle-box SAT: the box's 3 face axes, the triangle's normal, the 9 crosses of box axes with
// triangle edges. Complete also for a degenerate triangle (a segment: its Minkowski difference
// with the box has only box faces and edge crosses; a point: only box faces) and for flat boxes
// (the box's axes exist whatever its extents; when box and triangle are coplanar, the in-plane
// normal n x e of a triangle edge is, on the flat difference, equivalent to any u x e that is not
// parallel to n, and one of the three box axes gives such an axis).
template <class T>
bool triangleBoxIntersect(std::array<Vec3<T>, 3> v, SatBox<T> box) {
  toUnitScale(v, {&box.center, &box.half});
  const T scale =
      box.center.norm() + box.half.sum() + std::max({v[0].norm(), v[1].norm(), v[2].norm()});
  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(v, axis), projectOnto(box, axis), axis, scale);
  };
  for (int i = 0; i < 3; ++i)
    if (separated(box.axes.col(i))) return false;
  const std::array<Vec3<T>, 3> e = edgesOf(v);
  Vec3<T> axis;
  if (properNormal(e, axis) && separated(axis)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis<T>(box.axes.col(i), e[j], axis) && separated(axis)) return false;
  return true;
}

// The longest edge of a degenerate triangle, the segment it stands for.
template <class T>
SegmentT<T> longestEdge(const std::array<Vec3<T>, 3>& v) {
  const std::array<Vec3<T>, 3> e = edgesOf(v);
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (e[i].squaredNorm() > e[k].squaredNorm()) k = i;
  return {v[k], v[(k + 1) % 3]};
}

template <class T>
bool trianglesIntersect(std::array<Vec3<T>, 3> v1, std::array<Vec3<T>, 3> v2) {
  toUnitScale(v1, {&v2[0], &v2[1], &v2[2]});
  T scale = 0;
  for (int i = 0; i < 3; ++i) scale = std::max({scale, v1[i].norm(), v2[i].norm()});
  scale *= 2;  // also bounds the edge lengths
  const std::array<Vec3<T>, 3> e1 = edgesOf(v1), e2 = edgesOf(v2);
  Vec3<T> n1, n2;
  const bool proper1 = properNormal(e1, n1), proper2 = properNormal(e2, n2);
  if (!proper1 && !proper2)
    return closestPoints(longestEdge(v1), longestEdge(v2)).distance <=
           2 * kGeometryTolerance<T> * scale;

  const auto separated = [&](const Vec3<T>& axis) {
    return separatedOn(projectOnto(v1, axis), projectOnto(v2, axis), axis, scale);
  };
  if ((proper1 && separated(n1)) || (proper2 && separated(n2))) return false;
  Vec3<T> axis;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (crossAxis(e1[i], e2[j], axis) && separated(axis)) return false;
  const auto separatedInPlane = [&](const Vec3<T>& n) {
    for (const std::array<Vec3<T>, 3>* e : {&e1, &e2})
      for (int i = 0; i < 3; ++i)
        if (crossAxis(n, (*e)[i], axis) && separated(axis)) return true;
    return false;
  };
  return !((proper1 && separatedInPlane(n1)) || (proper2 && separatedInPlane(n2)));
}

template <class T>
std::array<Vec3<T>, 3> relative(const TriangleT<T>& t, const Vec3<T>& origin) {
  return {t.a - origin, t.b - origin, t.c - origin};
}

// An AABB as a SatBox relative to its own min corner (differences of nearby coordinates are exact,
// its center (min + max) / 2 at large coordinates would not be).
template <class T>
SatBox<T> boxFromMin(const AabbT<T>& box) {
  const Vec3<T> half = (box.max - box.min) / T(2);
  return {half, half, Mat3<T>::Identity()};
}

// |s| <= r within the tolerance: a shape of radius r along the normal, at signed distance s.
template <class T>
bool withinPlaneReach(T s, T r, T scale) {
  return std::abs(s) <= r + kGeometryTolerance<T> * scale;
}

}  // namespace detail

template <class T>
bool intersects(const SphereT<T>& a, const SphereT<T>& b) {
  const T distance = (b.center - a.center).norm();
  const T reach = a.radius + b.radius;
  return distance <= reach + kGeometryTolerance<T> * (distance + reach);
}

template <class T>
bool intersects(const SphereT<T>& sphere, const AabbT<T>& box) {
  const T distance = (sphere.center - closestPoint(box, sphere.center)).norm();
  return distance <= sphere.radius + kGeometryTolerance<T> * (distance + sphere.radius);
}

template <class T>
bool intersects(const SphereT<T>& sphere, const ObbT<T>& box) {
  const Vec3<T> offset = sphere.center - box.center;
  const Vec3<T> local = box.axes.transpose() * offset;
  const Vec3<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  return (local - clamped).norm() <=
         sphere.radius + kGeometryTolerance<T> * (offset.norm() + sphere.radius);
}

template <class T>
bool intersects(const SphereT<T>& sphere, const PlaneT<T>& plane) {
  return detail::withinPlaneReach(plane.signedDistance(sphere.center), sphere.radius,
                                  sphere.center.norm() + std::abs(plane.d) + sphere.radius);
}

template <class T>
bool intersects(const AabbT<T>& a, const ObbT<T>& b) {
  return detail::boxesIntersect(detail::boxFromMin(a),
                                detail::SatBox<T>{b.center - a.min, b.halfExtents, b.axes});
}

template <class T>
bool intersects(const AabbT<T>& box, const PlaneT<T>& plane) {
  const Vec3<T> center = box.center(), half = box.halfExtents();
  const T reach = half.dot(plane.normal.cwiseAbs());
  return detail::withinPlaneReach(plane.signedDistance(center), reach,
                                  center.norm() + std::abs(plane.d) + reach);
}

template <class T>
bool intersects(const ObbT<T>& a, const ObbT<T>& b) {
  const Vec3<T> m = a.center * T(0.5) + b.center * T(0.5);
  return detail::boxesIntersect(detail::SatBox<T>{a.center - m, a.halfExtents, a.axes},
                                detail::SatBox<T>{b.center - m, b.halfExtents, b.axes});
}

template <class T>
bool intersects(const ObbT<T>& box, const PlaneT<T>& plane) {
  const T reach = box.halfExtents.dot((box.axes.transpose() * plane.normal).cwiseAbs());
  return detail::withinPlaneReach(plane.signedDistance(box.center), reach,
                                  box.center.norm() + std::abs(plane.d) + reach);
}

template <class T>
bool intersects(const PlaneT<T>& a, const PlaneT<T>& b) {
  if (detail::swapToCanonical(a, b)) return intersects(b, a);
  if (a.normal.cross(b.normal).norm() > kGeometryTolerance<T>) return true;
  const T offset = a.normal.dot(b.normal) > 0 ? a.d - b.d : a.d + b.d;
  return std::abs(offset) <= kGeometryTolerance<T> * (std::abs(a.d) + std::abs(b.d));
}

template <class T>
bool intersects(const TriangleT<T>& triangle, const SphereT<T>& sphere) {
  const Vec3<T> ac = sphere.center - triangle.a;
  const T distance = (ac - detail::closestOnTriangle(triangle, sphere.center)).norm();
  const T longest = std::sqrt(detail::longestEdgeSquared<T>(
      triangle.b - triangle.a, triangle.c - triangle.a, triangle.c - triangle.b));
  return distance <=
         sphere.radius + kGeometryTolerance<T> * (std::max(ac.norm(), longest) + sphere.radius);
}

template <class T>
bool intersects(const TriangleT<T>& triangle, const AabbT<T>& box) {
  return detail::triangleBoxIntersect(detail::relative(triangle, box.min), detail::boxFromMin(box));
}

template <class T>
bool intersects(const TriangleT<T>& triangle, const ObbT<T>& box) {
  return detail::triangleBoxIntersect(
      detail::relative(triangle, box.center),
      detail::SatBox<T>{Vec3<T>::Zero(), box.halfExtents, box.axes});
}

template <class T>
bool intersects(const TriangleT<T>& triangle, const PlaneT<T>& plane) {
  const T sa = plane.signedDistance(triangle.a), sb = plane.signedDistance(triangle.b),
          sc = plane.signedDistance(triangle.c);
  const T scale =
      std::max({triangle.a.norm(), triangle.b.norm(), triangle.c.norm()}) + std::abs(plane.d);
  const T tolerance = kGeometryTolerance<T> * scale;
  return std::min({sa, sb, sc}) <= tolerance && std::max({sa, sb, sc}) >= -tolerance;
}

template <class T>
bool intersects(const TriangleT<T>& a, const TriangleT<T>& b) {
  if (detail::swapToCanonical(a, b)) return intersects(b, a);
  return detail::trianglesIntersect(detail::relative(a, a.a), detail::relative(b, a.a));
}

}  // namespace simdphys

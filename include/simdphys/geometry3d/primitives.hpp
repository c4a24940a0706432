// The 3D primitives of the book's chapters 7 and 11, as small value types on Eigen vectors,
// templated on the scalar: `float` is the API, `double` the reference errors are measured
// against. They are plain aggregates; `validate` checks one (values within the supported range of
// math.hpp, which also excludes NaN and inf, non-negative sizes, unit directions, orthonormal
// axes) and throws Error saying what and where. A sphere or box must lie in the range as a whole
// (its center +- its extent), a plane pass within kMaxCoordinate of the origin. Streams and
// constructors of the library validate what they are given; a user building one by hand calls
// `validate` where the data enters.
#pragma once

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/math.hpp"

namespace simdphys {

template <class T>
using PointT = Vec3<T>;

// The segment from start to end (the book's "Line"); start == end is a degenerate segment, a
// point, which queries accept.
template <class T>
struct SegmentT {
  Vec3<T> start, end;
  Vec3<T> direction() const { return end - start; }
  T length() const { return direction().norm(); }
};

// A half-line from origin along a unit direction: t >= 0 gives origin + t direction.
template <class T>
struct RayT {
  Vec3<T> origin, direction;
  Vec3<T> at(T t) const { return origin + t * direction; }
  // The ray from origin towards target; throws Error if they coincide.
  static RayT fromTo(const Vec3<T>& origin, const Vec3<T>& target);
};

template <class T>
struct SphereT {
  Vec3<T> center;
  T radius;
};

// Axis-aligned box, closed: a box whose min equals its max on an axis is a valid flat box.
template <class T>
struct AabbT {
  Vec3<T> min, max;
  Vec3<T> center() const { return (min + max) / T(2); }
  Vec3<T> halfExtents() const { return (max - min) / T(2); }
  static AabbT fromCenter(const Vec3<T>& c, const Vec3<T>& half) { return {c - half, c + half}; }
};

// Oriented box: the columns of `axes` are its local x, y, z axes (orthonormal, right-handed);
// a point p is inside when |axes^T (p - center)| <= halfExtents on every axis.
template <class T>
struct ObbT {
  Vec3<T> center;
  Vec3<T> halfExtents;
  Mat3<T> axes = Mat3<T>::Identity();
};

// The plane n.p + d = 0 with unit normal n; n.p + d > 0 is its front.
template <class T>
struct PlaneT {
  Vec3<T> normal;
  T d;
  T signedDistance(const Vec3<T>& p) const { return normal.dot(p) + d; }
  // The plane through `point` with the given normal (normalised; throws Error if zero).
  static PlaneT fromPointNormal(const Vec3<T>& point, const Vec3<T>& normal);
};

// A triangle; its front face is counter-clockwise: normal = (b - a) x (c - a).
template <class T>
struct TriangleT {
  Vec3<T> a, b, c;
  Vec3<T> normal() const { return (b - a).cross(c - a); }  // not normalised
};

using Point = PointT<float>;
using Segment = SegmentT<float>;
using Ray = RayT<float>;
using Sphere = SphereT<float>;
using Aabb = AabbT<float>;
using Obb = ObbT<float>;
using Plane = PlaneT<float>;
using Triangle = TriangleT<float>;
using Segmentd = SegmentT<double>;
using Rayd = RayT<double>;
using Sphered = SphereT<double>;
using Aabbd = AabbT<double>;
using Obbd = ObbT<double>;
using Planed = PlaneT<double>;
using Triangled = TriangleT<double>;

// Converts a primitive to another scalar type (float to the double reference, mostly).
template <class U, class T>
SphereT<U> cast(const SphereT<T>& s) {
  return {s.center.template cast<U>(), U(s.radius)};
}
template <class U, class T>
AabbT<U> cast(const AabbT<T>& b) {
  return {b.min.template cast<U>(), b.max.template cast<U>()};
}
template <class U, class T>
ObbT<U> cast(const ObbT<T>& b) {
  return {b.center.template cast<U>(), b.halfExtents.template cast<U>(), b.axes.template cast<U>()};
}
template <class U, class T>
PlaneT<U> cast(const PlaneT<T>& p) {
  return {p.normal.template cast<U>(), U(p.d)};
}
template <class U, class T>
TriangleT<U> cast(const TriangleT<T>& t) {
  return {t.a.template cast<U>(), t.b.template cast<U>(), t.c.template cast<U>()};
}
template <class U, class T>
SegmentT<U> cast(const SegmentT<T>& s) {
  return {s.start.template cast<U>(), s.end.template cast<U>()};
}
template <class U, class T>
RayT<U> cast(const RayT<T>& r) {
  return {r.origin.template cast<U>(), r.direction.template cast<U>()};
}

// ---- validation ------------------------------------------------------------------------------

namespace detail {
// Each component finite and within the supported range (math.hpp), e.g. "where: min.y is 1e+20,
// outside the supported range +-1e+18".
template <class V>
void requireFiniteField(const V& v, std::string_view where, const char* field) {
  constexpr char kAxis[] = {'x', 'y', 'z', 'w'};
  for (int a = 0; a < int(v.size()); ++a)  // the field's name is built only for the message
    if (!inSupportedRange(std::abs(double(v[a]))))
      requireInRange(v[a], where, std::string(field) + '.' + kAxis[a]);
}
template <class T>
void requireFiniteScalar(T x, std::string_view where, const char* field) {
  requireInRange(x, where, field);
}
// Tolerance for "unit length" and "orthonormal": a few rounding steps of a normalisation in T.
template <class T>
constexpr T kUnitTolerance = T(64) * std::numeric_limits<T>::epsilon();
}  // namespace detail

template <class T>
void validate(const AabbT<T>& box, std::string_view where) {
  detail::requireFiniteField(box.min, where, "min");
  detail::requireFiniteField(box.max, where, "max");
  constexpr char kAxis[] = {'x', 'y', 'z'};
  for (int a = 0; a < 3; ++a) {
    if (box.min[a] <= box.max[a]) continue;
    std::ostringstream msg;
    msg << where << ": min." << kAxis[a] << " (" << box.min[a] << ") > max." << kAxis[a] << " ("
        << box.max[a] << ")";
    throw Error(msg.str());
  }
}

template <class T>
void validate(const SphereT<T>& sphere, std::string_view where) {
  detail::requireFiniteField(sphere.center, where, "center");
  if (!(std::isfinite(sphere.radius) && sphere.radius >= 0)) {
    std::ostringstream msg;
    msg << where << ": radius is " << sphere.radius << ", must be finite and >= 0";
    throw Error(msg.str());
  }
  detail::requireReachInRange(sphere.center, Vec3<T>::Constant(sphere.radius), where,
                              "center +- radius");
}

template <class T>
void validate(const SegmentT<T>& s, std::string_view where) {
  detail::requireFiniteField(s.start, where, "start");
  detail::requireFiniteField(s.end, where, "end");
}

template <class T>
void validate(const RayT<T>& r, std::string_view where) {
  detail::requireFiniteField(r.origin, where, "origin");
  detail::requireFiniteField(r.direction, where, "direction");
  if (std::abs(r.direction.norm() - T(1)) > detail::kUnitTolerance<T>)
    throw Error(std::string(where) + ": direction is not unit length (|d| = " +
                std::to_string(double(r.direction.norm())) + ")");
}

template <class T>
void validate(const PlaneT<T>& p, std::string_view where) {
  detail::requireFiniteField(p.normal, where, "normal");
  detail::requireFiniteScalar(p.d, where, "d");
  if (std::abs(p.normal.norm() - T(1)) > detail::kUnitTolerance<T>)
    throw Error(std::string(where) + ": normal is not unit length (|n| = " +
                std::to_string(double(p.normal.norm())) + ")");
}

template <class T>
void validate(const ObbT<T>& b, std::string_view where) {
  detail::requireFiniteField(b.center, where, "center");
  detail::requireFiniteField(b.halfExtents, where, "halfExtents");
  detail::requireFiniteField(b.axes.col(0), where, "axes.col(0)");
  detail::requireFiniteField(b.axes.col(1), where, "axes.col(1)");
  detail::requireFiniteField(b.axes.col(2), where, "axes.col(2)");
  for (int a = 0; a < 3; ++a)
    if (!(b.halfExtents[a] >= 0))
      throw Error(std::string(where) + ": halfExtents has a negative component");
  const T error = (b.axes.transpose() * b.axes - Mat3<T>::Identity()).cwiseAbs().maxCoeff();
  if (error > detail::kUnitTolerance<T> || b.axes.determinant() < 0)
    throw Error(std::string(where) + ": axes are not orthonormal and right-handed (|A^T A - I| = " +
                std::to_string(double(error)) + ")");
  detail::requireReachInRange(b.center, Vec3<T>(b.axes.cwiseAbs() * b.halfExtents), where,
                              "the box (center +- |axes| halfExtents)");
}

template <class T>
void validate(const TriangleT<T>& t, std::string_view where) {
  detail::requireFiniteField(t.a, where, "a");
  detail::requireFiniteField(t.b, where, "b");
  detail::requireFiniteField(t.c, where, "c");
}

// Both accept any finite non-zero offset or normal (unitOr scales it before taking its length)
// and check that the points are in the supported range and the plane passes within it.
template <class T>
RayT<T> RayT<T>::fromTo(const Vec3<T>& origin, const Vec3<T>& target) {
  detail::requireFiniteField(origin, "Ray::fromTo", "origin");
  detail::requireFiniteField(target, "Ray::fromTo", "target");
  const Vec3<T> d = target - origin;
  if ((d.array() == 0).all()) throw Error("Ray::fromTo: origin and target coincide");
  return {origin, detail::unitOr(d, Vec3<T>::Zero().eval())};
}

template <class T>
PlaneT<T> PlaneT<T>::fromPointNormal(const Vec3<T>& point, const Vec3<T>& normal) {
  detail::requireFiniteField(point, "Plane::fromPointNormal", "point");
  if (!normal.allFinite()) throw Error("Plane::fromPointNormal: the normal is not finite");
  if ((normal.array() == 0).all()) throw Error("Plane::fromPointNormal: the normal is zero");
  const Vec3<T> n = detail::unitOr(normal, Vec3<T>::Zero().eval());
  const PlaneT plane{n, -n.dot(point)};
  validate(plane, "Plane::fromPointNormal");
  return plane;
}

// Closed overlap of two boxes: boxes that only touch overlap.
template <class T>
bool overlaps(const AabbT<T>& a, const AabbT<T>& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace simdphys

// The 3D primitives of the book's chapters 7 and 11, as small value types on Eigen vectors,
// templated on the scalar: `float` is the API, `double` the reference errors are measured
// against. They are plain aggregates; `validate` checks one (values within the supported range of
// math.hpp, which also excludes NaN and inf, non-negative sizes, unit directions, orthonormal
// axes) and throws Error saying what and where. A sphere or box must lie in the range as a whole
// (its center +- its extent), a plane pass within kMaxCoordinate of the origin. Streams and
// constructors of the library validate what they are given; a user building one by hand calls
// `validate` where the data enters.
#pragma once

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
// Each throws Error saying what is wrong and where (compiled for float and double in
// src/reference/geometry3d/primitives.cpp).

// min <= max on every axis.
template <class T>
void validate(const AabbT<T>& box, std::string_view where);
// radius finite and >= 0, center +- radius in range.
template <class T>
void validate(const SphereT<T>& sphere, std::string_view where);
template <class T>
void validate(const SegmentT<T>& s, std::string_view where);
// direction of unit length (within 64 eps).
template <class T>
void validate(const RayT<T>& r, std::string_view where);
// normal of unit length (within 64 eps).
template <class T>
void validate(const PlaneT<T>& p, std::string_view where);
// halfExtents >= 0, axes orthonormal and right-handed, center +- |axes| halfExtents in range.
template <class T>
void validate(const ObbT<T>& b, std::string_view where);
template <class T>
void validate(const TriangleT<T>& t, std::string_view where);

// Closed overlap of two boxes: boxes that only touch overlap.
template <class T>
bool overlaps(const AabbT<T>& a, const AabbT<T>& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace simdphys

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
#include "simdphys/primitives.hpp"

namespace simdphys {

template <class T>
using PointT = Vec3<T>;

// The segment (the book's "Line"), ray, sphere and axis-aligned box are those of
// primitives.hpp, shared with 2D.
template <class T>
using SegmentT = SegmentN<T, 3>;
template <class T>
using RayT = RayN<T, 3>;
template <class T>
using SphereT = BallN<T, 3>;
template <class T>
using AabbT = BoxN<T, 3>;

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

// Converts a primitive to another scalar type (float to the double reference, mostly; the shared
// ones in primitives.hpp).
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

namespace detail {
template <class T>
inline constexpr int kPairOrder<TriangleT<T>> = 0;  // the pair tests' order (primitives.hpp)
template <class T>
inline constexpr int kPairOrder<ObbT<T>> = 3;
template <class T>
inline constexpr int kPairOrder<PlaneT<T>> = 4;
}  // namespace detail

// ---- validation ------------------------------------------------------------------------------
// Each throws Error saying what is wrong and where (compiled for float and double in
// src/reference/geometry3d/primitives.cpp; the shared shapes' in primitives.hpp).

// normal of unit length (within 64 eps).
template <class T>
void validate(const PlaneT<T>& p, std::string_view where);
// halfExtents >= 0, axes orthonormal and right-handed, center +- |axes| halfExtents in range.
template <class T>
void validate(const ObbT<T>& b, std::string_view where);
template <class T>
void validate(const TriangleT<T>& t, std::string_view where);

}  // namespace simdphys

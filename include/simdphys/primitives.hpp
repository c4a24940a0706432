// The primitives that are the same in 2D and 3D, written once as templates on the scalar T and
// the dimension N: segment, ray, ball (circle, sphere) and axis-aligned box (rectangle, AABB).
// geometry2d/primitives.hpp and geometry3d/primitives.hpp name them per dimension (Segment2T,
// SegmentT, CircleT, SphereT, RectT, AabbT, ...) beside the shapes of one dimension only.
// They are plain aggregates; `validate` checks one and throws Error saying what and where
// (compiled for float and double, 2D and 3D, in src/reference/primitives.cpp).
#pragma once

#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/math.hpp"

namespace simdphys {

template <class T, int N>
using VecN = Eigen::Matrix<T, N, 1>;

// The segment from start to end (the book's Line and Line2D); start == end is a point, which
// queries accept.
template <class T, int N>
struct SegmentN {
  VecN<T, N> start, end;
  VecN<T, N> direction() const { return end - start; }
  T length() const { return direction().norm(); }
};

// A half-line from origin along a unit direction: t >= 0 gives origin + t direction.
template <class T, int N>
struct RayN {
  VecN<T, N> origin, direction;
  VecN<T, N> at(T t) const { return origin + t * direction; }
  // The ray from origin towards target; throws Error if they coincide or are not finite.
  static RayN fromTo(const VecN<T, N>& origin, const VecN<T, N>& target);
};

// A circle (N = 2) or sphere (N = 3).
template <class T, int N>
struct BallN {
  VecN<T, N> center;
  T radius;
};

// Axis-aligned box (a rectangle for N = 2) as its corners, closed: min == max on an axis is a
// valid flat box.
template <class T, int N>
struct BoxN {
  VecN<T, N> min, max;
  VecN<T, N> center() const { return (min + max) / T(2); }
  VecN<T, N> halfExtents() const { return (max - min) / T(2); }
  VecN<T, N> size() const { return max - min; }
  static BoxN fromCenter(const VecN<T, N>& c, const VecN<T, N>& half) {
    return {c - half, c + half};
  }
  // The book's Rectangle2D(origin, size): origin is the min corner.
  static BoxN fromOriginSize(const VecN<T, N>& origin, const VecN<T, N>& size) {
    return {origin, origin + size};
  }
};

// Converts a primitive to another scalar type (float to the double reference, mostly).
template <class U, class T, int N>
SegmentN<U, N> cast(const SegmentN<T, N>& s) {
  return {s.start.template cast<U>(), s.end.template cast<U>()};
}
template <class U, class T, int N>
RayN<U, N> cast(const RayN<T, N>& r) {
  return {r.origin.template cast<U>(), r.direction.template cast<U>()};
}
template <class U, class T, int N>
BallN<U, N> cast(const BallN<T, N>& b) {
  return {b.center.template cast<U>(), U(b.radius)};
}
template <class U, class T, int N>
BoxN<U, N> cast(const BoxN<T, N>& b) {
  return {b.min.template cast<U>(), b.max.template cast<U>()};
}

namespace detail {

// The order in which the pair tests (intersects, collide) take two kinds of shapes: each pair is
// written once, the lower order first, and the other order swaps the arguments (intersects below,
// collide in geometry2d/collisions.hpp). The dimension headers give their own shapes theirs:
// the triangle 0, the oriented rectangle and the OBB 3, the plane 4. -1: not a shape of the pair
// tests.
template <class S>
inline constexpr int kPairOrder = -1;
template <class T>
inline constexpr int kPairOrder<SegmentN<T, 2>> = 0;
template <class T, int N>
inline constexpr int kPairOrder<BallN<T, N>> = 1;
template <class T, int N>
inline constexpr int kPairOrder<BoxN<T, N>> = 2;

// (a, b) is a pair written as (b, a).
template <class A, class B>
concept SwappedPair = kPairOrder<B>
>= 0 && kPairOrder<A> > kPairOrder<B>;

}  // namespace detail

// Each throws Error saying what is wrong and where. Coordinates must be in the supported range
// (math.hpp).
template <class T, int N>
void validate(const SegmentN<T, N>& s, std::string_view where);
// direction of unit length (within 64 eps).
template <class T, int N>
void validate(const RayN<T, N>& r, std::string_view where);
// radius finite and >= 0, center +- radius in range.
template <class T, int N>
void validate(const BallN<T, N>& b, std::string_view where);
// min <= max on every axis.
template <class T, int N>
void validate(const BoxN<T, N>& b, std::string_view where);

// Closed overlap of two boxes: boxes that only touch overlap.
template <class T, int N>
bool overlaps(const BoxN<T, N>& a, const BoxN<T, N>& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}
// The same under the name of the other shape tests (geometry2d/collisions.hpp,
// geometry3d/intersect.hpp).
template <class T, int N>
bool intersects(const BoxN<T, N>& a, const BoxN<T, N>& b) {
  return overlaps(a, b);
}

// The tests are symmetric: a pair in the other order than its test is written in.
template <class A, class B>
requires detail::SwappedPair<A, B>
bool intersects(const A& a, const B& b) { return intersects(b, a); }

}  // namespace simdphys

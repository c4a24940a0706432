// The 2D primitives of the book's chapter 4 as small value types on Eigen vectors, templated on
// the scalar (`float` is the API, `double` the reference errors are measured against), and their
// validation. They mirror the 3D primitives (geometry3d/primitives.hpp): plain aggregates, closed
// shapes (a shape contains its boundary, shapes that touch intersect), and `validate` overloads
// that throw Error saying what is wrong and where.
//
// Conventions of everything 2D (geometry2d.hpp and its parts):
// - The plane is x to the right, y up; angles are radians, counter-clockwise positive.
// - Shapes are closed and solid. Zero sizes are valid: a zero-radius circle, a zero-size
//   rectangle or oriented rectangle, a zero-length segment are points (a rectangle of zero width
//   is a segment) and every query accepts them.
// - Computations that round (everything but the axis-aligned rectangle's comparisons) decide
//   "touching" within kGeometry2dTolerance times a scale stated per function: the sizes and
//   offsets the rounding error grows with. Differences are taken relative to a point of a shape
//   before anything is multiplied, so shapes of size 1 at coordinates of 1e5 keep the precision
//   of their size; a result given in absolute coordinates (a closest point, a contact point) is of
//   course only as precise as the representation of its coordinates (an ulp of 1e5 is 0.0078 in
//   float).
// - Queries do not validate; inputs are assumed valid and within the supported range of math.hpp
//   (coordinates and sizes up to kMaxCoordinate = 1e18 in magnitude, a shape's center +- extent
//   included), where they do not overflow: call validate() where data enters, as the library's
//   own constructors and streams do.
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/math.hpp"
#include "simdphys/primitives.hpp"

namespace simdphys {

// The relative tolerance of the 2D tests: a distance up to kGeometry2dTolerance * scale counts as
// zero (a point on a shape, shapes touching). It is the 3D one, kGeometryTolerance (math.hpp):
// 16 eps, 1.9e-6 in float and 3.6e-15 in double.
template <class T>
inline constexpr T kGeometry2dTolerance = kGeometryTolerance<T>;

template <class T>
using Point2T = Vec2<T>;

// The segment (the book's Line2D), ray, circle and axis-aligned rectangle are those of
// primitives.hpp, shared with 3D (RectT::fromOriginSize is the book's Rectangle2D(origin, size)).
template <class T>
using Segment2T = SegmentN<T, 2>;
template <class T>
using Ray2T = RayN<T, 2>;
template <class T>
using CircleT = BallN<T, 2>;
template <class T>
using RectT = BoxN<T, 2>;

// Oriented rectangle: `halfExtents` along its local axes, turned by `rotation` radians
// counter-clockwise about its center. Its local x axis is (cos, sin), its local y axis
// (-sin, cos); a point p is inside when |axes()^T (p - center)| <= halfExtents on both axes.
template <class T>
struct OrientedRectT {
  Vec2<T> center;
  Vec2<T> halfExtents;
  T rotation = 0;
  // Columns: the local x and y axes in world coordinates (a rotation matrix). rotation == 0 gives
  // the identity exactly.
  Mat2<T> axes() const {
    const T c = std::cos(rotation), s = std::sin(rotation);
    Mat2<T> m;
    m << c, -s, s, c;
    return m;
  }
  // The corners, counter-clockwise from local (-hx, -hy).
  std::array<Vec2<T>, 4> corners() const {
    const Mat2<T> r = axes();
    const Vec2<T> ex = r.col(0) * halfExtents.x(), ey = r.col(1) * halfExtents.y();
    return {center - ex - ey, center + ex - ey, center + ex + ey, center - ex + ey};
  }
};

using Point2 = Point2T<float>;
using Segment2 = Segment2T<float>;
using Ray2 = Ray2T<float>;
using Circle = CircleT<float>;
using Rect = RectT<float>;
using OrientedRect = OrientedRectT<float>;
using Point2d = Point2T<double>;
using Segment2d = Segment2T<double>;
using Ray2d = Ray2T<double>;
using Circled = CircleT<double>;
using Rectd = RectT<double>;
using OrientedRectd = OrientedRectT<double>;

// Converts a primitive to another scalar type (float to the double reference, mostly; the shared
// ones in primitives.hpp).
template <class U, class T>
OrientedRectT<U> cast(const OrientedRectT<T>& r) {
  return {r.center.template cast<U>(), r.halfExtents.template cast<U>(), U(r.rotation)};
}

namespace detail {
template <class T>
inline constexpr int kPairOrder<OrientedRectT<T>> = 3;  // the pair tests' order (primitives.hpp)
}  // namespace detail

// The smallest axis-aligned rectangles around the other shapes (exact for the circle; for the
// oriented rectangle, the extents |axes| * halfExtents, rounded once per product).
template <class T>
RectT<T> boundingRect(const CircleT<T>& c) {
  const Vec2<T> r = Vec2<T>::Constant(c.radius);
  return {c.center - r, c.center + r};
}
template <class T>
RectT<T> boundingRect(const OrientedRectT<T>& b) {
  const Vec2<T> e = b.axes().cwiseAbs() * b.halfExtents;
  return {b.center - e, b.center + e};
}
template <class T>
RectT<T> boundingRect(const Segment2T<T>& s) {
  return {s.start.cwiseMin(s.end), s.start.cwiseMax(s.end)};
}

// ---- validation ------------------------------------------------------------------------------
// Each throws Error saying what is wrong and where (compiled for float and double in
// src/reference/geometry2d/primitives.cpp; the shared shapes' in primitives.hpp). Coordinates
// must be in the supported range (math.hpp).

template <class T>
void validate(const Vec2<T>& point, std::string_view where);
// rotation finite, halfExtents >= 0, center +- |axes| halfExtents in range.
template <class T>
void validate(const OrientedRectT<T>& b, std::string_view where);

}  // namespace simdphys

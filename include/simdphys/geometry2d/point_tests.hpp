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
#include "simdphys/point_tests.hpp"

namespace simdphys {

// ---- containment ----------------------------------------------------------------------------

// On the segment: distance to it <= tolerance * max(|p - start|, length). A zero-length segment
// contains only its point.
template <class T>
bool contains(const Segment2T<T>& segment, const detail::NoDeduce<Vec2<T>>& point);

// Closed disc: |p - c| <= r, within the tolerance times max(|p - c|, r). A zero-radius circle
// contains only its center.
template <class T>
bool contains(const CircleT<T>& circle, const detail::NoDeduce<Vec2<T>>& point);

// Closed oriented rectangle: |local| <= halfExtents on both axes, within the tolerance times
// |p - c| + the larger half extent (the rotation into the local frame rounds by about 2 eps |p -
// c|).
template <class T>
bool contains(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point);

// ---- closest points -------------------------------------------------------------------------

// Those of the segment, the circle and the rectangle, and the rectangle's containment, are shared
// with 3D: simdphys/point_tests.hpp.

// p clamped to the rectangle in its local frame; a point inside is returned unchanged (exactly).
template <class T>
Vec2<T> closestPoint(const OrientedRectT<T>& box, const detail::NoDeduce<Vec2<T>>& point);

}  // namespace simdphys

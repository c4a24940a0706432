// Containing shapes and compound shapes (the book's chapter 6, "2D optimisations"):
// - containingRect(points): the smallest axis-aligned rectangle around a point set (exact).
// - containingCircle(points): the smallest circle around a point set, by Welzl's algorithm in its
//   iterative form (Welzl 1991; de Berg et al., "MiniDisc"): the points are visited in a shuffled
//   order (a fixed seed: the result is deterministic), and each point outside the current circle
//   is put on the boundary of a new one, recursively for up to three boundary points. Guarantee:
//   in exact arithmetic the result is THE minimal enclosing circle, found in expected O(n) time
//   (the shuffle makes the expectation hold for every input). In floating point its radius is
//   within a few ulps of the minimal one, and a final pass grows the radius to the farthest point,
//   so every point is contained (contains(circle, p) is true) with no tolerance at all. The book
//   instead takes the centroid and the farthest point: it contains the points but can be much
//   larger than needed (e.g. many points bunched on one side).
// - BoundingShape2T: a compound shape, the union of several circles, rectangles and oriented
//   rectangles (the book's BoundingShape has circles and rectangles). It contains a point, meets
//   a shape or a segment, or is hit by a ray when one of its parts does. An empty one contains
//   and meets nothing.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/line_tests.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
#include "simdphys/geometry2d/primitives.hpp"

namespace simdphys {

namespace detail::g2 {

// What a compound shape can be tested against: a primitive or a segment.
template <class S, class T>
concept PartOrSegment = std::is_same_v<S, CircleT<T>> || std::is_same_v<S, RectT<T>> ||
    std::is_same_v<S, OrientedRectT<T>> || std::is_same_v<S, Segment2T<T>>;

}  // namespace detail::g2

// The smallest axis-aligned rectangle containing every point (componentwise min and max: exact).
// Throws Error on an empty set or a point outside the supported range (math.hpp).
template <class T>
RectT<T> containingRect(std::span<const Vec2<T>> points);
template <class T>
RectT<T> containingRect(const std::vector<Vec2<T>>& points);

// The minimal enclosing circle (Welzl, see the header comment). Throws Error on an empty set or a
// point outside the supported range (math.hpp). One point gives a zero-radius circle on it.
template <class T>
CircleT<T> containingCircle(std::span<const Vec2<T>> points);
template <class T>
CircleT<T> containingCircle(const std::vector<Vec2<T>>& points);

// ---- compound shapes -------------------------------------------------------------------------

template <class T>
struct BoundingShape2T {
  std::vector<CircleT<T>> circles;
  std::vector<RectT<T>> rects;
  std::vector<OrientedRectT<T>> orientedRects;
  bool empty() const { return circles.empty() && rects.empty() && orientedRects.empty(); }

  // Calls f(part) for each part until it returns true; returns whether one did.
  template <class F>
  bool any(F&& f) const {
    for (const CircleT<T>& c : circles)
      if (f(c)) return true;
    for (const RectT<T>& r : rects)
      if (f(r)) return true;
    for (const OrientedRectT<T>& b : orientedRects)
      if (f(b)) return true;
    return false;
  }
};
using BoundingShape2 = BoundingShape2T<float>;
using BoundingShape2d = BoundingShape2T<double>;

// Validates every part; the message names it, e.g. "load: circles[2]: radius is -1, must be >= 0".
template <class T>
void validate(const BoundingShape2T<T>& shape, std::string_view where);

// The union of the parts' bounding rectangles; throws Error for an empty shape.
template <class T>
RectT<T> boundingRect(const BoundingShape2T<T>& shape);

template <class T>
bool contains(const BoundingShape2T<T>& shape, const detail::NoDeduce<Vec2<T>>& point);

// Against a primitive or a segment: some part meets it (each part's own test and tolerance).
template <class T, detail::g2::PartOrSegment<T> S>
bool intersects(const BoundingShape2T<T>& shape, const S& other) {
  return shape.any([&](const auto& part) { return intersects(part, other); });
}
template <class T, detail::g2::PartOrSegment<T> S>
bool intersects(const S& other, const BoundingShape2T<T>& shape) {
  return intersects(shape, other);
}

// Two compound shapes: some pair of parts meets.
template <class T>
bool intersects(const BoundingShape2T<T>& a, const BoundingShape2T<T>& b) {
  return a.any([&](const auto& part) { return intersects(part, b); });
}

// The nearest hit over the parts (ties: the first part, circles then rects then oriented rects).
template <class T>
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const BoundingShape2T<T>& shape);

}  // namespace simdphys

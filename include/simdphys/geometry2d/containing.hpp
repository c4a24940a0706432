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

template <class T>
void requirePoints(std::span<const Vec2<T>> points, const char* fn) {
  if (points.empty()) throw Error(std::string(fn) + ": no points");
  const auto inRange = [](T x) { return detail::inSupportedRange(std::abs(double(x))); };
  for (std::size_t i = 0; i < points.size(); ++i)  // the name is built only for the message
    if (!(inRange(points[i].x()) && inRange(points[i].y())))
      requireInRange(points[i], fn, ("points[" + std::to_string(i) + "]").c_str());
}

// The circle with a and b on opposite ends of a diameter.
template <class T>
CircleT<T> diameterCircle(const Vec2<T>& a, const Vec2<T>& b) {
  const Vec2<T> center = a + (b - a) / T(2);
  return {center, std::max((a - center).norm(), (b - center).norm())};
}

// The circle through a, b and c; for (nearly) collinear points, whose circumcircle is unbounded
// or numerically meaningless, the diameter circle of the farthest pair (which then contains the
// third). Computed relative to a, on offsets scaled exactly by a power of two to about 1 (the
// center's offset is a ratio of cubes of lengths, which overflow float from lengths of about 7e12:
// scaled, it has the unscaled bits wherever those are finite); the radius is the largest distance
// to the three, so all three are inside.
template <class T>
CircleT<T> circumcircle(const Vec2<T>& a, const Vec2<T>& b, const Vec2<T>& c) {
  const T scale = detail::inversePowerOfTwo(
      std::max((b - a).cwiseAbs().maxCoeff(), (c - a).cwiseAbs().maxCoeff()));
  const Vec2<T> ab = (b - a) * scale, ac = (c - a) * scale;
  const T cross = ab.x() * ac.y() - ab.y() * ac.x();
  // |cross| = |ab| |ac| sin(angle at a); below the tolerance the angle is rounding noise.
  if (std::abs(cross) <= kGeometry2dTolerance<T> * ab.norm() * ac.norm()) {
    const T dab = ab.norm(), dac = ac.norm(), dbc = ((c - b) * scale).norm();
    if (dab >= dac && dab >= dbc) return diameterCircle(a, b);
    if (dac >= dbc) return diameterCircle(a, c);
    return diameterCircle(b, c);
  }
  const T ab2 = ab.squaredNorm(), ac2 = ac.squaredNorm();
  const Vec2<T> offset(ac.y() * ab2 - ab.y() * ac2, ab.x() * ac2 - ac.x() * ab2);
  const Vec2<T> center = a + (offset / (2 * cross)) / scale;
  return {center, std::max({(a - center).norm(), (b - center).norm(), (c - center).norm()})};
}

// What a compound shape can be tested against: a primitive or a segment.
template <class S, class T>
concept PartOrSegment = std::is_same_v<S, CircleT<T>> || std::is_same_v<S, RectT<T>> ||
    std::is_same_v<S, OrientedRectT<T>> || std::is_same_v<S, Segment2T<T>>;

// Welzl's point test: the same closed test with tolerance as contains(circle, p).
template <class T>
bool inCircle(const CircleT<T>& c, const Vec2<T>& p) {
  return contains(c, p);
}

}  // namespace detail::g2

// The smallest axis-aligned rectangle containing every point (componentwise min and max: exact).
// Throws Error on an empty set or a point outside the supported range (math.hpp).
template <class T>
RectT<T> containingRect(std::span<const Vec2<T>> points) {
  detail::g2::requirePoints(points, "containingRect");
  RectT<T> r{points[0], points[0]};
  for (const Vec2<T>& p : points) {
    r.min = r.min.cwiseMin(p);
    r.max = r.max.cwiseMax(p);
  }
  return r;
}
template <class T>
RectT<T> containingRect(const std::vector<Vec2<T>>& points) {
  return containingRect(std::span<const Vec2<T>>(points));
}

// The minimal enclosing circle (Welzl, see the header comment). Throws Error on an empty set or a
// point outside the supported range (math.hpp). One point gives a zero-radius circle on it.
template <class T>
CircleT<T> containingCircle(std::span<const Vec2<T>> points) {
  detail::g2::requirePoints(points, "containingCircle");
  std::vector<Vec2<T>> p(points.begin(), points.end());
  // Fisher-Yates with SplitMix64 from a fixed seed: a deterministic "random" order.
  std::uint64_t state = 0x5EED2D;
  for (std::size_t i = p.size(); i > 1; --i) {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    std::swap(p[i - 1], p[z % i]);
  }
  CircleT<T> c{p[0], T(0)};
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (detail::g2::inCircle(c, p[i])) continue;
    c = {p[i], T(0)};  // p[i] is on the boundary of the minimal circle of p[0..i]
    for (std::size_t j = 0; j < i; ++j) {
      if (detail::g2::inCircle(c, p[j])) continue;
      c = detail::g2::diameterCircle(p[i], p[j]);  // ... and so is p[j]
      for (std::size_t k = 0; k < j; ++k)
        if (!detail::g2::inCircle(c, p[k])) c = detail::g2::circumcircle(p[i], p[j], p[k]);
    }
  }
  for (const Vec2<T>& q : p) c.radius = std::max(c.radius, (q - c.center).norm());
  return c;
}
template <class T>
CircleT<T> containingCircle(const std::vector<Vec2<T>>& points) {
  return containingCircle(std::span<const Vec2<T>>(points));
}

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
void validate(const BoundingShape2T<T>& shape, std::string_view where) {
  const auto each = [&](const auto& parts, const char* name) {
    for (std::size_t i = 0; i < parts.size(); ++i)
      validate(parts[i], std::string(where) + ": " + name + "[" + std::to_string(i) + "]");
  };
  each(shape.circles, "circles");
  each(shape.rects, "rects");
  each(shape.orientedRects, "orientedRects");
}

// The union of the parts' bounding rectangles; throws Error for an empty shape.
template <class T>
RectT<T> boundingRect(const BoundingShape2T<T>& shape) {
  if (shape.empty()) throw Error("boundingRect: the bounding shape is empty");
  RectT<T> box{Vec2<T>::Constant(std::numeric_limits<T>::infinity()),
               Vec2<T>::Constant(-std::numeric_limits<T>::infinity())};
  shape.any([&](const auto& part) {
    RectT<T> r;
    if constexpr (std::is_same_v<std::decay_t<decltype(part)>, RectT<T>>) {
      r = part;
    } else {
      r = boundingRect(part);
    }
    box.min = box.min.cwiseMin(r.min);
    box.max = box.max.cwiseMax(r.max);
    return false;
  });
  return box;
}

template <class T>
bool contains(const BoundingShape2T<T>& shape, const detail::NoDeduce<Vec2<T>>& point) {
  return shape.any([&](const auto& part) { return contains(part, point); });
}

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
std::optional<RayHit2T<T>> raycast(const Ray2T<T>& ray, const BoundingShape2T<T>& shape) {
  std::optional<RayHit2T<T>> best;
  shape.any([&](const auto& part) {
    const std::optional<RayHit2T<T>> hit = raycast(ray, part);
    if (hit && (!best || hit->t < best->t)) best = hit;
    return false;
  });
  return best;
}

}  // namespace simdphys

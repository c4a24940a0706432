// The definitions of simdphys/geometry2d/containing.hpp (containing shapes and compound shapes):
// included by containing.cpp, which instantiates them for float and double, and by any file of src/
// that wants them inlined.
#pragma once

#include "simdphys/geometry2d/containing.hpp"
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "src/reference/geometry2d/line_tests-inl.hpp"
#include "src/reference/math-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

namespace detail::g2 {

template <class T>
void requirePoints(std::span<const Vec2<T>> points, const char* fn) {
  if (points.empty()) throw Error(std::string(fn) + ": no points");
  const auto inRange = [](T x) { return detail::inSupportedRange(std::abs(double(x))); };
  for (std::size_t i = 0; i < points.size(); ++i)  // the name is built only for the message
    if (!(inRange(points[i].x()) && inRange(points[i].y())))
      requireFiniteField(points[i], fn, ("points[" + std::to_string(i) + "]").c_str());
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

// Welzl's point test: the same closed test with tolerance as contains(circle, p).
template <class T>
bool inCircle(const CircleT<T>& c, const Vec2<T>& p) {
  return contains(c, p);
}

}  // namespace detail::g2

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

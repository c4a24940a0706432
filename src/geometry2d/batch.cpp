// 2D batch queries: the reference path loops over the scalar functions; the SIMD kernels mirror
// them.
#include "simdphys/geometry2d/batch.hpp"

#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
#include "src/core/on_path.hpp"
// The reference path calls these per element: their definitions, so that they inline.
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "src/views.hpp"

namespace simdphys {
namespace {

// One shape (or point) against a stream: validated, then `meets(shape, element)` per element on
// the reference path, or the kernel on the shape's query.
template <class Shape, class Stream, class Meets, class Kernel>
std::size_t select(const char* where, const Shape& shape, const Stream& stream,
                   std::vector<std::uint32_t>& out, Meets meets, Kernel kernel) {
  validate(shape, where);
  return selectOnPath(
      view(stream), out, [&](std::uint32_t i) { return meets(shape, stream[i]); },
      [&](const auto& v, std::uint32_t* o) { return kernel(query2d(shape), v, o); });
}

constexpr auto kIntersects = [](const auto& shape, const auto& e) { return intersects(shape, e); };
constexpr auto kContains = [](const Vec2f& point, const auto& e) { return contains(e, point); };

}  // namespace

std::size_t overlapping(const Circle& circle, const CircleStream& circles,
                        std::vector<std::uint32_t>& out) {
  return select("overlapping", circle, circles, out, kIntersects, simd::circleOverlapsCircles);
}

std::size_t overlapping(const Rect& rect, const RectStream& rects,
                        std::vector<std::uint32_t>& out) {
  return select("overlapping", rect, rects, out, kIntersects, simd::rectOverlapsRects);
}

std::size_t overlapping(const OrientedRect& rect, const OrientedRectStream& rects,
                        std::vector<std::uint32_t>& out) {
  return select("overlapping", rect, rects, out, kIntersects,
                simd::orientedRectOverlapsOrientedRects);
}

std::size_t containing(const Vec2f& point, const CircleStream& circles,
                       std::vector<std::uint32_t>& out) {
  return select("containing", point, circles, out, kContains, simd::pointInCircles);
}

std::size_t containing(const Vec2f& point, const RectStream& rects,
                       std::vector<std::uint32_t>& out) {
  return select("containing", point, rects, out, kContains, simd::pointInRects);
}

std::size_t containing(const Vec2f& point, const OrientedRectStream& rects,
                       std::vector<std::uint32_t>& out) {
  return select("containing", point, rects, out, kContains, simd::pointInOrientedRects);
}

}  // namespace simdphys

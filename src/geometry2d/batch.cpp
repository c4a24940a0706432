// 2D batch queries: the reference path loops over the scalar functions; the SIMD kernels mirror
// them.
#include "simdphys/geometry2d/batch.hpp"

#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
// The reference path calls these per element: their definitions, so that they inline.
#include "src/reference/geometry2d/collisions-inl.hpp"
#include "views.hpp"

namespace simdphys {
namespace {

// Runs `kernel` into room for a whole padded stream, or the scalar `test` per element.
template <class Stream, class Test, class Kernel>
std::size_t select(const Stream& stream, std::vector<std::uint32_t>& out, Test test,
                   Kernel kernel) {
  out.clear();
  if (referencePathActive()) {
    for (std::uint32_t i = 0; i < stream.size(); ++i)
      if (test(stream[i])) out.push_back(i);
    return out.size();
  }
  out.resize(stream.padded());  // kernels store whole vectors
  out.resize(kernel(view(stream), out.data()));
  return out.size();
}

// Runs one shape against a stream: validated, then the scalar intersects or the kernel.
template <class Shape, class Stream, class Kernel>
std::size_t overlappingShape(const Shape& shape, const Stream& stream,
                             std::vector<std::uint32_t>& out, Kernel kernel) {
  validate(shape, "overlapping");
  return select(
      stream, out, [&](const auto& element) { return intersects(shape, element); },
      [&](const auto& v, std::uint32_t* o) {
        return kernel(query2d(shape), v, o, simd::Loop::kSimd);
      });
}

template <class Stream, class Kernel>
std::size_t containingPoint(const Vec2f& point, const Stream& stream,
                            std::vector<std::uint32_t>& out, Kernel kernel) {
  validate(point, "containing");
  return select(
      stream, out, [&](const auto& element) { return contains(element, point); },
      [&](const auto& v, std::uint32_t* o) {
        return kernel(query2d(point), v, o, simd::Loop::kSimd);
      });
}

}  // namespace

std::size_t overlapping(const Circle& circle, const CircleStream& circles,
                        std::vector<std::uint32_t>& out) {
  return overlappingShape(circle, circles, out, simd::circleOverlapsCircles);
}

std::size_t overlapping(const Rect& rect, const RectStream& rects,
                        std::vector<std::uint32_t>& out) {
  return overlappingShape(rect, rects, out, simd::rectOverlapsRects);
}

std::size_t overlapping(const OrientedRect& rect, const OrientedRectStream& rects,
                        std::vector<std::uint32_t>& out) {
  return overlappingShape(rect, rects, out, simd::orientedRectOverlapsOrientedRects);
}

std::size_t containing(const Vec2f& point, const CircleStream& circles,
                       std::vector<std::uint32_t>& out) {
  return containingPoint(point, circles, out, simd::pointInCircles);
}

std::size_t containing(const Vec2f& point, const RectStream& rects,
                       std::vector<std::uint32_t>& out) {
  return containingPoint(point, rects, out, simd::pointInRects);
}

std::size_t containing(const Vec2f& point, const OrientedRectStream& rects,
                       std::vector<std::uint32_t>& out) {
  return containingPoint(point, rects, out, simd::pointInOrientedRects);
}

}  // namespace simdphys

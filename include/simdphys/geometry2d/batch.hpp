// Batch forms of the 2D tests: one shape or point against a whole stream, a SIMD vector of
// elements at a time. Each answers exactly as its scalar function (collisions.hpp,
// point_tests.hpp) does for every element, on every path: the kernels mirror its arithmetic
// operation for operation, unfused, so the answers are bit for bit the same even for touching
// shapes, where the tolerance decides.
#pragma once

#include <cstdint>
#include <vector>

#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry2d/streams.hpp"

namespace simdphys {

// The indices (ascending) of the elements that `shape` intersects (closed: touching counts),
// intersects(shape, element) of collisions.hpp, written to `out`; returns their number.
std::size_t overlapping(const Circle& circle, const CircleStream& circles,
                        std::vector<std::uint32_t>& out);
std::size_t overlapping(const Rect& rect, const RectStream& rects, std::vector<std::uint32_t>& out);
// The separating axis theorem on the four face normals, one element per lane.
std::size_t overlapping(const OrientedRect& rect, const OrientedRectStream& rects,
                        std::vector<std::uint32_t>& out);

// The indices (ascending) of the elements that contain `point` (closed), contains(element, point)
// of point_tests.hpp.
std::size_t containing(const Vec2f& point, const CircleStream& circles,
                       std::vector<std::uint32_t>& out);
std::size_t containing(const Vec2f& point, const RectStream& rects,
                       std::vector<std::uint32_t>& out);
std::size_t containing(const Vec2f& point, const OrientedRectStream& rects,
                       std::vector<std::uint32_t>& out);

}  // namespace simdphys

// Streams of 2D primitives: one aligned, padded array per field (StreamSet,
// geometry3d/streams.hpp). Each stream validates what it is given (validate() of
// geometry2d/primitives.hpp) and names the offending element; padding makes padded lanes inert, so
// kernels can run over whole vectors.
#pragma once

#include <cmath>

#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry3d/streams.hpp"

namespace simdphys {

// Circles as centre and radius. Padding: radius -inf, which every test fails.
class CircleStream : public StreamSet<fields::Circle> {
 public:
  void push(const Circle& circle);
  void set(std::size_t i, const Circle& circle);
  Circle operator[](std::size_t i) const { return {{value(0, i), value(1, i)}, value(2, i)}; }
};

// Axis-aligned rectangles as min/max corners, the layout of the exact overlap tests. Padding:
// empty rectangles (min = +inf, max = -inf), which overlap and contain nothing.
class RectStream : public StreamSet<fields::Rect> {
 public:
  void push(const Rect& rect);
  void set(std::size_t i, const Rect& rect);
  Rect operator[](std::size_t i) const {
    return {{value(0, i), value(1, i)}, {value(2, i), value(3, i)}};
  }
};

// Oriented rectangles as centre, half extents and rotation, with the rotation's cosine and sine
// stored beside it: they are computed once on entry, exactly as OrientedRect::axes() computes them
// (std::cos and std::sin of the float angle), so kernels read the same axes the scalar functions
// use without a transcendental per test. Padding: half extents -inf, axes the identity; kernels
// that could make a NaN of it (-inf * 0) mask padded lanes out by the sign of the half extent.
class OrientedRectStream : public StreamSet<fields::OrientedRect> {
 public:
  void push(const OrientedRect& rect);
  void set(std::size_t i, const OrientedRect& rect);
  OrientedRect operator[](std::size_t i) const {
    return {{value(0, i), value(1, i)}, {value(2, i), value(3, i)}, value(6, i)};
  }

 private:
  static std::array<float, 7> fieldsOf(const OrientedRect& r) {
    return {r.center.x(),         r.center.y(),         r.halfExtents.x(), r.halfExtents.y(),
            std::cos(r.rotation), std::sin(r.rotation), r.rotation};
  }
};

}  // namespace simdphys

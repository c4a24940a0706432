// 2D streams and shapes seen through the plain views and queries the SIMD kernels take.
#pragma once

#include "simd/kernels.hpp"
#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry2d/streams.hpp"

namespace simdphys {

inline simd::CirclesView view(const CircleStream& c) {
  return {c.x().data(), c.y().data(), c.r().data(), c.size(), c.padded()};
}

inline simd::RectsView view(const RectStream& r) {
  return {r.minX().data(), r.minY().data(), r.maxX().data(), r.maxY().data(), r.size(), r.padded()};
}

inline simd::OrientedRectsView view(const OrientedRectStream& b) {
  return {b.cx().data(),  b.cy().data(),  b.hx().data(), b.hy().data(),
          b.cos().data(), b.sin().data(), b.size(),      b.padded()};
}

inline simd::CircleQuery2d query2d(const Circle& c) {
  return {c.center.x(), c.center.y(), c.radius, kGeometry2dTolerance<float>};
}

inline simd::RectQuery2d query2d(const Rect& r) {
  return {r.min.x(), r.min.y(), r.max.x(), r.max.y()};
}

// The axes as OrientedRect::axes() computes them: column 0 is (cos, sin).
inline simd::OrientedRectQuery2d query2d(const OrientedRect& b) {
  const Mat2f axes = b.axes();
  return {b.center.x(), b.center.y(), b.halfExtents.x(),          b.halfExtents.y(),
          axes(0, 0),   axes(1, 0),   kGeometry2dTolerance<float>};
}

inline simd::PointQuery2d query2d(const Vec2f& p) {
  return {p.x(), p.y(), kGeometry2dTolerance<float>};
}

}  // namespace simdphys

// What crosses from the library to the kernels: any stream as the one kernel view (view()), and
// single shapes as the kernels' query structs.
#pragma once

#include "simd/kernels.hpp"
#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry2d/streams.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/scene/frustum.hpp"

namespace simdphys {

// Any stream, read-only: its fields in layout order, its size and padded size.
template <class Fields>
core::View<Fields> view(const StreamSet<Fields>& s) {
  core::View<Fields> v{{}, s.size(), s.padded()};
  for (std::size_t f = 0; f < Fields::kCount; ++f) v.field[f] = s.field(f).data();
  return v;
}

// ---- 3D shapes -------------------------------------------------------------------------------

inline simd::ObbQuery obbQuery(const Obb& b) {
  simd::ObbQuery q{};
  for (int k = 0; k < 3; ++k) {
    q.center[k] = b.center[k], q.half[k] = b.halfExtents[k];
    for (int c = 0; c < 3; ++c) q.axis[c][k] = b.axes(k, c);
  }
  q.tolerance = kGeometryTolerance<float>;
  return q;
}

inline simd::Box box(const Aabb& b) {
  return {b.min.x(), b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z()};
}

inline simd::Planes planes(const Frustum& f) {
  simd::Planes p;
  for (int k = 0; k < 6; ++k) {
    p.nx[k] = f.planes[k].normal.x(), p.ny[k] = f.planes[k].normal.y();
    p.nz[k] = f.planes[k].normal.z(), p.d[k] = f.planes[k].d;
  }
  return p;
}

// ---- 2D shapes -------------------------------------------------------------------------------

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

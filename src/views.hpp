// Streams seen through the plain views the SIMD kernels take.
#pragma once

#include "simd/kernels.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/scene.hpp"

namespace simdphys {

inline simd::BoxesView view(const BoxStream& b) {
  return {b.minX().data(), b.minY().data(), b.minZ().data(), b.maxX().data(),
          b.maxY().data(), b.maxZ().data(), b.size(),        b.padded()};
}

inline simd::SpheresView view(const SphereStream& s) {
  return {s.x().data(), s.y().data(), s.z().data(), s.r().data(), s.size(), s.padded()};
}

inline simd::BoundsView view(const BoundsStream& b) {
  return {b.cx().data(), b.cy().data(), b.cz().data(), b.ex().data(),
          b.ey().data(), b.ez().data(), b.size(),      b.padded()};
}

inline simd::TrianglesView view(const TriangleStream& t) {
  simd::TrianglesView v{{}, t.size(), t.padded()};
  for (int q = 0; q < 3; ++q)
    for (int k = 0; k < 3; ++k) v.v[q][k] = t.vertex(q, k).data();
  return v;
}

inline simd::ObbsView view(const ObbStream& o) {
  simd::ObbsView v{{}, {}, {}, o.size(), o.padded()};
  for (int k = 0; k < 3; ++k) {
    v.center[k] = o.center(k).data(), v.half[k] = o.halfExtent(k).data();
    for (int c = 0; c < 3; ++c) v.axis[c][k] = o.axis(c, k).data();
  }
  return v;
}

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

}  // namespace simdphys

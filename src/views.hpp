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

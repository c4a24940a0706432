// Batch queries: the reference path loops over the scalar functions; the SIMD kernels mirror them.
#include "simdphys/geometry3d/batch.hpp"

#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "simdphys/geometry3d/raycast.hpp"
#include "src/core/on_path.hpp"
// The reference path calls these per element: their definitions, so that they inline.
#include "src/reference/geometry3d/intersect-inl.hpp"
#include "src/reference/geometry3d/raycast-inl.hpp"
#include "src/reference/validate-inl.hpp"
#include "src/views.hpp"

namespace simdphys {
namespace {

simd::SphereQuery query(const Sphere& s) {
  return {s.center.x(), s.center.y(), s.center.z(), s.radius, kGeometryTolerance<float>};
}

simd::RayQuery query(const Ray& r, float tMax) {
  return {r.origin.x(),    r.origin.y(),    r.origin.z(), r.direction.x(),
          r.direction.y(), r.direction.z(), tMax};
}

template <class Stream, class Kernel>
ElementHit closest(const Ray& ray, const Stream& stream, float tMax, Kernel kernel) {
  validate(ray, "raycast");
  if (!(tMax >= 0))  // as MeshBvh's: +inf is fine, NaN or negative is a caller's bug
    throw Error("raycast: tMax " + std::to_string(tMax) + " is negative or NaN");
  if (referencePathActive()) {
    ElementHit best;
    for (std::uint32_t i = 0; i < stream.size(); ++i)
      if (auto hit = raycast(stream[i], ray, tMax); hit && (!best.hit() || hit->t < best.t))
        best = {i, hit->t};
    return best;
  }
  return kernel(query(ray, tMax), view(stream));
}

}  // namespace

std::size_t overlapping(const Sphere& s, const SphereStream& spheres,
                        std::vector<std::uint32_t>& out) {
  validate(s, "overlapping");
  return selectOnPath(
      view(spheres), out, [&](std::uint32_t i) { return intersects(s, spheres[i]); },
      [&](const auto& v, std::uint32_t* o) { return simd::sphereOverlapsSpheres(query(s), v, o); });
}

std::size_t overlapping(const Sphere& s, const BoxStream& boxes, std::vector<std::uint32_t>& out) {
  validate(s, "overlapping");
  return selectOnPath(
      view(boxes), out, [&](std::uint32_t i) { return intersects(s, boxes[i]); },
      [&](const auto& v, std::uint32_t* o) { return simd::sphereOverlapsBoxes(query(s), v, o); });
}

std::size_t overlapping(const Obb& box, const ObbStream& boxes, std::vector<std::uint32_t>& out) {
  validate(box, "overlapping");
  return selectOnPath(
      view(boxes), out, [&](std::uint32_t i) { return intersects(box, boxes[i]); },
      [&](const auto& v, std::uint32_t* o) { return simd::obbOverlapsObbs(obbQuery(box), v, o); });
}

std::size_t containing(const Vec3f& p, const BoxStream& boxes, std::vector<std::uint32_t>& out) {
  detail::requireFiniteField(p, "containing", "point");
  return selectOnPath(
      view(boxes), out, [&](std::uint32_t i) { return contains(boxes[i], p); },
      [&](const auto& v, std::uint32_t* o) {
        return simd::pointInBoxes(p.x(), p.y(), p.z(), v, o);
      });
}

void closestPoints(const Vec3f& p, const BoxStream& boxes, PointStream& out) {
  detail::requireFiniteField(p, "closestPoints", "point");
  out.overwrite(boxes.size(), [&](float* x, float* y, float* z) {
    if (!referencePathActive())
      return simd::closestPointsOnBoxes(p.x(), p.y(), p.z(), view(boxes), x, y, z);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const Vec3f q = closestPoint(boxes[i], p);
      x[i] = q.x(), y[i] = q.y(), z[i] = q.z();
    }
  });
}

ElementHit raycast(const Ray& ray, const BoxStream& boxes, float tMax) {
  return closest(ray, boxes, tMax, simd::rayClosestBox);
}

ElementHit raycast(const Ray& ray, const SphereStream& spheres, float tMax) {
  return closest(ray, spheres, tMax, simd::rayClosestSphere);
}

ElementHit raycast(const Ray& ray, const TriangleStream& triangles, float tMax) {
  return closest(ray, triangles, tMax, [](const simd::RayQuery& q, const simd::TrianglesView& v) {
    const WatertightRay w(Vec3f(q.ox, q.oy, q.oz), Vec3f(q.dx, q.dy, q.dz));
    return simd::rayClosestTriangle({q.ox, q.oy, q.oz, w.kx, w.ky, w.kz, w.sx, w.sy, w.sz, q.tMax},
                                    v);
  });
}

}  // namespace simdphys

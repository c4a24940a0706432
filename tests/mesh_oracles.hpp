// Brute-force oracles for the mesh tests: every triangle tested with the scalar functions of
// geometry3d/, no tree. The closest-hit rule is mesh_bvh.hpp's (W2's): the smallest t, then the
// smallest id among the hits within kTieWindow of it.
#pragma once

#include <limits>
#include <vector>

#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/raycast.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "workloads.hpp"

namespace simdphys::test {

// The rule over a list of (t, id) hits.
inline ElementHit closestByRule(const std::vector<ElementHit>& hits) {
  float tMin = std::numeric_limits<float>::infinity();
  for (const ElementHit& h : hits) tMin = std::min(tMin, h.t);
  ElementHit best;
  for (const ElementHit& h : hits)
    if (h.t <= tMin * kTieWindow && h.index < best.index) best = h;
  return best;
}

inline std::vector<ElementHit> allHits(const Mesh& m, const WatertightRay& ray, float tMax) {
  std::vector<ElementHit> hits;
  for (std::uint32_t i = 0; i < m.size(); ++i)
    if (auto h = intersectTriangle(ray, m.triangle(i), tMax)) hits.push_back({i, h->t});
  return hits;
}

inline ElementHit bruteRaycast(const Mesh& m, const Ray& ray,
                               float tMax = std::numeric_limits<float>::infinity()) {
  return closestByRule(allHits(m, WatertightRay(ray.origin, ray.direction), tMax));
}

inline bool bruteOccluded(const Mesh& m, const Ray& ray,
                          float tMax = std::numeric_limits<float>::infinity()) {
  return !allHits(m, WatertightRay(ray.origin, ray.direction), tMax).empty();
}

template <class Shape>
std::vector<std::uint32_t> bruteOverlapping(const Mesh& m, const Shape& shape) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < m.size(); ++i)
    if (intersects(m.triangle(i), shape)) ids.push_back(i);
  return ids;
}

// A soup of n random triangles of edge up to `size` in [-spread, spread]^3 (none degenerate: the
// draw is repeated until the double normal is non-zero).
inline Mesh randomSoup(std::uint64_t seed, std::size_t n, float spread, float size) {
  workloads::Random r(seed);
  Mesh m;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f c(r.uniform(-spread, spread), r.uniform(-spread, spread),
                  r.uniform(-spread, spread));
    Triangle t;
    do {
      t = {c + size * r.unitDirection(), c + size * r.unitDirection(),
           c + size * r.unitDirection()};
    } while ((detail::rays::triangleNormalWide(t).array() == 0).all());
    const auto base = std::uint32_t(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {t.a, t.b, t.c});
    m.triangles.push_back({base, base + 1, base + 2});
  }
  return m;
}

// Rays from random origins in [-reach, reach]^3: random directions, and one in eight along an
// axis (zero direction components: the slab test's NaN case when the origin is on a face).
inline std::vector<Ray> randomRays(std::uint64_t seed, std::size_t n, float reach) {
  workloads::Random r(seed);
  std::vector<Ray> rays;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f o(r.uniform(-reach, reach), r.uniform(-reach, reach), r.uniform(-reach, reach));
    Vec3f d = r.unitDirection();
    if (i % 8 == 0) {
      d = Vec3f::Zero();
      d[i / 8 % 3] = i % 16 == 0 ? 1.0f : -1.0f;
    }
    rays.push_back({o, d});
  }
  return rays;
}

}  // namespace simdphys::test

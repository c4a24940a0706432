#include "rays.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "simdphys/geometry3d/raycast.hpp"
#include "workloads.hpp"

namespace simdphys::workloads {

double heightfieldHeight(double x, double z) {
  return 8 * std::sin(0.07 * x) * std::cos(0.05 * z) + 3 * std::sin(0.31 * x + 0.17 * z);
}

Mesh makeHeightfield(std::uint32_t g) {
  return heightfieldMesh(g, g, -100, 100, -100, 100, heightfieldHeight);
}

namespace {
// W2's normalisation: each component divided by the float square root of the squared length.
Vec3f normalised(const Vec3f& v) {
  const float l = std::sqrt(v.x() * v.x() + v.y() * v.y() + v.z() * v.z());
  return {v.x() / l, v.y() / l, v.z() / l};
}
}  // namespace

RayStream makeCoherentRays(std::uint32_t width, std::uint32_t height) {
  const Vec3f eye(0, 60, -140), target(0, 0, 0), upWorld(0, 1, 0);
  const Vec3f forward = normalised(target - eye);
  const Vec3f right = normalised(forward.cross(upWorld));
  const Vec3f up = right.cross(forward);
  const float t = float(std::tan(30.0 * std::numbers::pi / 180.0));
  const float aspect = float(width) / float(height);
  RayStream rays;
  rays.reserve(std::size_t(width) * height);
  for (std::uint32_t py = 0; py < height; ++py)
    for (std::uint32_t px = 0; px < width; ++px) {
      const float sx = (2 * (float(px) + 0.5f) / float(width) - 1) * t * aspect;
      const float sy = (1 - 2 * (float(py) + 0.5f) / float(height)) * t;
      const Vec3f sRight = sx * right, sUp = sy * up;
      rays.push({eye, normalised(forward + sRight + sUp)});
    }
  return rays;
}

RayStream makeIncoherentRays(std::size_t n) {
  Random r(2);
  RayStream rays;
  rays.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const float x = r.uniform(-100, 100);
    const float y = r.uniform(20, 40);
    const float z = r.uniform(-100, 100);
    rays.push({{x, y, z}, r.unitDirection()});
  }
  return rays;
}

RaysReference summarise(std::span<const ElementHit> hits) {
  RaysReference s{0, 0, 0};
  for (const ElementHit& h : hits)
    if (h.hit()) ++s.hits, s.sumT += double(h.t), s.sumId += h.index;
  return s;
}

namespace {
// Distance from the hit (barycentric weights u, v, w of a, b, c) to the triangle's nearest edge:
// the weight of a vertex times the triangle's height over the opposite edge.
double edgeDistance(const Triangled& tri, const TriangleHitd& h) {
  const double twiceArea = (tri.b - tri.a).cross(tri.c - tri.a).norm();
  return std::min({std::abs(h.u) * twiceArea / (tri.c - tri.b).norm(),
                   std::abs(h.v) * twiceArea / (tri.a - tri.c).norm(),
                   std::abs(h.w) * twiceArea / (tri.b - tri.a).norm()});
}

class GridWalk {
 public:
  GridWalk(const Mesh& mesh, std::uint32_t g, const Ray& ray)
      : mesh_(mesh), g_(g), ray_(ray.origin.cast<double>(), ray.direction.cast<double>()) {}

  ReferenceHit run() {
    const Vec3d o = ray_.origin, d = ray_.direction;
    // The part of the ray inside the grid's box (heights within +-11.5: |y| <= 8 + 3).
    double t0 = 0, t1 = std::numeric_limits<double>::infinity();
    const double lo[3] = {-100, -11.5, -100}, hi[3] = {100, 11.5, 100};
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0) {
        if (o[a] < lo[a] || o[a] > hi[a]) return {};
        continue;
      }
      double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    if (t0 > t1) return {};
    const double cell = 200.0 / (g_ - 1);
    const int last = int(g_) - 2;
    auto cellOf = [&](double p) { return std::clamp(int(std::floor((p + 100) / cell)), 0, last); };
    const Vec3d start = o + t0 * d;
    int i = cellOf(start.x()), j = cellOf(start.z());
    const int si = d.x() > 0 ? 1 : -1, sj = d.z() > 0 ? 1 : -1;
    auto boundary = [&](int c, int step, double oa, double da) {
      if (da == 0) return std::numeric_limits<double>::infinity();
      const double edge = -100 + cell * (c + (step > 0 ? 1 : 0));
      return (edge - oa) / da;
    };
    double nextI = boundary(i, si, o.x(), d.x()), nextJ = boundary(j, sj, o.z(), d.z());
    for (;;) {
      testCell(i, j);
      const double exit = std::min(nextI, nextJ);
      // A later cell's triangles are hit at t >= exit; ties need t within 1e-6 relative.
      if (best_.id != kNoHit && tMin_ * (1 + 1e-6) < exit) break;
      if (exit > t1) break;
      if (nextI == nextJ) {  // through a grid vertex: the diagonal's side cells too
        testCell(i + si, j);
        testCell(i, j + sj);
      }
      if (nextI == exit) i += si;
      if (nextJ == exit) j += sj;
      nextI = boundary(i, si, o.x(), d.x()), nextJ = boundary(j, sj, o.z(), d.z());
      if (i < 0 || j < 0 || i > last || j > last) break;
    }
    return best_;
  }

 private:
  void testCell(int i, int j) {
    if (i < 0 || j < 0 || i > int(g_) - 2 || j > int(g_) - 2) return;
    const std::uint32_t first = 2 * (std::uint32_t(j) * (g_ - 1) + std::uint32_t(i));
    for (std::uint32_t id = first; id < first + 2; ++id) {
      const Triangled tri = cast<double>(mesh_.triangle(id));
      const auto h = intersectTriangle(ray_, tri);
      if (!h) continue;
      offer(h->t, id, edgeDistance(tri, *h));
    }
  }

  // W2's rule over every hit seen: the smallest t, then the smallest id within 1e-6 relative.
  void offer(double t, std::uint32_t id, double edge) {
    hits_.push_back({id, t, edge});
    tMin_ = std::min(tMin_, t);
    best_ = {};
    for (const ReferenceHit& h : hits_)
      if (h.t <= tMin_ * (1 + 1e-6) && (best_.id == kNoHit || h.id < best_.id)) best_ = h;
  }

  const Mesh& mesh_;
  std::uint32_t g_;
  WatertightRayd ray_;
  std::vector<ReferenceHit> hits_;
  double tMin_ = std::numeric_limits<double>::infinity();
  ReferenceHit best_;
};
}  // namespace

ReferenceHit referenceHit(const Mesh& mesh, std::uint32_t g, const Ray& ray) {
  return GridWalk(mesh, g, ray).run();
}

std::vector<ReferenceHit> referenceHits(const Mesh& mesh, std::uint32_t g, const RayStream& rays) {
  std::vector<ReferenceHit> out(rays.size());
#pragma omp parallel for schedule(dynamic, 1024)
  for (std::int64_t i = 0; i < std::int64_t(rays.size()); ++i)
    out[std::size_t(i)] = referenceHit(mesh, g, rays[std::size_t(i)]);
  return out;
}

ReferenceComparison compareWithReference(std::span<const ElementHit> hits,
                                         std::span<const ReferenceHit> reference) {
  ReferenceComparison c;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const ElementHit& h = hits[i];
    const ReferenceHit& r = reference[i];
    if (h.index == r.id) {
      if (h.hit()) c.maxRelativeT = std::max(c.maxRelativeT, std::abs(double(h.t) - r.t) / r.t);
      continue;
    }
    if (r.id != kNoHit && r.edgeDistance < 1e-5)
      ++c.excused;
    else
      ++c.differ;
  }
  return c;
}

}  // namespace simdphys::workloads

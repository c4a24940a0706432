// Batch 3D queries: closest ray hit against a stream of boxes, spheres or triangles, and one OBB
// against a stream of OBBs, on every path, with the error against the same queries in double
// precision.
#include <cmath>

#include "bench_common.hpp"
#include "simdphys/geometry3d/batch.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/raycast.hpp"
#include "testing/kernels.hpp"

namespace simdphys::bench {
namespace {

constexpr std::size_t kRays = 256;

// Rays from seed 3: origins uniform in the W1 cube, random unit directions.
const std::vector<Ray>& rays() {
  static const std::vector<Ray> r = [] {
    workloads::Random rnd(3);
    std::vector<Ray> out;
    for (std::size_t i = 0; i < kRays; ++i) {
      Vec3f o(rnd.uniform(-100, 100), rnd.uniform(-100, 100), rnd.uniform(-100, 100));
      out.push_back({o, rnd.unitDirection()});
    }
    return out;
  }();
  return r;
}

// The W2 heightfield, 129 x 129 vertices (32,768 triangles) so a brute-force batch stays short.
const TriangleStream& triangles() {
  static const TriangleStream t = [] {
    constexpr int g = 129;
    auto vertex = [](int i, int j) {
      double x = -100 + 200.0 * i / (g - 1), z = -100 + 200.0 * j / (g - 1);
      return Vec3f(
          float(x),
          float(8 * std::sin(0.07 * x) * std::cos(0.05 * z) + 3 * std::sin(0.31 * x + 0.17 * z)),
          float(z));
    };
    TriangleStream out;
    for (int j = 0; j + 1 < g; ++j)
      for (int i = 0; i + 1 < g; ++i) {
        out.push({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
        out.push({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
      }
    return out;
  }();
  return t;
}

// The largest |t - t_double| / max(1, t_double) over the rays that hit in both precisions, and
// the number of rays whose hit/miss or element differs from the double query.
template <class Stream, class Get>
void errorAgainstDouble(benchmark::State& state, const Stream& stream, Get elementDouble) {
  double worst = 0;
  int differing = 0;
  for (const Ray& ray : rays()) {
    const auto hit = raycast(ray, stream);
    std::optional<std::pair<std::uint32_t, double>> exact;
    const Rayd rayd = cast<double>(ray);
    for (std::uint32_t i = 0; i < stream.size(); ++i)
      if (auto h = raycast(elementDouble(i), rayd); h && (!exact || h->t < exact->second))
        exact = std::pair{i, h->t};
    if (hit.hit() != exact.has_value() || (hit.hit() && hit.index != exact->first)) {
      ++differing;
      continue;
    }
    if (hit.hit())
      worst = std::max(worst, std::abs(hit.t - exact->second) / std::max(1.0, exact->second));
  }
  state.counters["error"] = worst;
  state.counters["differing"] = differing;
}

template <class Stream, class Get>
void rayBody(benchmark::State& state, const Stream& stream, Get elementDouble) {
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (const Ray& ray : rays()) hits += raycast(ray, stream).hit();
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * rays().size() * stream.size()));
  state.counters["result"] = double(hits);
  errorAgainstDouble(state, stream, elementDouble);
}

// The plain-loop baseline on the forced path: the same rays, the same answers.
template <class Stream, class Kernel>
void autovecBody(benchmark::State& state, const Stream& stream, Kernel kernel) {
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (const Ray& ray : rays()) {
      const simd::RayQuery q{ray.origin.x(),
                             ray.origin.y(),
                             ray.origin.z(),
                             ray.direction.x(),
                             ray.direction.y(),
                             ray.direction.z(),
                             std::numeric_limits<float>::infinity()};
      hits += kernel(q, view(stream)).index != kNoHit;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * rays().size() * stream.size()));
  state.counters["result"] = double(hits);
}

// ---- one OBB against many (docs/workloads.md, "OBBs") ----

constexpr std::size_t kObbQueries = 16, kObbBoxes = 100'000;

Mat3f randomRotation(workloads::Random& rnd) {
  const Vec3f axis = rnd.unitDirection();
  return axisAngle(axis, rnd.uniform(0, 3.14159265f));
}

// Braces: list-initialisation evaluates the draws left to right (a constructor's arguments, in
// parentheses, in an unspecified order), so the workload is the same with every compiler.
Obb randomObb(workloads::Random& rnd, float spread, float minHalf, float maxHalf) {
  const Vec3f c{rnd.uniform(-spread, spread), rnd.uniform(-spread, spread),
                rnd.uniform(-spread, spread)};
  const Vec3f h{rnd.uniform(minHalf, maxHalf), rnd.uniform(minHalf, maxHalf),
                rnd.uniform(minHalf, maxHalf)};
  return {c, h, randomRotation(rnd)};
}

// Seed 9: 100,000 boxes in [-10, 10]^3, half extents 0.1 to 1.5, then 16 queries in [-5, 5]^3,
// half extents 0.5 to 3; every orientation a random axis and angle.
struct ObbWorkload {
  ObbStream boxes;
  std::vector<Obb> queries;
  std::uint64_t overlaps = 0;   // scalar intersects(), float: what every path must find
  std::uint64_t checksum = 0;   // sum of q * N + i over the overlapping pairs
  std::uint64_t differing = 0;  // pairs whose float answer differs from intersects() in double
};

const ObbWorkload& obbWorkload() {
  static const ObbWorkload w = [] {
    workloads::Random rnd(9);
    ObbWorkload out;
    for (std::size_t i = 0; i < kObbBoxes; ++i) out.boxes.push(randomObb(rnd, 10, 0.1f, 1.5f));
    for (std::size_t q = 0; q < kObbQueries; ++q) out.queries.push_back(randomObb(rnd, 5, 0.5f, 3));
    const std::size_t n = out.boxes.size();
    for (std::size_t q = 0; q < kObbQueries; ++q)
      for (std::size_t i = 0; i < n; ++i) {
        const bool hit = intersects(out.queries[q], out.boxes[i]);
        out.overlaps += hit;
        out.checksum += hit ? q * n + i : 0;
        out.differing +=
            hit != intersects(cast<double>(out.queries[q]), cast<double>(out.boxes[i]));
      }
    return out;
  }();
  return w;
}

// Runs `find(query, out)` for every query, then checks the pairs against the scalar test's.
template <class Find>
void obbBody(benchmark::State& state, Find find) {
  const ObbWorkload& w = obbWorkload();
  std::vector<std::uint32_t> out;
  std::uint64_t overlaps = 0;
  for (auto _ : state) {
    overlaps = 0;
    for (const Obb& q : w.queries) overlaps += find(q, out);
    benchmark::DoNotOptimize(overlaps);
  }
  std::uint64_t checksum = 0;
  for (std::size_t q = 0; q < w.queries.size(); ++q) {
    const std::size_t found = find(w.queries[q], out);
    for (std::size_t k = 0; k < found; ++k) checksum += q * w.boxes.size() + out[k];
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * w.queries.size() * w.boxes.size()));
  if (!checkExact(state, overlaps, w.overlaps)) return;
  if (checksum != w.checksum) state.SkipWithError("the pairs differ from the scalar test's");
  state.counters["differing"] = double(w.differing);  // the same on every path: bit-identical
}

}  // namespace

void registerGeometry3dBenchmarks() {
  registerPerPath("obb_obbs", "sat", kObbBoxes, [](benchmark::State& state) {
    obbBody(state, [](const Obb& q, std::vector<std::uint32_t>& out) {
      return overlapping(q, obbWorkload().boxes, out);
    });
  });
  registerPerPath(
      "obb_obbs", "autovec", kObbBoxes,
      [](benchmark::State& state) {
        obbBody(state, [](const Obb& q, std::vector<std::uint32_t>& out) {
          out.resize(obbWorkload().boxes.padded());
          return simd::obbOverlapsObbsAutovec(obbQuery(q), view(obbWorkload().boxes), out.data());
        });
      },
      false);

  const auto& boxes = aabbWorkload(100'000).boxes;
  registerPerPath("ray_boxes", "closest", boxes.size(), [&boxes](benchmark::State& state) {
    rayBody(state, boxes, [&](std::uint32_t i) { return cast<double>(boxes[i]); });
  });
  registerPerPath("ray_spheres", "closest", sphereField().size(), [](benchmark::State& state) {
    rayBody(state, sphereField(), [](std::uint32_t i) { return cast<double>(sphereField()[i]); });
  });
  registerPerPath(
      "ray_boxes", "autovec", boxes.size(),
      [&boxes](benchmark::State& state) { autovecBody(state, boxes, simd::rayClosestBoxAutovec); },
      false);
  registerPerPath(
      "ray_spheres", "autovec", sphereField().size(),
      [](benchmark::State& state) {
        autovecBody(state, sphereField(), simd::rayClosestSphereAutovec);
      },
      false);
  registerPerPath("ray_triangles", "closest", triangles().size(), [](benchmark::State& state) {
    rayBody(state, triangles(), [](std::uint32_t i) { return cast<double>(triangles()[i]); });
  });
  registerPerPath(
      "ray_triangles", "autovec", triangles().size(),
      [](benchmark::State& state) {
        autovecBody(state, triangles(), [](const simd::RayQuery& q, const simd::TrianglesView& v) {
          const WatertightRay w(Vec3f(q.ox, q.oy, q.oz), Vec3f(q.dx, q.dy, q.dz));
          return simd::rayClosestTriangleAutovec(
              {q.ox, q.oy, q.oz, w.kx, w.ky, w.kz, w.sx, w.sy, w.sz, q.tMax}, v);
        });
      },
      false);
}

}  // namespace simdphys::bench

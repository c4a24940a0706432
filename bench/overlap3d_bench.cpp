// Batch 3D overlap queries: one sphere against 100,000 spheres or boxes, one point against
// 100,000 boxes, and the closest points of 100,000 boxes to a point; every path, the scalar
// reference path, and the plain-loop baseline. Every path must find exactly what the scalar
// functions find (checked); beside the speed, how many answers differ from the same test in
// double.
#include <algorithm>
#include <cmath>

#include "bench_common.hpp"
#include "simdphys/geometry3d/batch.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "testing/kernels.hpp"

namespace simdphys::bench {
namespace {

constexpr std::size_t kQueries = 64;

// Seed 11: query spheres with centres in the W1 cube and radii in [2, 10] (a few dozen
// spheres or boxes each), and query points in the same cube.
struct Queries {
  std::vector<Sphere> spheres;
  std::vector<Vec3f> points;
};
const Queries& queries() {
  static const Queries q = [] {
    workloads::Random rnd(11);
    Queries out;
    for (std::size_t i = 0; i < kQueries; ++i) {
      const Vec3f c(rnd.uniform(-100, 100), rnd.uniform(-100, 100), rnd.uniform(-100, 100));
      out.spheres.push_back({c, rnd.uniform(2.0f, 10.0f)});
      out.points.emplace_back(rnd.uniform(-100, 100), rnd.uniform(-100, 100),
                              rnd.uniform(-100, 100));
    }
    return out;
  }();
  return q;
}

// What the scalar functions find, in float (every path must match it: count and sum of indices)
// and how many (query, element) answers differ from the same function in double.
struct Expected {
  std::uint64_t count = 0, indexSum = 0, differing = 0;
};
template <class Q, class Stream>
Expected expected(const std::vector<Q>& qs, const Stream& stream) {
  Expected e;
  for (const Q& q : qs)
    for (std::uint32_t i = 0; i < stream.size(); ++i) {
      bool hit, exact;
      if constexpr (std::is_same_v<Q, Vec3f>) {
        hit = contains(stream[i], q);
        exact = contains(cast<double>(stream[i]), Vec3d(q.template cast<double>()));
      } else {
        hit = intersects(q, stream[i]);
        exact = intersects(cast<double>(q), cast<double>(stream[i]));
      }
      e.count += hit, e.indexSum += hit ? i : 0, e.differing += hit != exact;
    }
  return e;
}

// Runs find(query, out) for every query; checks count and index sum against `e`.
template <class Q, class Find>
void overlapBody(benchmark::State& state, const std::vector<Q>& qs, std::size_t n,
                 const Expected& e, Find find) {
  std::vector<std::uint32_t> out;
  std::uint64_t count = 0;
  for (auto _ : state) {
    count = 0;
    for (const Q& q : qs) count += find(q, out);
    benchmark::DoNotOptimize(count);
  }
  std::uint64_t indexSum = 0;
  for (const Q& q : qs) {
    const std::size_t found = find(q, out);
    for (std::size_t k = 0; k < found; ++k) indexSum += out[k];
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * qs.size() * n));
  if (!checkExact(state, count, e.count)) return;
  if (indexSum != e.indexSum) state.SkipWithError("the indices differ from the scalar tests'");
  state.counters["differing"] = double(e.differing);
}

simd::SphereQuery sphereQuery(const Sphere& s) {
  return {s.center.x(), s.center.y(), s.center.z(), s.radius, kGeometryTolerance<float>};
}

// Registers the batch (every path and the reference) and its plain loop (every path).
template <class Q, class Stream, class Batch, class Plain>
void registerOverlap(const std::string& task, const std::vector<Q>& qs, const Stream& stream,
                     Batch batch, Plain plain) {
  const std::size_t n = stream.size();
  registerPerPath(task, "batch", n, [&qs, &stream, batch, n](benchmark::State& state) {
    static const Expected e = expected(qs, stream);
    overlapBody(state, qs, n, e,
                [&](const Q& q, std::vector<std::uint32_t>& out) { return batch(q, stream, out); });
  });
  registerPerPath(
      task, "autovec", n,
      [&qs, &stream, plain, n](benchmark::State& state) {
        static const Expected e = expected(qs, stream);
        overlapBody(state, qs, n, e, [&](const Q& q, std::vector<std::uint32_t>& out) {
          out.resize(stream.padded());
          return plain(q, view(stream), out.data());
        });
      },
      false);
}

// Closest points: every box's clamp of the point; the answer is exact (a clamp rounds nothing),
// so the check is bit equality with the scalar closestPoint and the error against double is 0.
template <class Fill>
void closestBody(benchmark::State& state, Fill fill) {
  const BoxStream& boxes = aabbWorkload(100'000).boxes;
  PointStream out;
  for (auto _ : state) {
    for (const Vec3f& p : queries().points) fill(p, boxes, out);
    benchmark::DoNotOptimize(out.field(fields::Point::x).data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kQueries * boxes.size()));
  std::uint64_t differing = 0;
  for (const Vec3f& p : queries().points) {
    fill(p, boxes, out);
    for (std::size_t i = 0; i < boxes.size(); ++i) differing += out[i] != closestPoint(boxes[i], p);
  }
  if (differing != 0) state.SkipWithError("closest points differ from the scalar function's");
  state.counters["differing"] = 0;
}

}  // namespace

void registerOverlap3dBenchmarks() {
  const Queries& q = queries();
  const BoxStream& boxes = aabbWorkload(100'000).boxes;
  registerOverlap(
      "sphere_spheres", q.spheres, sphereField(),
      [](const Sphere& s, const SphereStream& v, auto& out) { return overlapping(s, v, out); },
      [](const Sphere& s, const simd::SpheresView& v, std::uint32_t* out) {
        return simd::sphereOverlapsSpheresAutovec(sphereQuery(s), v, out);
      });
  registerOverlap(
      "sphere_boxes", q.spheres, boxes,
      [](const Sphere& s, const BoxStream& v, auto& out) { return overlapping(s, v, out); },
      [](const Sphere& s, const simd::BoxesView& v, std::uint32_t* out) {
        return simd::sphereOverlapsBoxesAutovec(sphereQuery(s), v, out);
      });
  registerOverlap(
      "point_boxes", q.points, boxes,
      [](const Vec3f& p, const BoxStream& v, auto& out) { return containing(p, v, out); },
      [](const Vec3f& p, const simd::BoxesView& v, std::uint32_t* out) {
        return simd::pointInBoxesAutovec(p.x(), p.y(), p.z(), v, out);
      });
  registerPerPath("closest_boxes", "batch", boxes.size(), [](benchmark::State& state) {
    closestBody(state, [](const Vec3f& p, const BoxStream& b, PointStream& out) {
      closestPoints(p, b, out);
    });
  });
  registerPerPath(
      "closest_boxes", "autovec", boxes.size(),
      [](benchmark::State& state) {
        closestBody(state, [](const Vec3f& p, const BoxStream& b, PointStream& out) {
          out.overwrite(b.size(), [&](float* x, float* y, float* z) {
            simd::closestPointsOnBoxesAutovec(p.x(), p.y(), p.z(), view(b), x, y, z);
          });
        });
      },
      false);
}

}  // namespace simdphys::bench

// W7, the 2D shapes: the broadphase methods (sweep and prune, brute force, quadtree) from 100 to
// 100,000 shapes, the narrowphase of their candidate pairs, and the batch kernels (one shape or
// point against a stream) per path beside the reference path and the plain-loop baseline.
#include <functional>
#include <map>
#include <memory>

#include "bench_common.hpp"
#include "simdphys/geometry2d/batch.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "testing/kernels.hpp"
#include "testing/pairs.hpp"

namespace simdphys::bench {
namespace {

constexpr std::size_t kSizes[] = {100, 300, 1'000, 3'000, 10'000, 30'000, 100'000};
// The reference path's brute force stops here: beyond, one run takes many seconds.
constexpr std::size_t kMaxReferenceBrute = 30'000;
constexpr std::size_t kKernelShapes = 100'000;

const workloads::Shapes2dWorkload& shapes2dWorkload(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<workloads::Shapes2dWorkload>> cache;
  auto& w = cache[n];
  if (!w) w = std::make_unique<workloads::Shapes2dWorkload>(workloads::makeShapes2dWorkload(n));
  return *w;
}

// Times a persistent finder (as a world steps it) on the active path; items are the pairs found,
// so items_per_second is pairs per second.
template <class Finder = PairFinder2d, class Find>
void pairsBody(benchmark::State& state, std::size_t n, Find find) {
  const auto& w = shapes2dWorkload(n);
  const auto& ref = workloads::shapes2dReference(n);
  Finder finder;
  std::vector<Pair> pairs;
  find(finder, w.bounds, pairs);  // warm-up: the scratch memory reaches its size
  for (auto _ : state) {
    find(finder, w.bounds, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * pairs.size()));
  state.counters["shapes_per_second"] =
      benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["colliding"] = double(workloads::collidingPairs(w, pairs));
  state.counters["colliding_ok"] = state.counters["colliding"] == double(ref.collidingPairs);
  checkExact(state, pairs.size(), ref.boundPairs);
}

// Every path and the plain loops at W7's size; the crossover sizes on the best path only (the
// choice between methods does not depend on the path).
void registerPairs(std::size_t n) {
  const std::pair<const char*, PairMethod2d> methods[] = {
      {"banded_sweep", PairMethod2d::kBandedSweep},
      {"sweep", PairMethod2d::kSweep},
      {"brute", PairMethod2d::kBrute}};
  const bool everyPath = n == 100'000;  // W7's size in docs/workloads.md
  for (auto [name, method] : methods) {
    const auto body = [n, m = method](benchmark::State& state) {
      pairsBody(state, n, [m](PairFinder2d& f, const RectStream& r, std::vector<Pair>& p) {
        f.find(r, p, m);
      });
    };
    if (!everyPath) {
      registerBestPath("pairs2d", name, n, body);
      continue;
    }
    registerPerPath("pairs2d", name, n, body,
                    method != PairMethod2d::kBrute || n <= kMaxReferenceBrute);
    registerPerPath(
        "pairs2d", std::string(name) + "_autovec", n,
        [n, m = method](benchmark::State& state) {
          pairsBody<test::PlainLoopPairFinder2d>(
              state, n,
              [m](test::PlainLoopPairFinder2d& f, const RectStream& r, std::vector<Pair>& p) {
                f.find(r, p, m);
              });
        },
        false);
  }
  registerOnce("pairs2d", "quadtree", "scalar", n, [n](benchmark::State& state) {
    pairsBody(state, n, [](PairFinder2d& f, const RectStream& r, std::vector<Pair>& p) {
      f.find(r, p, PairMethod2d::kQuadtree);
    });
  });
  // The narrowphase after the broadphase: intersects() on each candidate pair's shapes.
  registerOnce("narrow2d", "intersects", "scalar", n, [n](benchmark::State& state) {
    const auto& w = shapes2dWorkload(n);
    std::vector<Pair> candidates;
    findPairs(w.bounds, candidates);
    std::uint64_t colliding = 0;
    for (auto _ : state)
      benchmark::DoNotOptimize(colliding = workloads::collidingPairs(w, candidates));
    state.SetItemsProcessed(std::int64_t(state.iterations() * candidates.size()));
    checkExact(state, colliding, workloads::shapes2dReference(n).collidingPairs);
  });
}

// ---- batch kernels ------------------------------------------------------------------------------

using Ids = std::vector<std::uint32_t>;

// One kernel's runs: every query through the public API (the active path), or through the plain
// loop compiled for the active target. Both return the total number of hits.
struct KernelCase {
  std::string task;
  std::size_t streamSize, queries;
  std::function<std::uint64_t()> api, autovec;
};

template <class Query, class Stream, class Kernel>
KernelCase kernelCase(std::string task, std::vector<Query> queries, const Stream& stream,
                      Kernel kernel) {
  auto out = std::make_shared<Ids>();
  KernelCase k{std::move(task), stream.size(), queries.size(), {}, {}};
  k.api = [queries, &stream, out] {
    std::uint64_t hits = 0;
    for (const Query& q : queries) {
      if constexpr (std::is_same_v<Query, Vec2f>)
        hits += containing(q, stream, *out);
      else
        hits += overlapping(q, stream, *out);
    }
    return hits;
  };
  k.autovec = [queries, &stream, out, kernel] {
    std::uint64_t hits = 0;
    out->resize(stream.padded());
    for (const Query& q : queries) hits += kernel(query2d(q), view(stream), out->data());
    return hits;
  };
  return k;
}

std::vector<KernelCase> kernelCases() {
  const auto& w = shapes2dWorkload(kKernelShapes);
  std::vector<Rect> rects;
  std::vector<Vec2f> points;
  for (const Circle& c : w.queryCircles)
    rects.push_back(boundingRect(c)), points.push_back(c.center);
  for (const OrientedRect& b : w.queryOrientedRects)
    rects.push_back(boundingRect(b)), points.push_back(b.center);
  return {
      kernelCase("circle_circles", w.queryCircles, w.circles, simd::circleOverlapsCirclesAutovec),
      kernelCase("rect_rects", rects, w.bounds, simd::rectOverlapsRectsAutovec),
      kernelCase("orect_orects", w.queryOrientedRects, w.orientedRects,
                 simd::orientedRectOverlapsOrientedRectsAutovec),
      kernelCase("point_circles", points, w.circles, simd::pointInCirclesAutovec),
      kernelCase("point_rects", points, w.bounds, simd::pointInRectsAutovec),
      kernelCase("point_orects", points, w.orientedRects, simd::pointInOrientedRectsAutovec),
  };
}

void kernelBody(benchmark::State& state, const KernelCase& k,
                const std::function<std::uint64_t()>& run) {
  // The expected total is the reference path's, computed once: every path must equal it.
  static std::map<std::string, std::uint64_t> expected;
  if (!expected.count(k.task)) {
    ScopedPath reference("reference");
    expected[k.task] = k.api();
  }
  std::uint64_t hits = 0;
  for (auto _ : state) benchmark::DoNotOptimize(hits = run());
  state.SetItemsProcessed(std::int64_t(state.iterations() * k.queries * k.streamSize));
  state.counters["queries"] = double(k.queries);
  checkExact(state, hits, expected[k.task]);
}

void registerKernels() {
  static const std::vector<KernelCase> cases = kernelCases();
  for (const KernelCase& k : cases) {
    registerPerPath("batch2d_" + k.task, "batch", k.streamSize,
                    [&k](benchmark::State& state) { kernelBody(state, k, k.api); });
    registerPerPath(
        "batch2d_" + k.task, "autovec", k.streamSize,
        [&k](benchmark::State& state) { kernelBody(state, k, k.autovec); }, false);
  }
}

}  // namespace

void registerGeometry2dBenchmarks() {
  for (std::size_t n : kSizes) registerPairs(n);
  registerKernels();
}

}  // namespace simdphys::bench

// W1: batched box queries (tree and brute force) and broadphase pairs.
#include "bench_common.hpp"
#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"
#include "testing/kernels.hpp"
#include "testing/pairs.hpp"

namespace simdphys::bench {
namespace {

constexpr std::size_t kSizes[] = {100'000, 1'000'000};

void queryTests(benchmark::State& state, std::size_t n, std::size_t q) {
  state.SetItemsProcessed(std::int64_t(state.iterations() * n * q));
}

void registerQueries(std::size_t n) {
  registerPerPath("aabb_query", "bvh", n, [n](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    const Bvh tree(w.boxes);
    std::uint64_t count = 0;
    for (auto _ : state) benchmark::DoNotOptimize(count = tree.countOverlaps(w.queries));
    queryTests(state, n, w.queries.size());
    checkExact(state, count, aabbReference(n).queryOverlaps);
  });
  registerPerPath("aabb_query", "brute", n, [n](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    std::uint64_t count = 0;
    for (auto _ : state) benchmark::DoNotOptimize(count = countOverlapsBrute(w.boxes, w.queries));
    queryTests(state, n, w.queries.size());
    checkExact(state, count, aabbReference(n).queryOverlaps);
  });
  registerPerPath(
      "aabb_query", "autovec", n,
      [n](benchmark::State& state) {
        const auto& w = aabbWorkload(n);
        std::vector<simd::Box> qs;
        for (const Aabb& q : w.queries) qs.push_back(box(q));
        std::uint64_t count = 0;
        for (auto _ : state)
          benchmark::DoNotOptimize(
              count = simd::countOverlapsBruteAutovec(view(w.boxes), qs.data(), qs.size()));
        queryTests(state, n, w.queries.size());
        checkExact(state, count, aabbReference(n).queryOverlaps);
      },
      false);
  registerBestPath("aabb_build", "sah", n, [n](benchmark::State& state) {
    const auto& w = aabbWorkload(n);
    Bvh tree;
    for (auto _ : state) {
      tree.build(w.boxes);
      benchmark::DoNotOptimize(tree.nodes().data());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * n));
    state.counters["nodes"] = double(tree.nodes().size());
    state.counters["depth"] = tree.depth();
  });
}

// Times a persistent PairFinder (as a world steps it), so allocation is not what is measured.
template <class Finder = PairFinder, class FindPairs>
void pairsBody(benchmark::State& state, std::size_t n, FindPairs findPairsNow) {
  const auto& w = aabbWorkload(n);
  const auto& ref = aabbReference(n);
  std::vector<Pair> pairs;
  Finder finder;
  findPairsNow(finder, w.boxes, pairs);  // warm-up: the scratch memory reaches its size
  for (auto _ : state) {
    findPairsNow(finder, w.boxes, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * n));
  state.counters["checksum_ok"] = workloads::pairChecksum(pairs, n) == ref.checksum ? 1 : 0;
  checkExact(state, pairs.size(), ref.pairs);
}

void registerPairs(std::size_t n) {
  const std::pair<const char*, PairMethod> methods[] = {
      {"grid", PairMethod::kGridSweep}, {"sweep", PairMethod::kSweep}, {"bvh", PairMethod::kBvh}};
  for (auto [name, method] : methods) {
    auto body = [n, m = method](benchmark::State& state) {
      pairsBody(state, n,
                [m](PairFinder& f, const BoxStream& b, std::vector<Pair>& p) { f.find(b, p, m); });
    };
    // The default method on every path; the others, for choosing it, on the best path.
    if (method == PairMethod::kGridSweep)
      registerPerPath("aabb_pairs", name, n, body);
    else
      registerBestPath("aabb_pairs", name, n, body);
  }
  registerPerPath(
      "aabb_pairs", "autovec", n,
      [n](benchmark::State& state) {
        pairsBody<test::PlainLoopPairFinder>(
            state, n, [](test::PlainLoopPairFinder& f, const BoxStream& b, std::vector<Pair>& p) {
              f.find(b, p, PairMethod::kGridSweep);
            });
      },
      false);
}

}  // namespace

void registerAabbBenchmarks() {
  for (std::size_t n : kSizes) registerQueries(n);
  for (std::size_t n : kSizes) registerPairs(n);
}

}  // namespace simdphys::bench

// W6 through the scene's structures: the 1,000,000 boxes culled through the octree (its leaves on
// each path) and through the top-level BVH, beside the flat batch cull of cull_bench.cpp
// (cull_boxes/planes), and what building each structure costs.
#include "bench_common.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/scene/octree.hpp"

namespace simdphys::bench {
namespace {

BoxStream minMaxBoxes() {
  const BoundsStream& b = cullWorkload().boxes;
  BoxStream out;
  out.reserve(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) out.push(b[i]);
  return out;
}

const Octree& w6Octree() {
  static const Octree tree(cullWorkload().boxes);
  return tree;
}

const Bvh& w6Bvh() {
  static const Bvh tree(minMaxBoxes());
  return tree;
}

template <class Cull>
void cullBody(benchmark::State& state, Cull cullNow) {
  const auto& w = cullWorkload();
  std::vector<std::uint32_t> visible;
  for (auto _ : state) {
    cullNow(w, visible);
    benchmark::DoNotOptimize(visible.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * w.boxes.size()));
  checkExact(state, visible.size(), workloads::kCullBoxesVisible);
}

}  // namespace

void registerSceneBenchmarks() {
  const std::size_t n = cullWorkload().boxes.size();
  registerPerPath("cull_boxes", "octree", n, [](benchmark::State& state) {
    const Octree& tree = w6Octree();
    cullBody(state, [&](const auto& w, auto& v) { tree.cull(w.frustum, v); });
    state.counters["nodes"] = double(tree.nodeCount());
    state.counters["entries"] = double(tree.entryCount());
  });
  // The BVH traversal is scalar code whatever the path (its leaves are single boxes).
  registerOnce("cull_boxes", "bvh", "scalar", n, [](benchmark::State& state) {
    const Bvh& tree = w6Bvh();
    cullBody(state, [&](const auto& w, auto& v) { cull(w.frustum, tree, w.boxes, v); });
  });
  registerOnce("scene_build", "octree", "scalar", n, [](benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(Octree(cullWorkload().boxes).nodeCount());
    state.SetItemsProcessed(std::int64_t(state.iterations() * cullWorkload().boxes.size()));
  });
  registerBestPath("scene_build", "bvh", n, [](benchmark::State& state) {
    const BoxStream boxes = minMaxBoxes();
    for (auto _ : state) benchmark::DoNotOptimize(Bvh(boxes).nodes().size());
    state.SetItemsProcessed(std::int64_t(state.iterations() * boxes.size()));
  });
}

}  // namespace simdphys::bench

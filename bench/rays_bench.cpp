// W2: closest-hit rays against the heightfield through the mesh BVH, per path (the reference
// path is the scalar traversal over the same tree), and the tree's build time.
#include "rays_common.hpp"

namespace simdphys::bench {
namespace {

void registerRays() {
  for (RaysKind kind : kRaysKinds) {
    registerPerPath(raysTask(kind), "bvh", raysCount(kind), [kind](benchmark::State& state) {
      const RaySet& set = raySet(kind);
      const MeshBvh& bvh = raysMeshBvh();
      std::vector<MeshHit> hits(set.rays.size());
      for (auto _ : state) {
        bvh.raycast(set.rays, hits);
        benchmark::DoNotOptimize(hits.data());
      }
      reportRays(state, set, hits);
    });
  }
  registerOnce("rays/build", "sah", "scalar", kRaysTriangles, [](benchmark::State& state) {
    std::unique_ptr<MeshBvh> bvh;
    for (auto _ : state) {
      bvh = std::make_unique<MeshBvh>(raysWorkload().mesh);
      benchmark::DoNotOptimize(bvh.get());
    }
    state.SetItemsProcessed(std::int64_t(state.iterations() * raysWorkload().mesh.size()));
    state.counters["nodes"] = double(bvh->bvh().nodes().size());
    state.counters["blocks"] = double(bvh->blocks().size());
    state.counters["depth"] = bvh->bvh().depth();
  });
}

// Registered at start-up like Google Benchmark's own BENCHMARK macros, so the runner needs no
// line for it.
const bool kRegistered = (registerRays(), true);

}  // namespace
}  // namespace simdphys::bench

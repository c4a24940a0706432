// W2: closest-hit rays against the heightfield through the mesh BVH, per path (the reference
// path is the scalar traversal over the same tree), and the tree's build time.
#include "rays_common.hpp"

namespace simdphys::bench {
namespace {

// Traversal modes (RayStreamOptions): "bvh" one ray at a time; "auto" the default options (the
// stream's consecutive rays as packets where they share an octant); "packet16" and "packet8"
// packets of the image's 4 x 4 and 4 x 2 tiles (as Embree's rtcIntersect16 run), coherent set only.
struct RaysMethod {
  const char* name;
  RayStreamOptions options;
  bool coherentOnly;
};
const RaysMethod kRaysMethods[] = {
    {"bvh", {RayStreamOptions::Mode::kSingle, 0, 0}, false},
    {"auto", {}, false},
    {"packet16", {RayStreamOptions::Mode::kPackets, 16, workloads::kCameraWidth}, true},
    {"packet8", {RayStreamOptions::Mode::kPackets, 8, workloads::kCameraWidth}, true},
};

void registerRays() {
  for (RaysKind kind : kRaysKinds)
    for (const RaysMethod& m : kRaysMethods) {
      if (m.coherentOnly && kind != RaysKind::kCoherent) continue;
      const RayStreamOptions options = m.options;
      registerPerPath(
          raysTask(kind), m.name, raysCount(kind),
          [kind, options](benchmark::State& state) {
            const RaySet& set = raySet(kind);
            const MeshBvh& bvh = raysMeshBvh();
            std::vector<ElementHit> hits(set.rays.size());
            for (auto _ : state) {
              bvh.raycast(set.rays, hits, options);
              benchmark::DoNotOptimize(hits.data());
            }
            reportRays(state, set, hits);
          },
          /*withReference=*/options.mode == RayStreamOptions::Mode::kSingle);  // no packets there
    }
  // The builder's binning and partitioning run on the path's SIMD target (128-bit rows on all).
  registerPerPath(
      "rays/build", "sah", kRaysTriangles,
      [](benchmark::State& state) {
        std::unique_ptr<MeshBvh> bvh;
        for (auto _ : state) {
          // As Embree's build is timed: the mesh's copy (moved in) and the previous tree's release
          // are not; validation, bounds, the tree and its triangle blocks are.
          state.PauseTiming();
          bvh.reset();
          Mesh mesh = raysWorkload().mesh;
          state.ResumeTiming();
          bvh = std::make_unique<MeshBvh>(std::move(mesh));
          benchmark::DoNotOptimize(bvh.get());
        }
        state.SetItemsProcessed(std::int64_t(state.iterations() * raysWorkload().mesh.size()));
        state.counters["nodes"] = double(bvh->bvh().nodes().size());
        state.counters["blocks"] = double(bvh->blocks().size());
        state.counters["depth"] = bvh->bvh().depth();
      },
      /*withReference=*/false);  // the build has no reference variant
}

// Registered at start-up like Google Benchmark's own BENCHMARK macros, so the runner needs no
// line for it.
const bool kRegistered = (registerRays(), true);

}  // namespace
}  // namespace simdphys::bench

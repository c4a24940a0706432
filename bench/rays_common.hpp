// W2 `rays` for the benchmarks and their peers: the workload generated once, and the checks
// every run reports against WORKLOADS.md's figures and the double-precision grid walk.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "rays.hpp"
#include "simdphys/mesh_bvh.hpp"

namespace simdphys::bench {

struct RaySet {
  const char* task;  // "rays/coherent", "rays/incoherent"
  RayStream rays;
  workloads::RaysReference figures;
  std::vector<workloads::ReferenceHit> reference;  // the double walk, per ray
};

struct RaysWorkload {
  Mesh mesh;
  RaySet coherent, incoherent;
};

inline const RaysWorkload& raysWorkload() {
  static const std::unique_ptr<RaysWorkload> w = [] {
    auto p = std::make_unique<RaysWorkload>();
    p->mesh = workloads::makeHeightfield();
    p->coherent = {
        "rays/coherent", workloads::makeCoherentRays(), workloads::kCoherentReference, {}};
    p->incoherent = {
        "rays/incoherent", workloads::makeIncoherentRays(), workloads::kIncoherentReference, {}};
    for (RaySet* s : {&p->coherent, &p->incoherent})
      s->reference = workloads::referenceHits(p->mesh, workloads::kRaysGrid, s->rays);
    return p;
  }();
  return *w;
}

// The two sets by name, with their sizes known without generating them (registration is cheap).
enum class RaysKind { kCoherent, kIncoherent };
inline constexpr RaysKind kRaysKinds[] = {RaysKind::kCoherent, RaysKind::kIncoherent};
inline const char* raysTask(RaysKind k) {
  return k == RaysKind::kCoherent ? "rays/coherent" : "rays/incoherent";
}
inline std::size_t raysCount(RaysKind k) {
  return k == RaysKind::kCoherent ? std::size_t(workloads::kCameraWidth) * workloads::kCameraHeight
                                  : workloads::kIncoherentRays;
}
inline const RaySet& raySet(RaysKind k) {
  return k == RaysKind::kCoherent ? raysWorkload().coherent : raysWorkload().incoherent;
}
inline constexpr std::size_t kRaysTriangles =
    2 * std::size_t(workloads::kRaysGrid - 1) * (workloads::kRaysGrid - 1);

inline const MeshBvh& raysMeshBvh() {
  static const MeshBvh bvh(raysWorkload().mesh);
  return bvh;
}

// Throughput and the checks: hits must equal the figure (else the run fails; for a peer, which
// is measured whatever it answers, `exact` is 0 and hits_missing says by how much); sum t and
// sum id are reported beside their figures; `differ` counts the rays whose answer differs from the
// double reference beyond W2's excuse (hit within 1e-5 of an edge), `excused` the others.
inline void reportRays(benchmark::State& state, const RaySet& set, std::span<const ElementHit> hits,
                       bool peer = false) {
  const double n = double(set.rays.size());
  state.SetItemsProcessed(std::int64_t(state.iterations() * set.rays.size()));
  state.counters["Mrays_per_s"] =
      benchmark::Counter(n * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  const workloads::RaysReference s = workloads::summarise(hits);
  state.counters["sum_t"] = s.sumT;
  state.counters["sum_t_rel_error"] = std::abs(s.sumT - set.figures.sumT) / set.figures.sumT;
  state.counters["sum_id"] = double(s.sumId);
  state.counters["sum_id_expected"] = double(set.figures.sumId);
  const workloads::ReferenceComparison c = workloads::compareWithReference(hits, set.reference);
  state.counters["differ"] = double(c.differ);
  state.counters["excused"] = double(c.excused);
  state.counters["max_rel_t"] = c.maxRelativeT;
  if (!peer) {
    checkExact(state, s.hits, set.figures.hits);
    return;
  }
  state.counters["result"] = double(s.hits);
  state.counters["expected"] = double(set.figures.hits);
  state.counters["exact"] = s.hits == set.figures.hits ? 1 : 0;
  state.counters["hits_missing"] = double(set.figures.hits) - double(s.hits);
}

}  // namespace simdphys::bench

// W3 `cloth` (WORKLOADS.md): the n x n cloth hanging over the sphere, 300 frames (one an
// iteration), on every path, with W3's measures and the error against the same cloth stepped by
// the double reference. The grid's kernels at simdphys's defaults (XPBD, 10 substeps, tethers),
// the same springs as a general network, the plain loops, the mass-spring model, and XPBD over
// its substeps for the speed-against-error plot. Bullet's btSoftBody runs in
// peers/bullet_cloth_bench.cpp.
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "cloth.hpp"
#include "simdphys/world.hpp"
#include "testing/cloth.hpp"
#include "testing/plain_loops.hpp"

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;

// How a run models W3's cloth.
struct Model {
  std::string name;
  ClothSettings settings;
  bool network = false;      // the springs as a general network, greedily coloured
  float stiffness = kRigid;  // every spring's (the mass-spring model needs a finite one)
  bool operator<(const Model& o) const { return name < o.name; }
};

Cloth clothOf(const workloads::ClothWorkload& w, const Model& m) {
  if (m.network) {
    std::vector<Spring> springs = workloads::clothSprings(w);
    for (Spring& s : springs) s.stiffness = m.stiffness;
    return Cloth(w.positions, w.invMass, springs, m.settings);
  }
  ClothGrid g = workloads::clothGrid(w);
  g.structural.stiffness = g.shear.stiffness = g.bend.stiffness = m.stiffness;
  return Cloth::grid(g, m.settings);
}

const workloads::ClothWorkload& clothWorkload(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<workloads::ClothWorkload>> cache;
  auto& w = cache[n];
  if (!w) w = std::make_unique<workloads::ClothWorkload>(workloads::makeClothWorkload(n));
  return *w;
}

World clothWorld() {
  World world(WorldSettings{workloads::kClothFrameTime, 1, 1});
  world.obstacles().add(workloads::kClothSphere);
  return world;
}

// The model's cloth stepped by the double reference: its positions after 10 frames (0.17 s, as
// the cloth falls towards the sphere) and at the end (300), computed once per model and n, shared
// by every path's run. The early error is the rounding's. Once the cloth meets the sphere, a
// contact's friction holds or lets go at a threshold, which rounding tips one way in float and
// the other in double, and the two cloths part: the end's error measures that as much as rounding.
constexpr int kEarlyFrame = 10;
struct DoubleRun {
  std::vector<Vec3d> early, final;
};
const DoubleRun& doubleRun(const Model& m, std::size_t n) {
  static std::map<std::pair<Model, std::size_t>, DoubleRun> cache;
  DoubleRun& r = cache[{m, n}];
  if (r.final.empty()) {
    World world = clothWorld();
    const Handle h = world.addCloth(clothOf(clothWorkload(n), m));
    test::ClothD d(world.cloth(h));
    for (int f = 1; f <= workloads::kClothFrames; ++f) {
      d.step(world.cloth(h), world);
      if (f == kEarlyFrame) r.early = d.positions(world.cloth(h));
    }
    r.final = d.positions(world.cloth(h));
  }
  return r;
}

void clothRun(benchmark::State& state, const Model& m, std::size_t n, bool plainLoops) {
  const workloads::ClothWorkload& w = clothWorkload(n);
  const DoubleRun& exact = doubleRun(m, n);  // before the timing, the first time
  World world = clothWorld();
  const Handle h = world.addCloth(clothOf(w, m));
  std::optional<test::ScopedPlainLoops> plain;
  if (plainLoops) plain.emplace();
  double seconds = 0, deepest = 0, updates = 0;
  bool finite = true;
  int frame = 0;
  for (auto _ : state) {
    const auto start = Clock::now();
    world.step();
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
    updates += double(world.profile().cloth.elements);
    state.PauseTiming();
    const std::vector<Vec3f> x = world.cloth(h).positions();
    finite = finite && workloads::allFinite(x);
    deepest = std::max(deepest, workloads::spherePenetration(workloads::kClothSphere, x));
    if (++frame == kEarlyFrame)
      state.counters["error_max_early"] = test::positionError(x, exact.early).max;
    state.ResumeTiming();
  }
  const std::vector<Vec3f> x = world.cloth(h).positions();
  const auto frames = double(state.iterations());
  state.counters["frames"] = frames;
  state.counters["substeps"] = updates / frames / double(world.cloth(h).springs().size());
  state.counters["ms_per_frame"] = seconds * 1e3 / frames;
  state.counters["spring_updates_per_second"] = updates / seconds;
  clothCounters(state, w, x, deepest, finite);
  state.SetItemsProcessed(std::int64_t(updates));
  if (state.iterations() != workloads::kClothFrames) {
    state.SkipWithError("W3 runs 300 frames: its checks need the final state");
    return;
  }
  const test::PositionError e = test::positionError(x, exact.final);
  state.counters["error_max"] = e.max;
  state.counters["error_rms"] = e.rms;
}

Model xpbd(int substeps = ClothSettings{}.substeps, bool tethers = true) {
  Model m{"xpbd", {}};
  m.settings.substeps = substeps, m.settings.tethers = tethers;
  if (substeps != ClothSettings{}.substeps) m.name += "_s" + std::to_string(substeps);
  if (!tethers) m.name += "_untethered";
  return m;
}

}  // namespace

void registerClothBenchmarks() {
  const auto run = [](Model m, std::size_t n, bool plain) {
    return [m, n, plain](benchmark::State& state) { clothRun(state, m, n, plain); };
  };
  const std::int64_t frames = workloads::kClothFrames;
  for (const std::size_t n : workloads::kClothSizes) {
    // The defaults, on every path; the plain loops at n = 128 on every SIMD path.
    registerPerPath("cloth", "xpbd", n, run(xpbd(), n, false), true, frames);
    if (n == 128) registerPerPath("cloth", "autovec", n, run(xpbd(), n, true), false, frames);
    // The same springs as a general network (greedy colours, indexed loads).
    Model network = xpbd();
    network.name = "xpbd_network", network.network = true;
    registerPerPath("cloth", network.name, n, run(network, n, false), n == 128, frames);
    if (n == 128) registerBestPath("cloth", "autovec_network", n, run(network, n, true), frames);
  }
  // Speed against error at n = 128 on the best path: XPBD over its substeps, with and without
  // tethers; the mass-spring model over its stiffness (its substeps follow the stability bound).
  for (const int substeps : {2, 4, 6, 8, 16, 24})
    for (const bool tethers : {true, false}) {
      const Model m = xpbd(substeps, tethers);
      registerBestPath("cloth", m.name, 128, run(m, 128, false), frames);
    }
  registerBestPath("cloth", xpbd(10, false).name, 128, run(xpbd(10, false), 128, false), frames);
  for (const float k : {1e4f, 1e5f, 1e6f}) {
    Model m{"mass_spring_k1e" + std::to_string(int(std::lround(std::log10(k)))), {}};
    m.settings.model = ClothModel::kMassSpring, m.settings.substeps = 1, m.stiffness = k;
    registerBestPath("cloth", m.name, 128, run(m, 128, false), frames);
  }
}

}  // namespace simdphys::bench

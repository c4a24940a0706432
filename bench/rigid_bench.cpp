// W5 `pyramid` (WORKLOADS.md): the square pyramid of unit boxes, 600 frames (one an iteration),
// with W5's measures (bench_common's pyramidCounters, shared with the peers) and the error
// against the same pyramid stepped by the double reference. The contact models at their defaults
// and over their substeps and iterations, for the speed-against-error plot. The defaults run on
// every path (the contact passes as lane-wide kernels, simd/rigid.cpp) and as the kernels'
// plain loops ("autovec"); the sweeps on the reference path. Bullet and ODE run in
// peers/*_pyramid_bench.cpp. The same pyramid of hulls (each box given as its 8 corners) shows what
// the general convex case (GJK, EPA and face clipping) costs beside box-box, and its error.
#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "pyramid.hpp"
#include "simdphys/world.hpp"
#include "testing/cloth.hpp"
#include "testing/plain_loops.hpp"
#include "testing/rigid.hpp"

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;

struct Model {
  std::string name;
  RigidSettings settings;
  bool withError;            // run the double reference too (about 40 ms a frame at B = 10)
  bool onReference = false;  // on the reference path (registered once, labelled so)
  bool hulls = false;        // every box a HullShape of its corners
};

World pyramidWorld(const Model& m, int base, std::vector<Handle>& handles) {
  World world(WorldSettings{workloads::kPyramidFrameTime, 1, 1});
  RigidSettings s = m.settings;
  s.gravity = workloads::kPyramidGravity;
  s.sleeping = false;  // W5: no sleeping or deactivation
  world.bodies().setSettings(s);
  world.obstacles().add(workloads::kPyramidGround);
  for (const Vec3f& p : workloads::pyramidCenters(base)) {
    BodyDef d;
    d.position = p, d.halfExtents = Vec3f::Constant(workloads::kPyramidHalf);
    d.mass = workloads::kPyramidMass, d.friction = workloads::kPyramidFriction;
    d.restitution = workloads::kPyramidRestitution;
    if (m.hulls) {
      static const auto cube = [] {
        std::vector<Vec3f> corners;
        for (int v = 0; v < 8; ++v)
          corners.push_back(workloads::kPyramidHalf * Vec3f((v & 1) ? 1.0f : -1.0f,
                                                            (v & 2) ? 1.0f : -1.0f,
                                                            (v & 4) ? 1.0f : -1.0f));
        return std::make_shared<const HullShape>(corners);
      }();
      d.shape = BodyShape::kHull, d.hull = cube;
    }
    handles.push_back(world.bodies().add(d));
  }
  return world;
}

// The model's pyramid stepped by the double reference: the boxes' centres at the end.
const std::vector<Vec3d>& doubleRun(const Model& m, int base) {
  static std::map<std::pair<std::string, int>, std::vector<Vec3d>> cache;
  std::vector<Vec3d>& r = cache[{m.name, base}];
  if (r.empty()) {
    std::vector<Handle> handles;
    World world = pyramidWorld(m, base, handles);
    test::BodiesD d(world.bodies());
    for (int f = 0; f < workloads::kPyramidFrames; ++f) d.step(world);
    r = d.positions();
  }
  return r;
}

void pyramidRun(benchmark::State& state, const Model& m, int base, bool plainLoops) {
  const std::vector<Vec3d>* exact = m.withError ? &doubleRun(m, base) : nullptr;
  std::optional<test::ScopedPlainLoops> plain;
  if (plainLoops) plain.emplace();
  std::optional<ScopedPath> path;
  if (m.onReference) path.emplace("reference");
  std::vector<Handle> handles;
  World world = pyramidWorld(m, base, handles);
  const std::vector<Vec3f> start = workloads::pyramidCenters(base);
  double seconds = 0, deepest = 0, passes = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    world.step();
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    deepest = std::max(deepest, double(world.bodies().deepestPenetration()));
    passes += world.bodies().contactPassSeconds();
  }
  // The contact passes alone (warm start, solve, relax, restitution): the kernels' share.
  state.counters["contact_passes_ms_per_frame"] = passes * 1e3 / double(state.iterations());
  std::vector<Vec3f> end;
  for (const Handle h : handles) end.push_back(world.bodies().position(h));
  pyramidCounters(state, start, end, int(state.iterations()), seconds, deepest);
  state.counters["substeps"] = m.settings.substeps;
  state.counters["iterations"] = m.settings.iterations;
  if (exact) {
    const test::PositionError e = test::positionError(end, *exact);
    state.counters["error_max"] = e.max;
    state.counters["error_rms"] = e.rms;
  }
}

Model model(ContactModel kind, int substeps, int iterations, bool withError = false,
            bool onReference = true) {
  Model m{kind == ContactModel::kSoftStep    ? "soft_step"
          : kind == ContactModel::kBaumgarte ? "baumgarte"
                                             : "projection",
          {},
          withError,
          onReference};
  m.settings.model = kind, m.settings.substeps = substeps, m.settings.iterations = iterations;
  m.name += "_s" + std::to_string(substeps) + "_i" + std::to_string(iterations);
  return m;
}

}  // namespace

void registerRigidBenchmarks() {
  const auto run = [](Model m, int base, bool plain = false) {
    return [m, base, plain](benchmark::State& state) { pyramidRun(state, m, base, plain); };
  };
  const std::int64_t frames = workloads::kPyramidFrames;
  // The defaults (soft step, 5 substeps, 1 iteration) on every path and as plain loops, and the
  // other models at their usual settings, at both sizes, with the error against the double
  // reference at B = 10.
  const Model soft = model(ContactModel::kSoftStep, RigidSettings{}.substeps, 1, true, false);
  const Model others[] = {model(ContactModel::kBaumgarte, 1, 10, true),
                          model(ContactModel::kProjection, 1, 10, true)};
  for (const int base : workloads::kPyramidBases) {
    const auto n = std::size_t(base);
    Model m = soft;
    m.withError = base == 10;
    registerPerPath("pyramid", m.name, n, run(m, base), true, frames);
    registerBestPath("pyramid", "autovec", n, run(m, base, true), frames);
    // The defaults with every manifold found afresh each step: what reuse costs in accuracy.
    Model fresh = m;
    fresh.name += "_fresh_manifolds";
    fresh.settings.reuseManifolds = false, fresh.withError = false;
    registerBestPath("pyramid", fresh.name, n, run(fresh, base), frames);
    Model hulls = m;
    hulls.name += "_hulls", hulls.hulls = true;
    registerBestPath("pyramid", hulls.name, n, run(hulls, base), frames);
    for (Model o : others) {
      o.withError = base == 10;
      registerOnce("pyramid", o.name, "reference", n, run(o, base), frames);
    }
  }
  // Speed against error at B = 10: each model over its substeps or iterations, on the reference.
  for (const int substeps : {2, 4, 6, 8, 12})
    registerOnce("pyramid", model(ContactModel::kSoftStep, substeps, 1).name, "reference", 10,
                 run(model(ContactModel::kSoftStep, substeps, 1), 10), frames);
  for (const int iterations : {4, 20})
    for (const ContactModel kind : {ContactModel::kBaumgarte, ContactModel::kProjection})
      registerOnce("pyramid", model(kind, 1, iterations).name, "reference", 10,
                   run(model(kind, 1, iterations), 10), frames);
}

}  // namespace simdphys::bench

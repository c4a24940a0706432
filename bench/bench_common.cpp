#include "bench_common.hpp"

#include <map>
#include <memory>
#include <optional>

namespace simdphys::bench {

const workloads::AabbWorkload& aabbWorkload(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<workloads::AabbWorkload>> cache;
  auto& w = cache[n];
  if (!w) w = std::make_unique<workloads::AabbWorkload>(workloads::makeAabbWorkload(n));
  return *w;
}

const workloads::AabbReference& aabbReference(std::size_t n) {
  for (const workloads::AabbReference& r : workloads::kAabbReference)
    if (r.boxes == n) return r;
  throw Error("no W1 reference figures for N = " + std::to_string(n));
}

const workloads::CullWorkload& cullWorkload() {
  static const workloads::CullWorkload w = workloads::makeCullWorkload();
  return w;
}

const SphereStream& sphereField() {
  static const SphereStream s = [] {
    workloads::Random rnd(7);
    SphereStream out;
    for (int i = 0; i < 100'000; ++i) {
      Vec3f c(rnd.uniform(-100, 100), rnd.uniform(-100, 100), rnd.uniform(-100, 100));
      out.push({c, rnd.uniform(0.1f, 1.5f)});
    }
    return out;
  }();
  return s;
}

namespace {
std::string name(const std::string& task, const std::string& method, const std::string& path,
                 std::size_t n) {
  return task + "/" + method + "/" + path + "/" + std::to_string(n);
}

// Registers a run labelled `label`, with `path` forced while it runs unless `path` is empty.
// Timed in wall-clock time (rates too), the time a caller waits and the time peers' figures
// elsewhere are given in; the JSON keeps the CPU time beside it (cpu_time), and report.py shows
// both, so contention on a shared machine shows as a gap between them.
void registerRun(const std::string& runName, const std::string& label, const std::string& path,
                 const Body& body, std::int64_t iterations = 0) {
  auto* run = benchmark::RegisterBenchmark(runName.c_str(),
                                           [body, label, path](benchmark::State& state) {
                                             std::optional<ScopedPath> forced;
                                             if (!path.empty()) forced.emplace(path);
                                             state.SetLabel(label);
                                             body(state);
                                           })
                  ->Unit(benchmark::kMillisecond)
                  ->UseRealTime();
  if (iterations > 0) run->Iterations(iterations);
}
}  // namespace

void registerPerPath(const std::string& task, const std::string& method, std::size_t n,
                     const Body& body, bool withReference, std::int64_t iterations) {
  for (const std::string& path : availablePaths())
    if (path != "reference" || withReference)
      registerRun(name(task, method, path, n), path, path, body, iterations);
}

void registerBestPath(const std::string& task, const std::string& method, std::size_t n,
                      const Body& body, std::int64_t iterations) {
  const std::string best = availablePaths().front();
  registerRun(name(task, method, best, n), best, best, body, iterations);
}

void registerOnce(const std::string& task, const std::string& method, const std::string& label,
                  std::size_t n, const Body& body, std::int64_t iterations) {
  registerRun(name(task, method, label, n), label, "", body, iterations);
}

bool checkExact(benchmark::State& state, std::uint64_t found, std::uint64_t expected) {
  state.counters["result"] = double(found);
  state.counters["expected"] = double(expected);
  state.counters["exact"] = found == expected ? 1 : 0;
  if (found != expected)
    state.SkipWithError(("result " + std::to_string(found) + " differs from the reference " +
                         std::to_string(expected))
                            .c_str());
  return found == expected;
}

void clothCounters(benchmark::State& state, const workloads::ClothWorkload& w,
                   std::span<const Vec3f> x, double deepest, bool finite) {
  const workloads::ClothStretch s = workloads::clothStretch(w, x);
  state.counters["stretch_mean"] = s.mean;
  state.counters["stretch_p99"] = s.p99;
  state.counters["stretch_max"] = s.max;
  state.counters["stretch_max_away_from_pins"] = s.maxAwayFromPins;
  state.counters["penetration"] = deepest;
  state.counters["finite"] = finite ? 1 : 0;
}

void pyramidCounters(benchmark::State& state, std::span<const Vec3f> start,
                     std::span<const Vec3f> end, int frames, double seconds, double deepest) {
  const workloads::PyramidMeasures m = workloads::measurePyramid(start, end);
  const double bodySteps = double(start.size()) * frames;
  state.counters["frames"] = frames;
  state.counters["ms_per_frame"] = seconds * 1e3 / frames;
  state.counters["body_steps_per_s"] = bodySteps / seconds;
  state.counters["max_displacement"] = m.maxDisplacement;
  state.counters["deepest_penetration"] = deepest;
  state.counters["standing"] = m.standing ? 1 : 0;
  state.SetItemsProcessed(std::int64_t(bodySteps));
}

}  // namespace simdphys::bench

// Many worlds (batch.hpp): batch files, one job on one thread, OpenMP over the jobs.
#include "simdphys/batch.hpp"

#include <omp.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>

#include "json_node.hpp"
#include "simdphys/measures.hpp"
#include "simdphys/snapshot.hpp"

namespace simdphys {
namespace {

using scenefile::Json;
using scenefile::Node;

void summarise(const WorldMeasures& m, BatchResult& r) {
  r.bodies = m.bodies.count;
  r.maxDisplacement = m.bodies.maxDisplacement;
  r.deepestBodyPenetration = m.bodies.deepestPenetration;
  r.standing = m.bodies.standing;
  r.finite = m.bodies.finite;
  for (const ClothMeasures& c : m.cloths) {
    r.clothMeanStretch = std::max(r.clothMeanStretch, c.stretch.mean);
    r.clothDeepestPenetration = std::max(r.clothDeepestPenetration, c.deepestPenetration);
    r.finite = r.finite && c.finite;
  }
  for (const ParticleMeasures& p : m.particles) {
    r.particles += p.count;
    r.particlesInside += p.inside;
    r.finite = r.finite && p.finite;
  }
}

// A job's sweep: every combination of the listed values, the first pointer varying slowest.
void expand(const Node& job, BatchJob base, std::vector<BatchJob>& out) {
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  if (auto sweep = job.find("sweep"))
    for (const auto& [pointer, values] : sweep->json().items()) {
      const Node v = *sweep->find(pointer.c_str());
      std::vector<std::string> texts;
      for (std::size_t i = 0, n = v.size(10'000); i < n; ++i) texts.push_back(v[i].json().dump());
      if (texts.empty()) v.fail("a sweep needs at least one value");
      axes.emplace_back(pointer, texts);
    }
  std::size_t combinations = 1;
  for (const auto& axis : axes) combinations *= axis.second.size();
  if (combinations > 1'000'000) job.fail("the sweep makes more than 1,000,000 jobs");
  for (std::size_t c = 0; c < combinations; ++c) {
    BatchJob j = base;
    std::size_t rest = c;
    for (auto axis = axes.rbegin(); axis != axes.rend(); ++axis) {
      j.patches.push_back({axis->first, axis->second[rest % axis->second.size()]});
      rest /= axis->second.size();
    }
    out.push_back(std::move(j));
  }
}

}  // namespace

std::vector<BatchJob> loadBatch(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw Error(name + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  Json json;
  try {
    json = Json::parse(text.str());
  } catch (const Json::parse_error& e) {
    throw Error(name + ": not valid JSON: " + e.what());
  }
  const Node root(json, "", name);
  root.keys({"jobs"});
  const Node jobs = root.require("jobs");
  std::vector<BatchJob> out;
  for (std::size_t i = 0, n = jobs.size(1'000'000); i < n; ++i) {
    const Node job = jobs[i];
    job.keys({"scene", "frames", "set", "sweep"});
    BatchJob base;
    base.scene = file.parent_path() / job.require("scene").string();
    if (auto f = job.find("frames")) base.frames = int(f->integer(0, 100'000'000));
    if (auto set = job.find("set"))
      for (const auto& [pointer, value] : set->json().items()) {
        set->find(pointer.c_str());  // checks that set is an object
        base.patches.push_back({pointer, value.dump()});
      }
    expand(job, base, out);
  }
  return out;
}

BatchResult runJob(const BatchJob& job, std::uint64_t index) {
  BatchResult r;
  r.job = index;
  try {
    SceneFile scene = loadScene(job.scene, job.patches);
    WorldSettings s = scene.world.settings();
    s.threads = 1;  // one job a thread: the jobs are the parallelism
    scene.world.setSettings(s);
    WorldMonitor monitor(scene.world);
    const int frames = job.frames >= 0 ? job.frames : scene.frames;
    const auto begin = std::chrono::steady_clock::now();
    for (; r.frames < frames; ++r.frames) {
      scene.world.step();
      monitor.observe(scene.world);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    summarise(monitor.measure(scene.world), r);
    r.stateHash = stateHash(scene.world);
  } catch (const std::exception& e) {
    r.failed = 1;
    std::strncpy(r.error, e.what(), sizeof r.error - 1);
  }
  return r;
}

std::vector<BatchResult> runBatch(std::span<const BatchJob> jobs, int threads,
                                  std::span<const std::uint64_t> indices) {
  std::vector<BatchResult> results(jobs.size());
  const int n = int(jobs.size());
  const int t = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(t)
  for (int i = 0; i < n; ++i)
    results[std::size_t(i)] =
        runJob(jobs[std::size_t(i)], indices.empty() ? std::uint64_t(i) : indices[std::size_t(i)]);
  return results;
}

std::string batchReport(std::span<const BatchResult> results) {
  Json out = Json::array();
  for (const BatchResult& r : results) {
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(r.stateHash));
    Json j = {{"job", r.job}, {"frames", r.frames}, {"seconds", r.seconds}, {"stateHash", hash}};
    if (r.failed) j["error"] = r.error;
    j["bodies"] = r.bodies;
    j["maxDisplacement"] = r.maxDisplacement;
    j["deepestBodyPenetration"] = r.deepestBodyPenetration;
    j["standing"] = bool(r.standing);
    j["clothMeanStretch"] = r.clothMeanStretch;
    j["clothDeepestPenetration"] = r.clothDeepestPenetration;
    j["particles"] = r.particles;
    j["particlesInside"] = r.particlesInside;
    j["finite"] = bool(r.finite);
    out.push_back(j);
  }
  return out.dump(1);
}

}  // namespace simdphys

// simdphys run SCENE: steps the scene with a progress bar, then prints the path, the time a frame,
// the stages' times and the scene's measures; --json writes the same as JSON.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>

#include "commands.hpp"
#include "progress.hpp"
#include "session.hpp"
#include "simdphys/snapshot.hpp"

namespace simdphys::cli {
namespace {

nlohmann::json toJson(const Session& s, const WorldMeasures& m) {
  nlohmann::json j;
  j["scene"] = s.file();
  j["name"] = const_cast<Session&>(s).scene().name;
  j["path"] = activePath();
  j["frames"] = s.stepped();
  j["seconds"] = s.seconds();
  j["msPerFrame"] = s.stepped() ? 1e3 * s.seconds() / s.stepped() : 0;
  const StepProfile& p = s.stages().sum;
  for (auto [name, stage] : {std::pair{"particles", &p.particles}, std::pair{"cloth", &p.cloth},
                             std::pair{"bodies", &p.bodies}})
    j["stages"][name] = {{"seconds", stage->seconds}, {"elements", stage->elements}};
  if (m.bodies.count)
    j["bodies"] = {{"count", m.bodies.count},
                   {"maxDisplacement", m.bodies.maxDisplacement},
                   {"standing", m.bodies.standing},
                   {"deepestPenetration", m.bodies.deepestPenetration},
                   {"finite", m.bodies.finite}};
  j["cloths"] = nlohmann::json::array();
  for (const ClothMeasures& c : m.cloths)
    j["cloths"].push_back({{"particles", c.particles},
                           {"springs", c.springs},
                           {"meanStretch", c.stretch.mean},
                           {"p99Stretch", c.stretch.p99},
                           {"maxStretch", c.stretch.max},
                           {"maxStretchAwayFromPins", c.stretch.maxAwayFromPins},
                           {"deepestPenetration", c.deepestPenetration},
                           {"finite", c.finite}});
  j["particles"] = nlohmann::json::array();
  for (const ParticleMeasures& pm : m.particles)
    j["particles"].push_back({{"count", pm.count},
                              {"inside", pm.inside},
                              {"meanHeight", pm.meanHeight},
                              {"finite", pm.finite}});
  return j;
}

void printStages(const StageTotals& t) {
  const double frames = t.steps ? t.steps : 1;
  std::printf("stages (ms a frame, elements a second):\n");
  for (auto [name, unit, stage] : {std::tuple{"particles", "particle steps", &t.sum.particles},
                                   std::tuple{"cloth", "spring updates", &t.sum.cloth},
                                   std::tuple{"bodies", "body steps", &t.sum.bodies}}) {
    if (stage->elements == 0 && stage->seconds == 0) continue;
    std::printf("  %-10s %9.3f ms  %12.4g %s/s\n", name, 1e3 * stage->seconds / frames,
                stage->seconds > 0 ? double(stage->elements) / stage->seconds : 0.0, unit);
  }
  const double other =
      t.sum.seconds - t.sum.particles.seconds - t.sum.cloth.seconds - t.sum.bodies.seconds;
  std::printf("  %-10s %9.3f ms\n", "other", 1e3 * other / frames);
  if (t.sum.contacts)
    std::printf("  particle contacts %llu, pushed out %llu, bounce-limited %llu\n",
                static_cast<unsigned long long>(t.sum.contacts),
                static_cast<unsigned long long>(t.sum.pushedOut),
                static_cast<unsigned long long>(t.sum.bounceLimited));
}

}  // namespace

void run(const RunOptions& o) {
  Session s(o.scene, o.overrides);
  const SceneFile& scene = s.scene();
  const int threads = scene.world.settings().threads;
  std::printf("scene   %s (%s)\n", scene.name.empty() ? o.scene.c_str() : scene.name.c_str(),
              o.scene.c_str());
  std::printf("path    %s, %s\n", activePath().c_str(),
              threads ? (std::to_string(threads) + " thread" + (threads > 1 ? "s" : "")).c_str()
                      : "OpenMP's default threads");
  Progress bar("simdphys run", s.frames(), o.progress || (!o.noProgress && stderrIsTerminal()));
  for (int f = 0; f < s.frames(); ++f) {
    s.step();
    bar.update(f + 1);
  }
  bar.finish();
  std::printf("frames  %d in %.3f s: %.3f ms a frame\n", s.stepped(), s.seconds(),
              s.stepped() ? 1e3 * s.seconds() / s.stepped() : 0.0);
  printStages(s.stages());
  const WorldMeasures m = s.measures();
  std::printf("measures:\n");
  printMeasures(m);
  if (!o.save.empty()) {
    saveSnapshot(s.scene().world, o.save);
    std::printf("saved the world after frame %d to %s\n", s.stepped(), o.save.c_str());
  }
  if (!o.json.empty()) {
    std::ofstream out(o.json);
    out << toJson(s, m).dump(2) << "\n";
    if (!out) throw Error(o.json + ": cannot be written");
  }
}

}  // namespace simdphys::cli

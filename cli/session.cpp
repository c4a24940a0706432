#include "session.hpp"

#include <cstdio>

#include "simdphys/snapshot.hpp"

namespace simdphys::cli {

void StageTotals::add(const StepProfile& p) {
  for (auto [to, from] : {std::pair{&sum.particles, &p.particles}, std::pair{&sum.cloth, &p.cloth},
                          std::pair{&sum.bodies, &p.bodies}}) {
    to->seconds += from->seconds;
    to->elements += from->elements;
  }
  sum.seconds += p.seconds;
  sum.contacts += p.contacts;
  sum.pushedOut += p.pushedOut;
  sum.bounceLimited += p.bounceLimited;
  sum.outOfRange += p.outOfRange;
  ++steps;
}

namespace {
SceneFile loadWith(const std::string& file, const Overrides& o) {
  SceneFile scene = loadScene(file);
  if (!o.restore.empty()) scene.world = loadSnapshot(o.restore);
  const std::string path = o.path.empty() ? scene.path : o.path;
  if (path != "auto") setPath(path);
  if (o.threads >= 0) {
    WorldSettings s = scene.world.settings();
    s.threads = o.threads;
    scene.world.setSettings(s);
  }
  return scene;
}
}  // namespace

Session::Session(const std::string& file, const Overrides& overrides)
    : file_(file),
      scene_(loadWith(file, overrides)),
      frames_(overrides.frames >= 0 ? overrides.frames : scene_.frames),
      monitor_(scene_.world) {}

void Session::step() {
  const auto begin = std::chrono::steady_clock::now();
  scene_.world.step();
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  stages_.add(scene_.world.profile());
  monitor_.observe(scene_.world);
  ++stepped_;
}

void printMeasures(const WorldMeasures& m) {
  if (m.bodies.count)
    std::printf(
        "  bodies      %zu; largest displacement %.3g m; %s; deepest penetration %.3g m%s\n",
        m.bodies.count, m.bodies.maxDisplacement,
        m.bodies.standing ? "every body within 0.5 m of its start (standing)"
                          : "some body beyond 0.5 m of its start",
        m.bodies.deepestPenetration, m.bodies.finite ? "" : "; NOT FINITE");
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothMeasures& cm = m.cloths[c];
    std::printf(
        "  cloth %-5zu %zu particles; stretch of %zu structural springs: mean %.3g%%, p99 "
        "%.3g%%, max %.3g%% (%.3g%% away from pins); deepest penetration %.3g m%s\n",
        c, cm.particles, cm.springs, 100 * cm.stretch.mean, 100 * cm.stretch.p99,
        100 * cm.stretch.max, 100 * cm.stretch.maxAwayFromPins, cm.deepestPenetration,
        cm.finite ? "" : "; NOT FINITE");
  }
  for (std::size_t s = 0; s < m.particles.size(); ++s) {
    const ParticleMeasures& pm = m.particles[s];
    std::printf("  particles %-2zu %zu; inside an obstacle %zu; mean height %.4g m%s\n", s,
                pm.count, pm.inside, pm.meanHeight, pm.finite ? "" : "; NOT FINITE");
  }
}

std::string summary(const WorldMeasures& m) {
  char text[160];
  std::string out;
  if (m.bodies.count) {
    std::snprintf(text, sizeof text, "displacement %.3g m, penetration %.3g m%s",
                  m.bodies.maxDisplacement, m.bodies.deepestPenetration,
                  m.bodies.standing ? "" : ", moved > 0.5 m");
    out += text;
  }
  for (const ClothMeasures& cm : m.cloths) {
    std::snprintf(text, sizeof text, "%sstretch %.3g%%, penetration %.3g m",
                  out.empty() ? "" : "; ", 100 * cm.stretch.mean, cm.deepestPenetration);
    out += text;
  }
  for (const ParticleMeasures& pm : m.particles) {
    std::snprintf(text, sizeof text, "%s%zu inside, mean height %.4g m", out.empty() ? "" : "; ",
                  pm.inside, pm.meanHeight);
    out += text;
  }
  return out;
}

}  // namespace simdphys::cli

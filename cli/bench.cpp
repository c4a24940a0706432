// simdphys bench SCENE: the scene run afresh on every path this machine has (the scalar reference
// and each SIMD target), each run's time a frame beside its measures, and the speed-up over the
// reference. The first frames (--warmup) are stepped but not timed.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "session.hpp"

namespace simdphys::cli {
void bench(const BenchOptions& o) {
  const std::vector<std::string> paths = o.paths.empty() ? availablePaths() : o.paths;
  const std::string before = activePath();
  struct Row {
    std::string path;
    double ms;
    std::string measures;
  };
  std::vector<Row> rows;
  for (const std::string& path : paths) {
    Overrides ov = o.overrides;
    ov.path = path;
    Session s(o.scene, ov);
    while (s.stepped() < std::min(o.warmup, s.frames())) s.step();
    const double warm = s.seconds();
    const int warmFrames = s.stepped();
    while (s.stepped() < s.frames()) s.step();
    const int timed = s.stepped() - warmFrames;
    rows.push_back({path, timed ? 1e3 * (s.seconds() - warm) / timed : 0, summary(s.measures())});
    std::fprintf(stderr, "%s done\n", path.c_str());
  }
  setPath(before);
  double reference = 0;
  for (const Row& r : rows)
    if (r.path == "reference") reference = r.ms;
  std::printf("%-12s %12s %14s  %s\n", "path", "ms a frame", "x reference", "measures at the end");
  for (const Row& r : rows) {
    char speedup[32] = "";
    if (reference > 0 && r.ms > 0) std::snprintf(speedup, sizeof speedup, "%.2f", reference / r.ms);
    std::printf("%-12s %12.3f %14s  %s\n", r.path.c_str(), r.ms, speedup, r.measures.c_str());
  }
}

}  // namespace simdphys::cli

// simdphys batch FILE: the jobs of a batch file (docs/batch.md) on this machine's cores, a job a
// thread; a table of the results and, with --json, the report.
#include <cstdio>
#include <fstream>

#include "commands.hpp"
#include "simdphys/batch.hpp"

namespace simdphys::cli {
void printBatch(std::span<const BatchResult> results) {
  std::printf("%5s %7s %10s %18s  %s\n", "job", "frames", "seconds", "state hash", "measures");
  for (const BatchResult& r : results) {
    if (r.failed) {
      std::printf("%5llu  failed: %s\n", static_cast<unsigned long long>(r.job), r.error);
      continue;
    }
    std::printf(
        "%5llu %7d %10.3f   %016llx  bodies %llu: displacement %.3g m, penetration %.3g m; "
        "cloth stretch %.3g%%; particles inside %llu\n",
        static_cast<unsigned long long>(r.job), r.frames, r.seconds,
        static_cast<unsigned long long>(r.stateHash), static_cast<unsigned long long>(r.bodies),
        r.maxDisplacement, r.deepestBodyPenetration, 100 * r.clothMeanStretch,
        static_cast<unsigned long long>(r.particlesInside));
  }
}

void writeReport(std::span<const BatchResult> results, const std::string& file) {
  std::ofstream out(file);
  out << batchReport(results) << "\n";
  if (!out) throw Error(file + ": cannot be written");
}

void batch(const BatchOptions& o) {
  const std::vector<BatchJob> jobs = loadBatch(o.file);
  const std::vector<BatchResult> results = runBatch(jobs, o.threads);
  printBatch(results);
  if (!o.json.empty()) writeReport(results, o.json);
}

}  // namespace simdphys::cli

// The benchmark runner: prints the active path and machine, registers every suite, runs.
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "bench_common.hpp"

namespace simdphys::bench {
void registerAabbBenchmarks();
void registerCullBenchmarks();
void registerBandwidthBenchmarks();
void registerGeometry3dBenchmarks();
void registerSceneBenchmarks();
void registerOverlap3dBenchmarks();
void registerGeometry2dBenchmarks();
void registerParticleBenchmarks();
void registerClothBenchmarks();
void registerRigidBenchmarks();
}  // namespace simdphys::bench

namespace {
// The CPU's name, for the report ("model name" of /proc/cpuinfo on Linux).
std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}
}  // namespace

int main(int argc, char** argv) {
  using namespace simdphys;
  // One thread unless asked otherwise: the figures are per core.
  const char* threads = std::getenv("SIMDPHYS_BENCH_THREADS");
  omp_set_num_threads(threads ? std::atoi(threads) : 1);
  std::string paths;
  for (const std::string& p : availablePaths()) paths += (paths.empty() ? "" : ",") + p;
  std::printf("simdphys benchmarks: active path %s; paths on this machine: %s\n",
              activePath().c_str(), paths.c_str());
  benchmark::AddCustomContext("simdphys_active_path", activePath());
  benchmark::AddCustomContext("simdphys_paths", paths);
  benchmark::AddCustomContext("compiler", "GCC " __VERSION__);
  benchmark::AddCustomContext("cpu_model", cpuModel());
  benchmark::AddCustomContext("simdphys_build_type", SIMDPHYS_BUILD_TYPE);
  benchmark::AddCustomContext("simdphys_threads", std::to_string(omp_get_max_threads()));
  bench::registerAabbBenchmarks();
  bench::registerCullBenchmarks();
  bench::registerBandwidthBenchmarks();
  bench::registerGeometry3dBenchmarks();
  bench::registerSceneBenchmarks();
  bench::registerOverlap3dBenchmarks();
  bench::registerGeometry2dBenchmarks();
  bench::registerParticleBenchmarks();
  bench::registerClothBenchmarks();
  bench::registerRigidBenchmarks();
#ifdef SIMDPHYS_HAVE_BULLET
  bench::registerBulletBenchmarks();
#endif
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}

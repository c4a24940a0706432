// Many worlds: jobs (a scene file, patches to it, a frame count) stepped independently, as a
// parameter sweep or a set of training environments runs them (docs/batch.md). A job's result is
// the same however it is run: alone, among others on several threads (OpenMP, one job a thread),
// or in another process or on another machine (MPI, the simdphys-batch-mpi command), because
// every job runs its world on one thread and steps are deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "simdphys/scene_file.hpp"

namespace simdphys {

struct BatchJob {
  std::filesystem::path scene;
  std::vector<ScenePatch> patches;
  int frames = -1;  // < 0: the scene's
};

// What a job gives: its state's hash and the measures (measures.hpp) in a flat record, the same
// in every runner and across processes.
struct BatchResult {
  std::uint64_t job = 0;        // index in the batch
  std::uint64_t stateHash = 0;  // FNV-1a of the final world's snapshot: equal hashes, equal states
  double seconds = 0;           // wall time of the steps
  std::int32_t frames = 0;      // frames stepped
  std::int32_t failed = 0;      // 1: `error` says why (a bad scene, a step that threw)
  std::uint64_t bodies = 0, particles = 0, particlesInside = 0;
  double maxDisplacement = 0, deepestBodyPenetration = 0;
  double clothMeanStretch = 0, clothDeepestPenetration = 0;  // the largest over the cloths
  std::int32_t standing = 1, finite = 1;
  char error[256] = {};
};

// The jobs of a batch file (docs/batch.md): its "jobs", each sweep expanded into the cartesian
// product of its values; scene paths relative to the batch file's folder. Throws Error naming the
// file and the JSON place.
std::vector<BatchJob> loadBatch(const std::filesystem::path& file);

// One job, on one thread. A failure is recorded in the result, not thrown.
BatchResult runJob(const BatchJob& job, std::uint64_t index);
// The jobs run `threads` at a time (0: OpenMP's default), results in job order; `indices` (if
// given) names each job's index in a larger batch.
std::vector<BatchResult> runBatch(std::span<const BatchJob> jobs, int threads = 0,
                                  std::span<const std::uint64_t> indices = {});

// The results as JSON (an array, one object a job).
std::string batchReport(std::span<const BatchResult> results);

}  // namespace simdphys

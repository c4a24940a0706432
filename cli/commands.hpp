// The simdphys command's subcommands (docs/cli.md), each its options and what it does; main.cpp
// declares their command lines. Only main.cpp and batch_mpi.cpp parse CLI11's header-only code
// (most of a file's compile time: generated per file).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "session.hpp"
#include "simdphys/batch.hpp"

namespace simdphys::cli {

// simdphys run SCENE: step it, the profile and the measures
struct RunOptions {
  std::string scene, json, save;
  Overrides overrides;
  bool progress = false, noProgress = false;
};
void run(const RunOptions& o);

// simdphys bench SCENE: time it on every path
struct BenchOptions {
  std::string scene;
  Overrides overrides;
  int warmup = 5;
  std::vector<std::string> paths;
};
void bench(const BenchOptions& o);

// simdphys render SCENE: PNG frames, and a GIF or MP4
struct RenderOptions {
  std::string scene, out = "frames", video;
  Overrides overrides;
  int every = 0;  // 0: about 60 pictures over the run
  int width = 640, height = 360;
  float particleRadius = 0.05f;
};
void render(const RenderOptions& o);

// simdphys batch FILE: many scenes on this machine's cores
struct BatchOptions {
  std::string file, json;
  int threads = 0;
};
void batch(const BatchOptions& o);

// The batch results as a table on stdout, and as the JSON report in a file (batch.cpp; the MPI
// batch command prints and writes the same).
void printBatch(std::span<const BatchResult> results);
void writeReport(std::span<const BatchResult> results, const std::string& file);

}  // namespace simdphys::cli

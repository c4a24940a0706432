// The simdphys command's subcommands (docs/cli.md): each adds itself to the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include "simdphys/batch.hpp"

namespace simdphys::cli {

void addRun(CLI::App& app);     // simdphys run SCENE: step it, the profile and the measures
void addBench(CLI::App& app);   // simdphys bench SCENE: time it on every path
void addRender(CLI::App& app);  // simdphys render SCENE: PNG frames, and a GIF or MP4
void addBatch(CLI::App& app);   // simdphys batch FILE: many scenes on this machine's cores

// The batch results as a table on stdout, and as the JSON report in a file (batch.cpp; the MPI
// batch command prints and writes the same).
void printBatch(std::span<const BatchResult> results);
void writeReport(std::span<const BatchResult> results, const std::string& file);

}  // namespace simdphys::cli

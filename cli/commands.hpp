// The simdphys command's subcommands (docs/cli.md): each adds itself to the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace simdphys::cli {

void addRun(CLI::App& app);     // simdphys run SCENE: step it, the profile and the measures
void addBench(CLI::App& app);   // simdphys bench SCENE: time it on every path
void addRender(CLI::App& app);  // simdphys render SCENE: PNG frames, and a GIF or MP4

}  // namespace simdphys::cli

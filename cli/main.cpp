// The simdphys command (docs/cli.md): scene files run, timed and rendered from the command line.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "simdphys/core.hpp"

namespace simdphys::cli {
namespace {

// Each subcommand's command line, its options filled into its options struct (commands.hpp).
void addRun(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd =
      app.add_subcommand("run", "Step a scene file, then print its profile and measures");
  cmd->add_option("scene", o->scene, "The scene file (JSON, docs/scenes.md)")->required();
  cmd->add_option("--frames,-n", o->overrides.frames, "Frames to step (default: the scene's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option(
      "--path", o->overrides.path,
      "Execution path: reference or a SIMD target (default: the scene's, else the best)");
  cmd->add_option("--threads", o->overrides.threads, "OpenMP threads, 0 for OpenMP's default")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--json", o->json, "Also write the results to this JSON file");
  cmd->add_option("--save", o->save, "Save the world at the end to this snapshot file");
  cmd->add_option("--restore", o->overrides.restore,
                  "Start from this snapshot (of the scene's world) instead of the scene's start");
  cmd->add_flag("--progress", o->progress, "Draw the progress bar even when stderr is no terminal");
  cmd->add_flag("--no-progress", o->noProgress, "Never draw the progress bar");
  cmd->footer(
      "Examples:\n"
      "  simdphys run scenes/w5_pyramid_b10.json\n"
      "  simdphys run scenes/w3_cloth.json --frames 60 --path reference\n"
      "  simdphys run scenes/playground.json --threads 2 --json result.json\n"
      "  simdphys run scenes/w3_cloth.json --frames 100 --save cloth.snap\n"
      "  simdphys run scenes/w3_cloth.json --frames 200 --restore cloth.snap");
  cmd->callback([o] { run(*o); });
}

void addBench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench", "Time a scene file on every execution path");
  cmd->add_option("scene", o->scene, "The scene file (JSON, docs/scenes.md)")->required();
  cmd->add_option("--frames,-n", o->overrides.frames, "Frames a path (default: the scene's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--warmup", o->warmup, "Frames stepped before the timing starts")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", o->overrides.threads, "OpenMP threads, 0 for OpenMP's default")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--paths", o->paths, "Only these paths (default: every one this CPU has)");
  cmd->footer(
      "Examples:\n"
      "  simdphys bench scenes/w5_pyramid_b10.json --frames 120\n"
      "  simdphys bench scenes/w4_particles.json --paths reference avx2");
  cmd->callback([o] { bench(*o); });
}

void addRender(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Step a scene file and ray cast its frames to PNG");
  cmd->add_option("scene", o->scene, "The scene file (JSON, docs/scenes.md)")->required();
  cmd->add_option("--frames,-n", o->overrides.frames, "Frames to step (default: the scene's)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--every", o->every,
                  "A picture every this many frames (default: about 60 in all)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--out,-o", o->out, "Folder of the PNG frames")->capture_default_str();
  cmd->add_option("--video", o->video,
                  "Also join the frames into this .gif or .mp4 (needs ffmpeg)");
  cmd->add_option("--width", o->width, "Picture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--height", o->height, "Picture height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(16, 8192));
  cmd->add_option("--particle-radius", o->particleRadius, "Radius particles are drawn with (m)")
      ->capture_default_str()
      ->check(CLI::Range(1e-4, 10.0));
  cmd->add_option("--path", o->overrides.path,
                  "Execution path (default: the scene's, else the best)");
  cmd->add_option("--threads", o->overrides.threads, "OpenMP threads, 0 for OpenMP's default")
      ->check(CLI::NonNegativeNumber);
  cmd->footer(
      "Examples:\n"
      "  simdphys render scenes/w3_cloth.json --video cloth.gif\n"
      "  simdphys render scenes/w5_pyramid_b10.json --frames 120 --every 10 --out pyramid");
  cmd->callback([o] { render(*o); });
}

void addBatch(CLI::App& app) {
  auto o = std::make_shared<BatchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "batch", "Run a batch file's jobs (scenes, sweeps) on this machine's cores");
  cmd->add_option("file", o->file, "The batch file (JSON, docs/batch.md)")->required();
  cmd->add_option("--threads", o->threads, "Jobs at a time, 0 for OpenMP's default")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--json", o->json, "Also write the results to this JSON file");
  cmd->footer(
      "Examples:\n"
      "  simdphys batch scenes/batches/sweep.json --threads 2 --json results.json\n"
      "  mpirun -n 4 simdphys-batch-mpi scenes/batches/sweep.json --json results.json   (across "
      "processes)");
  cmd->callback([o] { batch(*o); });
}

}  // namespace
}  // namespace simdphys::cli

int main(int argc, char** argv) {
  CLI::App app{"simdphys: run, time and render physics scene files (docs/scenes.md, docs/cli.md)",
               "simdphys"};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  simdphys run scenes/w5_pyramid_b10.json\n"
      "  simdphys bench scenes/w3_cloth.json --frames 60\n"
      "  simdphys render scenes/w3_cloth.json --video cloth.gif\n"
      "Each command's --help lists its options.");
  simdphys::cli::addRun(app);
  simdphys::cli::addBench(app);
  simdphys::cli::addRender(app);
  simdphys::cli::addBatch(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const simdphys::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}

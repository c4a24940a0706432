// The simdphys command (docs/cli.md): scene files run, timed and rendered from the command line.
#include <cstdio>

#include "commands.hpp"
#include "simdphys/core.hpp"

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

// What the simdphys command's subcommands share: a scene loaded with the command line's overrides
// (frames, path, threads), stepped frame by frame with its measures and stage times gathered.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "simdphys/measures.hpp"
#include "simdphys/scene_file.hpp"

namespace simdphys::cli {

struct Overrides {
  int frames = -1;      // < 0: the scene's
  std::string path;     // empty: the scene's
  int threads = -1;     // < 0: the scene's
  std::string restore;  // a snapshot (snapshot.hpp) to start from instead of the scene's world
};

// The stages' times summed over a run (World::profile() of each step).
struct StageTotals {
  StepProfile sum;
  int steps = 0;
  void add(const StepProfile& p);
};

class Session {
 public:
  // Loads the scene and applies the overrides; the path is made active. Throws Error.
  Session(const std::string& file, const Overrides& overrides);
  SceneFile& scene() { return scene_; }
  const std::string& file() const { return file_; }
  int frames() const { return frames_; }
  // Steps one frame (World::step), observes the measures and adds the stage times.
  void step();
  int stepped() const { return stepped_; }
  double seconds() const { return seconds_; }  // wall time in step() so far
  const StageTotals& stages() const { return stages_; }
  WorldMeasures measures() const { return monitor_.measure(scene_.world); }

 private:
  std::string file_;
  SceneFile scene_;
  int frames_ = 0, stepped_ = 0;
  double seconds_ = 0;
  StageTotals stages_;
  WorldMonitor monitor_;
};

// Prints the measures, one line per body set, cloth and particle system (docs/cli.md).
void printMeasures(const WorldMeasures& m);
// The one-line summary `simdphys bench` puts beside each path's time.
std::string summary(const WorldMeasures& m);

}  // namespace simdphys::cli

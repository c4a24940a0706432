// A progress bar on stderr: frames done, frames a second, the time left. Drawn only on a terminal
// (or when forced), at most ten times a second, and cleared at the end.
#pragma once

#include <chrono>
#include <string>

namespace simdphys::cli {

class Progress {
 public:
  Progress(std::string label, int total, bool show);
  void update(int done);  // done of total frames
  void finish();

 private:
  std::string label_;
  int total_;
  bool show_;
  std::chrono::steady_clock::time_point start_, drawn_;
};

// Whether stderr is a terminal.
bool stderrIsTerminal();

}  // namespace simdphys::cli

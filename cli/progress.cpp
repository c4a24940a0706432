#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace simdphys::cli {

bool stderrIsTerminal() { return isatty(fileno(stderr)) != 0; }

Progress::Progress(std::string label, int total, bool show)
    : label_(std::move(label)),
      total_(total),
      show_(show && total > 0),
      start_(std::chrono::steady_clock::now()),
      drawn_(start_) {}

void Progress::update(int done) {
  if (!show_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total_ && now - drawn_ < std::chrono::milliseconds(100)) return;
  drawn_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fps = elapsed > 0 ? done / elapsed : 0;
  const double left = fps > 0 ? (total_ - done) / fps : 0;
  constexpr int kWidth = 30;
  const int filled = int(double(kWidth) * done / total_);
  std::string bar(std::size_t(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r%s [%s] %d/%d frames  %.1f frames/s  %.1f s left ", label_.c_str(),
               bar.c_str(), done, total_, fps, left);
  std::fflush(stderr);
}

void Progress::finish() {
  if (!show_) return;
  std::fprintf(stderr, "\r\033[K");  // clear the line: the report follows on stdout
  std::fflush(stderr);
}

}  // namespace simdphys::cli

// Test support, not public API: while a ScopedPlainLoops lives, the operations that have a
// plain-loop baseline (the pair finders, the particle step) run it, the loop left to the
// compiler's auto-vectoriser: the second baseline the benchmarks quote SIMD speed-ups against.
#pragma once

#include "src/core/on_path.hpp"

namespace simdphys::test {

struct ScopedPlainLoops {
  ScopedPlainLoops() { detail::setPlainLoops(true); }
  ~ScopedPlainLoops() { detail::setPlainLoops(false); }
  ScopedPlainLoops(const ScopedPlainLoops&) = delete;
  ScopedPlainLoops& operator=(const ScopedPlainLoops&) = delete;
};

}  // namespace simdphys::test

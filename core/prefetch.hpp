// Prefetching a whole object, for what a walk or a gather is about to read in full: the hardware
// prefetcher does not follow the jumps between nodes, blocks or constraint records.
#pragma once

#include <cstddef>

namespace simdphys::core {

inline constexpr std::size_t kCacheLine = 64;

// Every cache line of the `bytes` bytes at p. kLocality is __builtin_prefetch's: 3 into every
// level; 2 into the second-level cache only, for what a walk visits a level later, so that it
// neither waits on the first level's few miss buffers nor evicts what is being tested now.
template <int kLocality = 3>
inline void prefetchLines(const void* p, std::size_t bytes) {
  const char* c = static_cast<const char*>(p);
  for (std::size_t line = 0; line < bytes; line += kCacheLine)
    __builtin_prefetch(c + line, 0, kLocality);
}

}  // namespace simdphys::core

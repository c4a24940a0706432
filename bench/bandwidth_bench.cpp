// The machine's streaming read bandwidth, for the memory-bound kernels to be read against: a
// plain reduction over a buffer, at the working-set sizes of W6 (16 MB of spheres, 24 MB of
// boxes, which may partly live in the last-level cache) and at 512 MB (main memory).
#include <cstring>
#include <vector>

#include "bench_common.hpp"

namespace simdphys::bench {
namespace {

void streamRead(benchmark::State& state, std::size_t bytes) {
  std::vector<std::uint64_t, AlignedAllocator<std::uint64_t>> buffer(bytes / 8);
  std::memset(buffer.data(), 1, bytes);
  for (auto _ : state) {
    // Four independent accumulators keep the reduction off the critical path of the loads.
    std::uint64_t a = 0, b = 0, c = 0, d = 0;
    for (std::size_t i = 0; i < buffer.size(); i += 4)
      a |= buffer[i], b |= buffer[i + 1], c |= buffer[i + 2], d |= buffer[i + 3];
    benchmark::DoNotOptimize(a | b | c | d);
  }
  state.SetBytesProcessed(std::int64_t(state.iterations() * bytes));
}

}  // namespace

void registerBandwidthBenchmarks() {
  for (std::size_t mb : {16, 24, 512})
    registerOnce("bandwidth", "read", "scalar", mb << 20,
                 [mb](benchmark::State& state) { streamRead(state, mb << 20); });
}

}  // namespace simdphys::bench

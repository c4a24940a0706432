// Stable LSD radix sort of indices by float key, for sweeps and tree builds.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace simdphys {

// Maps a float to an unsigned key with the same order (negative values flipped).
inline std::uint32_t sortableBits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u & 0x80000000u ? ~u : u | 0x80000000u;
}

// The permutation that sorts `keys` ascending, equal keys in index order.
inline std::vector<std::uint32_t> sortedOrder(const float* keys, std::size_t n) {
  constexpr int kBits = 11, kPasses = 3, kBuckets = 1 << kBits;
  std::vector<std::uint32_t> bits(n), order(n), next(n);
  std::vector<std::array<std::uint32_t, kBuckets>> counts(kPasses);
  for (auto& c : counts) c.fill(0);
  for (std::size_t i = 0; i < n; ++i) {
    bits[i] = sortableBits(keys[i]);
    order[i] = std::uint32_t(i);
    for (int p = 0; p < kPasses; ++p) ++counts[p][(bits[i] >> (p * kBits)) & (kBuckets - 1)];
  }
  for (int p = 0; p < kPasses; ++p) {
    std::uint32_t sum = 0;
    for (std::uint32_t& c : counts[p]) sum += std::exchange(c, sum);
    for (std::uint32_t i : order) next[counts[p][(bits[i] >> (p * kBits)) & (kBuckets - 1)]++] = i;
    order.swap(next);
  }
  return order;
}

}  // namespace simdphys

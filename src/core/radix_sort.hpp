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

// Sorts by float or unsigned key, reusing its buffers from call to call.
class RadixSorter {
 public:
  // The permutation that sorts `keys` ascending, equal keys in index order.
  const std::vector<std::uint32_t>& sort(const float* keys, std::size_t n) {
    bits_.resize(n);
    for (std::size_t i = 0; i < n; ++i) bits_[i] = sortableBits(keys[i]);
    return sortBits();
  }
  const std::vector<std::uint32_t>& sort(const std::uint32_t* keys, std::size_t n) {
    bits_.assign(keys, keys + n);
    return sortBits();
  }

 private:
  const std::vector<std::uint32_t>& sortBits() {
    constexpr int kBits = 11, kPasses = 3, kBuckets = 1 << kBits;
    const std::size_t n = bits_.size();
    order_.resize(n), next_.resize(n);
    std::array<std::array<std::uint32_t, kBuckets>, kPasses> counts{};
    for (std::size_t i = 0; i < n; ++i) {
      order_[i] = std::uint32_t(i);
      for (int p = 0; p < kPasses; ++p) ++counts[p][(bits_[i] >> (p * kBits)) & (kBuckets - 1)];
    }
    for (int p = 0; p < kPasses; ++p) {
      std::uint32_t sum = 0;
      for (std::uint32_t& c : counts[p]) sum += std::exchange(c, sum);
      for (std::uint32_t i : order_)
        next_[counts[p][(bits_[i] >> (p * kBits)) & (kBuckets - 1)]++] = i;
      order_.swap(next_);
    }
    return order_;
  }

  std::vector<std::uint32_t> bits_, order_, next_;
};

}  // namespace simdphys

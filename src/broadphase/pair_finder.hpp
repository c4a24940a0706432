// Internal: the parts of PairFinderOf (simdphys/pair_finder.hpp) written once for 2D and 3D, and
// their scalar sweep. Each finder's .cpp defines its Scratch and findWith, then instantiates the
// class.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "simd/kernels.hpp"
#include "simdphys/pair_finder.hpp"
#include "src/core/on_path.hpp"

namespace simdphys {

// The scalar sweep of one sorted cell (3D) or band (2D): the reference path's kernel.
namespace reference {
#include "core/sweep-inl.hpp"
}  // namespace reference

// Puts pairs in the finders' order, ascending by a, then b, in time linear in the pairs and
// elements. Two passes that each write into cache rather than one scatter across all the pairs
// (which cost a quarter of W1's time at a million boxes): the parts, in parallel, deal their pairs
// to buckets of kBucket consecutive a, then each bucket, in parallel, is counting-sorted on a with
// its counts in L1, and each run of one a (the few partners of one element) sorted by b.
class PairSorter {
 public:
  // Replaces `out` with the pairs of all `parts` (each with a < b < n), sorted.
  void sort(std::span<const std::vector<Pair>> parts, std::size_t n, std::vector<Pair>& out);

  static constexpr unsigned kBucketBits = 12;
  static constexpr std::size_t kBucket = std::size_t(1) << kBucketBits;

 private:
  std::vector<std::size_t> at_;           // per part and bucket: where its next pair goes
  std::vector<std::size_t> bucketStart_;  // into dealt_ and the output
  std::vector<Pair> dealt_;               // bucket by bucket
};

// Replaces `events` with the difference from `before` to `now` (each sorted ascending, no pair
// twice): one linear merge of the two lists, no hashing.
void comparePairs(std::span<const Pair> before, std::span<const Pair> now, PairEvents& events);

template <class Stream, class Method>
PairFinderOf<Stream, Method>::PairFinderOf() : scratch_(std::make_unique<Scratch>()) {}
template <class Stream, class Method>
PairFinderOf<Stream, Method>::~PairFinderOf() = default;
template <class Stream, class Method>
PairFinderOf<Stream, Method>::PairFinderOf(PairFinderOf&&) noexcept = default;
template <class Stream, class Method>
PairFinderOf<Stream, Method>& PairFinderOf<Stream, Method>::operator=(PairFinderOf&&) noexcept =
    default;

template <class Stream, class Method>
const PairEvents& PairFinderOf<Stream, Method>::advance() {
  comparePairs(pairs_, found_, events_);
  pairs_.swap(found_);
  return events_;
}

}  // namespace simdphys

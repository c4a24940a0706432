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
// elements, at the cost of about one extra copy of the pairs. A finder produces its pairs in
// parts (a grid row, a group of bands) and hands each part to deal() while it is still in cache,
// from the thread that made it: deal() bins the part, a chunk of kChunk pairs at a time, by
// bucket of kBucket consecutive a. finish() then gathers each bucket's slices from every chunk
// (the buckets in parallel) and counting-sorts them on a with the counts in L1, each run of one
// a (the few partners of one element) sorted by b. Pairs are unique, so the order is total: the
// result does not depend on how the pairs were split into parts nor on the thread count.
class PairSorter {
 public:
  // Forgets what was dealt and expects up to `parts` parts of pairs with a < b < n.
  void begin(std::size_t parts, std::size_t n);
  // Bins part p (p < parts; each part dealt at most once). Distinct parts may be dealt at once
  // from different threads.
  void deal(std::size_t p, std::span<const Pair> pairs);
  // Replaces `out` with every dealt pair, sorted.
  void finish(std::vector<Pair>& out);

  static constexpr unsigned kBucketBits = 12;
  static constexpr std::size_t kBucket = std::size_t(1) << kBucketBits;
  // Pairs binned together: the chunk and its binned copy fit in L2 (128 KiB each).
  static constexpr std::size_t kChunk = std::size_t(1) << 14;

 private:
  struct Part {
    std::vector<Pair> binned;          // chunk by chunk, each bucket by bucket
    std::vector<std::uint32_t> start;  // per chunk, buckets + 1 offsets into binned
  };
  std::size_t buckets_ = 1;
  std::vector<Part> parts_;
  std::vector<std::size_t> bucketStart_;          // into the output
  std::vector<const Pair*> chunkData_;            // each chunk's part's binned pairs
  std::vector<const std::uint32_t*> chunkStart_;  // each chunk's bucket starts
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

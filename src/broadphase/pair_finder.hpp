// Internal: the parts of PairFinderOf (simdphys/pair_finder.hpp) written once for 2D and 3D. Each
// finder's .cpp defines its Scratch and findWith, then instantiates the class.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "simdphys/pair_finder.hpp"

namespace simdphys {

// Puts pairs in the finders' order, ascending by a, then b: a counting sort on a, then each run of
// equal a, which holds the few partners of one element, by b. Linear in the pairs and elements,
// where a comparison sort of all pairs is not.
class PairSorter {
 public:
  // Replaces `out` with the pairs of all `parts` (each with a < b < n), sorted.
  void sort(std::span<const std::vector<Pair>> parts, std::size_t n, std::vector<Pair>& out);

 private:
  std::vector<std::uint32_t> start_;
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

// The pair order and the pair events shared by the 2D and 3D pair finders.
#include "pair_finder.hpp"

#include <algorithm>
#include <array>

namespace simdphys {

namespace {

// After the counting sort on a, each run of one a is put in order by b. Runs of up to kReach + 1
// pairs (97 % of the runs, 89 % of the pairs at W1) without a branch: each pair moves by how many
// pairs of its run within kReach places belong on its other side. Branching insertion sorts, whose
// mispredictions cost most of the sort when every run had one, remain for the longer runs only.
constexpr std::ptrdiff_t kReach = 6;
constexpr std::uint32_t kLongRun = kReach + 1;

// A pair as one integer that orders as the pairs do.
std::uint64_t word(const Pair& p) { return std::uint64_t(p.a) << 32 | p.b; }
Pair pair(std::uint64_t w) { return {std::uint32_t(w >> 32), std::uint32_t(w)}; }

struct BucketScratch {
  std::vector<std::uint64_t> words;     // the bucket sorted on a, between kReach sentinels
  std::vector<std::uint32_t> longRuns;  // the a (less the base) of runs longer than kLongRun
};

// Sorts one bucket's pairs (a in [base, base + kBucket)), gathered from the slices
// [data[c] + start[c][0], data[c] + start[c][1]) of every chunk c, into `out`.
void sortBucket(std::span<const Pair* const> data, std::span<const std::uint32_t* const> start,
                std::uint32_t base, BucketScratch& scratch, Pair* out) {
  constexpr std::size_t kBucket = PairSorter::kBucket;
  std::array<std::uint32_t, kBucket + 1> first{};  // 32 KiB with `at`: in L1
  std::array<std::uint32_t, kBucket> at;
  for (std::size_t c = 0; c < data.size(); ++c)
    for (const Pair *p = data[c] + start[c][0], *end = data[c] + start[c][1]; p != end; ++p)
      ++first[p->a - base + 1];
  scratch.longRuns.clear();
  for (std::size_t a = 0; a < kBucket; ++a) {
    if (first[a + 1] > kLongRun) scratch.longRuns.push_back(std::uint32_t(a));
    first[a + 1] += first[a];
    at[a] = first[a] + std::uint32_t(kReach);
  }
  const std::uint32_t count = first[kBucket];
  // Sentinels that no pair moves past: 0 is below every pair (a < b), ~0 above.
  std::vector<std::uint64_t>& words = scratch.words;
  words.resize(count + 2 * kReach);
  std::fill(words.begin(), words.begin() + kReach, 0);
  std::fill(words.end() - kReach, words.end(), ~std::uint64_t(0));
  for (std::size_t c = 0; c < data.size(); ++c)
    for (const Pair *p = data[c] + start[c][0], *end = data[c] + start[c][1]; p != end; ++p)
      words[at[p->a - base]++] = word(*p);
  // The runs are sorted on a, so a pair compares below a later one (above an earlier one) only
  // if both have the same a.
  const std::uint64_t* sorted = words.data() + kReach;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint64_t* w = sorted + i;
    std::uint32_t to = i;
    for (std::ptrdiff_t d = 1; d <= kReach; ++d) to += (w[d] < *w) - (*w < w[-d]);
    out[to] = pair(*w);
  }
  for (const std::uint32_t a : scratch.longRuns) {
    Pair* run = out + first[a];
    const std::uint32_t size = first[a + 1] - first[a];
    for (std::uint32_t i = 0; i < size; ++i) run[i] = pair(sorted[first[a] + i]);
    if (size > 16) {
      std::sort(run, run + size);  // an element with many partners (a huge box)
      continue;
    }
    for (std::uint32_t i = 1; i < size; ++i)
      for (std::uint32_t j = i; j > 0 && run[j].b < run[j - 1].b; --j)
        std::swap(run[j], run[j - 1]);
  }
}

}  // namespace

void PairSorter::begin(std::size_t parts, std::size_t n) {
  buckets_ = (n >> kBucketBits) + 1;
  parts_.resize(parts);
  for (Part& part : parts_) part.binned.clear(), part.start.clear();
}

void PairSorter::deal(std::size_t p, std::span<const Pair> pairs) {
  Part& part = parts_[p];
  const std::size_t stride = buckets_ + 1, chunks = (pairs.size() + kChunk - 1) / kChunk;
  part.binned.resize(pairs.size());
  part.start.assign(chunks * stride, 0);
  for (std::size_t c = 0; c < chunks; ++c) {
    const std::size_t first = c * kChunk, last = std::min(first + kChunk, pairs.size());
    std::uint32_t* start = part.start.data() + c * stride;
    for (std::size_t i = first; i < last; ++i) ++start[(pairs[i].a >> kBucketBits) + 1];
    start[0] = std::uint32_t(first);
    for (std::size_t k = 0; k < buckets_; ++k) start[k + 1] += start[k];
    for (std::size_t i = first; i < last; ++i)
      part.binned[start[pairs[i].a >> kBucketBits]++] = pairs[i];
    // start[k] is now the end of bucket k: shift back to the starts.
    for (std::size_t k = buckets_; k > 0; --k) start[k] = start[k - 1];
    start[0] = std::uint32_t(first);
  }
}

void PairSorter::finish(std::vector<Pair>& out) {
  const std::size_t stride = buckets_ + 1;
  // Every chunk of every part, in part order, and where each bucket starts in the output.
  std::vector<const Pair*>& data = chunkData_;
  std::vector<const std::uint32_t*>& start = chunkStart_;
  data.clear(), start.clear();
  bucketStart_.assign(stride, 0);
  for (const Part& part : parts_)
    for (std::size_t c = 0; c * stride < part.start.size(); ++c) {
      const std::uint32_t* s = part.start.data() + c * stride;
      data.push_back(part.binned.data()), start.push_back(s);
      for (std::size_t k = 0; k < buckets_; ++k) bucketStart_[k + 1] += s[k + 1] - s[k];
    }
  for (std::size_t k = 0; k < buckets_; ++k) bucketStart_[k + 1] += bucketStart_[k];
  const std::size_t total = bucketStart_[buckets_];
  out.resize(total);
#pragma omp parallel if (total >= 100'000)
  {
    std::vector<const std::uint32_t*> at(start.size());
    BucketScratch scratch;
#pragma omp for schedule(dynamic)
    for (std::size_t k = 0; k < buckets_; ++k) {
      for (std::size_t c = 0; c < start.size(); ++c) at[c] = start[c] + k;
      sortBucket(data, at, std::uint32_t(k << kBucketBits), scratch, out.data() + bucketStart_[k]);
    }
  }
}

void comparePairs(std::span<const Pair> before, std::span<const Pair> now, PairEvents& events) {
  events.began.clear(), events.persisted.clear(), events.ended.clear();
  auto was = before.begin(), is = now.begin();
  while (was != before.end() && is != now.end()) {
    if (*was < *is)
      events.ended.push_back(*was++);
    else if (*is < *was)
      events.began.push_back(*is++);
    else
      events.persisted.push_back(*is++), ++was;
  }
  events.ended.insert(events.ended.end(), was, before.end());
  events.began.insert(events.began.end(), is, now.end());
}

}  // namespace simdphys

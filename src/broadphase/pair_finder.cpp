// The pair order and the pair events shared by the 2D and 3D pair finders.
#include "pair_finder.hpp"

#include <algorithm>
#include <array>

namespace simdphys {

namespace {

// Sorts one bucket's pairs (a in [base, base + kBucket)) from `in` into `out`.
void sortBucket(const Pair* in, std::size_t count, std::uint32_t base, Pair* out) {
  std::array<std::uint32_t, PairSorter::kBucket + 1> start{};  // 16 KiB: in L1
  for (std::size_t i = 0; i < count; ++i) ++start[in[i].a - base + 1];
  for (std::size_t a = 0; a < PairSorter::kBucket; ++a) start[a + 1] += start[a];
  for (std::size_t i = 0; i < count; ++i) out[start[in[i].a - base]++] = in[i];
  // start[a] is now the end of a's run.
  std::uint32_t begin = 0;
  for (std::size_t a = 0; a < PairSorter::kBucket && begin < count; ++a) {
    Pair* run = out + begin;
    const std::uint32_t size = start[a] - begin;
    begin = start[a];
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

void PairSorter::sort(std::span<const std::vector<Pair>> parts, std::size_t n,
                      std::vector<Pair>& out) {
  const std::size_t buckets = (n >> kBucketBits) + 1, nParts = parts.size();
  std::size_t total = 0;
  for (const std::vector<Pair>& part : parts) total += part.size();
  const bool parallel = total >= 100'000;
  // Each part's count per bucket, then where its pairs of each bucket go: bucket by bucket, and
  // within a bucket part by part, so the result is the same whatever the number of threads.
  at_.assign(nParts * buckets, 0);
#pragma omp parallel for schedule(dynamic) if (parallel)
  for (std::size_t p = 0; p < nParts; ++p)
    for (const Pair& pair : parts[p]) ++at_[p * buckets + (pair.a >> kBucketBits)];
  bucketStart_.resize(buckets + 1);
  std::size_t next = 0;
  for (std::size_t k = 0; k < buckets; ++k) {
    bucketStart_[k] = next;
    for (std::size_t p = 0; p < nParts; ++p) {
      const std::size_t count = at_[p * buckets + k];
      at_[p * buckets + k] = next;
      next += count;
    }
  }
  bucketStart_[buckets] = next;
  dealt_.resize(total);
#pragma omp parallel for schedule(dynamic) if (parallel)
  for (std::size_t p = 0; p < nParts; ++p)
    for (const Pair& pair : parts[p]) dealt_[at_[p * buckets + (pair.a >> kBucketBits)]++] = pair;
  out.resize(total);
#pragma omp parallel for schedule(dynamic) if (parallel)
  for (std::size_t k = 0; k < buckets; ++k)
    sortBucket(dealt_.data() + bucketStart_[k], bucketStart_[k + 1] - bucketStart_[k],
               std::uint32_t(k << kBucketBits), out.data() + bucketStart_[k]);
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

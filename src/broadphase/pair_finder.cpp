// The pair order and the pair events shared by the 2D and 3D pair finders.
#include "pair_finder.hpp"

#include <algorithm>

namespace simdphys {

void PairSorter::sort(std::span<const std::vector<Pair>> parts, std::size_t n,
                      std::vector<Pair>& out) {
  start_.assign(n + 1, 0);
  std::size_t total = 0;
  for (const std::vector<Pair>& part : parts) {
    for (const Pair& p : part) ++start_[p.a + 1];
    total += part.size();
  }
  for (std::size_t a = 0; a < n; ++a) start_[a + 1] += start_[a];
  out.resize(total);
  for (const std::vector<Pair>& part : parts)
    for (const Pair& p : part) out[start_[p.a]++] = p;
  for (auto run = out.begin(); run != out.end();) {
    const auto end = std::find_if(run, out.end(), [&](const Pair& p) { return p.a != run->a; });
    std::sort(run, end);
    run = end;
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

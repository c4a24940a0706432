// Fuzz target: findPairs on boxes decoded from the bytes (up to 48), every method on every path,
// against brute force over all pairs (closed test, a < b, sorted); countOverlapsBrute against
// the brute count of each box against all.
#include <omp.h>

#include <algorithm>
#include <vector>

#include "simdphys/broadphase.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  // One thread: the pairs do not depend on the thread count (broadphase.hpp), and waking threads
  // for 48 boxes costs a hundred times the search.
  static const bool oneThread = (omp_set_num_threads(1), true);
  (void)oneThread;
  fuzz::Input in(data, size);
  BoxStream boxes;
  std::vector<Aabb> list;
  try {
    for (std::size_t i = 0, n = in.count(48); i < n; ++i) {
      const Vec3f a = in.vec3(), b = in.vec3();
      // Mostly valid boxes; sometimes the corners as decoded (min > max must be an Error).
      const Aabb box = in.byte() < 240 ? Aabb{a.cwiseMin(b), a.cwiseMax(b)} : Aabb{a, b};
      boxes.push(box);
      list.push_back(box);
    }
  } catch (const Error&) {
    return 0;
  }
  auto overlaps = [](const Aabb& p, const Aabb& q) {
    return (p.min.array() <= q.max.array()).all() && (q.min.array() <= p.max.array()).all();
  };
  std::vector<Pair> brute;
  std::uint64_t count = 0;
  for (std::uint32_t i = 0; i < list.size(); ++i)
    for (std::uint32_t j = 0; j < list.size(); ++j) {
      count += overlaps(list[i], list[j]);
      if (i < j && overlaps(list[i], list[j])) brute.push_back({i, j});
    }
  for (const PairMethod method : {PairMethod::kGridSweep, PairMethod::kSweep, PairMethod::kBvh}) {
    const auto out = fuzz::sameOnEveryPath("findPairs", [&] {
      std::vector<Pair> pairs;
      findPairs(boxes, pairs, method);
      return pairs;
    });
    const auto* pairs = fuzz::resultOf(out);
    fuzz::require(pairs != nullptr, "findPairs rejected boxes the stream accepted");
    std::vector<Pair> sorted = *pairs;
    std::sort(sorted.begin(), sorted.end());
    fuzz::require(sorted == brute, "findPairs (method " + std::to_string(int(method)) +
                                       "): differs from brute force");
  }
  const auto out =
      fuzz::sameOnEveryPath("countOverlapsBrute", [&] { return countOverlapsBrute(boxes, list); });
  if (const auto* n = fuzz::resultOf(out))
    fuzz::require(*n == count, "countOverlapsBrute: differs from brute force");
  return 0;
}

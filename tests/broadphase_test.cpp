// Pair finding: every method on every path equals brute force, in a deterministic order.
#include <gtest/gtest.h>

#include <algorithm>

#include <omp.h>

#include "box_sets.hpp"
#include "paths.hpp"
#include "testing/pairs.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

constexpr PairMethod kMethods[] = {PairMethod::kGridSweep, PairMethod::kSweep, PairMethod::kBvh};

std::vector<Pair> sorted(std::vector<Pair> p) {
  std::sort(p.begin(), p.end());
  return p;
}

void expectPairsEqualBruteForce(const BoxStream& boxes) {
  const std::vector<Pair> want = test::bruteForcePairs(boxes);
  for (PairMethod m : kMethods) {
    SCOPED_TRACE("method " + std::to_string(int(m)));
    std::vector<Pair> pairs;
    findPairs(boxes, pairs, m);
    for (const Pair& p : pairs) ASSERT_LT(p.a, p.b);
    ASSERT_EQ(sorted(pairs), want);  // same set, each pair once
  }
}

class Pairs : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Pairs);

TEST_P(Pairs, RandomBoxesEqualBruteForce) {
  expectPairsEqualBruteForce(test::randomBoxes(31, 4000, 60, 0.1f, 3));
}

TEST_P(Pairs, HardSetsEqualBruteForce) {
  for (const test::BoxSet& set : test::hardBoxSets()) {
    SCOPED_TRACE(set.name);
    expectPairsEqualBruteForce(set.boxes);
  }
}

TEST_P(Pairs, NoBoxesAndOneBox) {
  BoxStream boxes;
  std::vector<Pair> pairs{{0, 1}};
  findPairs(boxes, pairs);
  EXPECT_TRUE(pairs.empty());  // the output is replaced, not appended to
  boxes.push({Vec3f::Zero(), Vec3f::Ones()});
  findPairs(boxes, pairs);
  EXPECT_TRUE(pairs.empty());
}

// The order is a function of the input only: the SIMD sweep and the scalar one report the same
// pairs in the same order, run after run.
TEST_P(Pairs, OrderIsDeterministicAndPathIndependent) {
  BoxStream boxes = test::randomBoxes(32, 5000, 50, 0.1f, 2);
  std::vector<Pair> here, again, reference;
  findPairs(boxes, here);
  findPairs(boxes, again);
  {
    ScopedPath ref("reference");
    findPairs(boxes, reference);
  }
  EXPECT_EQ(here, again);
  EXPECT_EQ(here, reference);
}

// Every method returns the pairs sorted (by a, then b), the order the 2D finder returns too.
TEST_P(Pairs, EveryMethodReturnsPairsSorted) {
  std::vector<test::BoxSet> sets = test::hardBoxSets();
  sets.push_back({"random", test::randomBoxes(33, 4000, 60, 0.1f, 3)});
  PairFinder finder;  // reused: its scratch memory must not leak between calls
  for (const test::BoxSet& set : sets) {
    const std::vector<Pair> want = test::bruteForcePairs(set.boxes);
    for (PairMethod m : kMethods) {
      std::vector<Pair> pairs;
      finder.find(set.boxes, pairs, m);
      EXPECT_EQ(pairs, want) << set.name << ", method " << int(m);
    }
  }
}

// More pairs than the pair sorter's chunk and its parallel threshold, over several buckets of a:
// the same sorted pairs on one thread and on more, for every method.
TEST_P(Pairs, ManyPairsSortedAtAnyThreadCount) {
  static const BoxStream boxes = test::randomBoxes(35, 4500, 10, 0.5f, 2.5f);
  static const std::vector<Pair> want = test::bruteForcePairs(boxes);  // the same on every path
  ASSERT_GT(want.size(), 150'000u);
  const int threads = omp_get_max_threads();
  PairFinder finder;
  std::vector<Pair> pairs;
  for (int t : {1, 2, 3}) {
    omp_set_num_threads(t);
    for (PairMethod m : kMethods) {
      finder.find(boxes, pairs, m);
      EXPECT_EQ(pairs, want) << t << " threads, method " << int(m);
    }
  }
  omp_set_num_threads(threads);
}

// The plain-loop baseline of the benchmarks (testing/pairs.hpp) finds the same pairs; it has no
// BVH form.
TEST_P(Pairs, PlainLoopBaselineEqualsBruteForce) {
  if (referencePathActive()) GTEST_SKIP() << "the baseline is compiled per SIMD target";
  test::PlainLoopPairFinder finder;
  std::vector<Pair> pairs;
  for (PairMethod m : {PairMethod::kGridSweep, PairMethod::kSweep}) {
    const BoxStream boxes = test::randomBoxes(34, 3000, 50, 0.1f, 2);
    finder.find(boxes, pairs, m);
    EXPECT_EQ(pairs, test::bruteForcePairs(boxes)) << "method " << int(m);
  }
  EXPECT_THROW(finder.find(BoxStream(), pairs, PairMethod::kBvh), Error);
}

// W1 at N = 100,000: the exact reference figures of the workload specification.
TEST_P(Pairs, W1ReferenceFigures) {
  const workloads::AabbReference& ref = workloads::kAabbReference[0];
  workloads::AabbWorkload w = workloads::makeAabbWorkload(ref.boxes);
  std::vector<Pair> pairs;
  findPairs(w.boxes, pairs);
  EXPECT_EQ(pairs.size(), ref.pairs);
  EXPECT_EQ(workloads::pairChecksum(pairs, ref.boxes), ref.checksum);
  EXPECT_EQ(Bvh(w.boxes).countOverlaps(w.queries), ref.queryOverlaps);
}

}  // namespace
}  // namespace simdphys

// The wide BVH: structure, box queries against brute force, refit, on every path.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <optional>

#include "box_sets.hpp"
#include "paths.hpp"
#include "simdphys/bvh.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

std::vector<std::uint32_t> bruteForceQuery(const BoxStream& b, const Aabb& q) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < b.size(); ++i)
    if (overlaps(q, b[i])) ids.push_back(i);
  return ids;
}

std::vector<std::uint32_t> sortedQuery(const Bvh& tree, const Aabb& q) {
  std::vector<std::uint32_t> ids;
  tree.query(q, ids);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// Every primitive appears in exactly one leaf, and every slot's box contains what is below it.
void checkStructure(const Bvh& tree, const BoxStream& b) {
  std::vector<int> seen(b.size(), 0);
  for (const BvhNode& n : tree.nodes()) {
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      std::uint32_t c = n.child[k];
      if (c == BvhNode::kEmpty) {
        EXPECT_GT(n.minX[k], n.maxX[k]) << "an unused slot must hold an empty box";
        continue;
      }
      Aabb slot{{n.minX[k], n.minY[k], n.minZ[k]}, {n.maxX[k], n.maxY[k], n.maxZ[k]}};
      if (BvhNode::isLeaf(c)) {
        ASSERT_EQ(BvhNode::leafCount(c), 1u);
        std::uint32_t id = BvhNode::leafFirst(c);
        ASSERT_LT(id, b.size());
        ++seen[id];
        EXPECT_EQ(slot.min, b[id].min);  // a leaf slot is the primitive's box, exactly
        EXPECT_EQ(slot.max, b[id].max);
        continue;
      }
      const BvhNode& sub = tree.nodes()[c];
      for (int j = 0; j < BvhNode::kWidth; ++j) {
        if (sub.child[j] == BvhNode::kEmpty) continue;
        EXPECT_LE(slot.min.x(), sub.minX[j]);
        EXPECT_GE(slot.max.x(), sub.maxX[j]);
        EXPECT_LE(slot.min.y(), sub.minY[j]);
        EXPECT_GE(slot.max.y(), sub.maxY[j]);
        EXPECT_LE(slot.min.z(), sub.minZ[j]);
        EXPECT_GE(slot.max.z(), sub.maxZ[j]);
      }
    }
  }
  for (std::size_t i = 0; i < b.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
  EXPECT_LE(tree.depth(), BvhNode::kMaxDepth);
}

class BvhQuery : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(BvhQuery);

TEST_P(BvhQuery, RandomBoxesEqualBruteForce) {
  BoxStream boxes = test::randomBoxes(21, 3000, 50, 0.1f, 3);
  Bvh tree(boxes);
  checkStructure(tree, boxes);
  workloads::Random r(22);
  std::vector<Aabb> queries;
  std::uint64_t expected = 0;
  for (int q = 0; q < 200; ++q) {
    Vec3f c(r.uniform(-60, 60), r.uniform(-60, 60), r.uniform(-60, 60));
    Vec3f h = Vec3f::Constant(r.uniform(0, 10));
    queries.push_back({c - h, c + h});
    std::vector<std::uint32_t> want = bruteForceQuery(boxes, queries.back());
    expected += want.size();
    ASSERT_EQ(sortedQuery(tree, queries.back()), want) << "query " << q;
  }
  EXPECT_EQ(tree.countOverlaps(queries), expected);
  EXPECT_EQ(countOverlapsBrute(boxes, queries), expected);
}

TEST_P(BvhQuery, HardSetsEqualBruteForce) {
  for (const test::BoxSet& set : test::hardBoxSets()) {
    SCOPED_TRACE(set.name);
    Bvh tree(set.boxes);
    checkStructure(tree, set.boxes);
    // Each box as a query hits itself and exactly its brute-force neighbours, touching included.
    std::vector<Aabb> queries;
    std::uint64_t expected = 0;
    for (std::size_t i = 0; i < set.boxes.size(); i += 7) {
      queries.push_back(set.boxes[i]);
      std::vector<std::uint32_t> want = bruteForceQuery(set.boxes, set.boxes[i]);
      expected += want.size();
      ASSERT_EQ(sortedQuery(tree, set.boxes[i]), want) << "box " << i;
    }
    EXPECT_EQ(tree.countOverlaps(queries), expected);
    EXPECT_EQ(countOverlapsBrute(set.boxes, queries), expected);
  }
}

TEST_P(BvhQuery, EmptyAndSingleBoxTrees) {
  BoxStream none;
  Bvh empty(none);
  std::vector<std::uint32_t> ids;
  empty.query({Vec3f::Zero(), Vec3f::Ones()}, ids);
  EXPECT_TRUE(ids.empty());
  BoxStream one;
  one.push({Vec3f::Zero(), Vec3f::Ones()});
  Bvh single(one);
  single.query({Vec3f::Ones(), Vec3f::Constant(2)}, ids);  // touches at a corner
  EXPECT_EQ(ids, std::vector<std::uint32_t>{0});
}

// Centres apart by denormal distances: 16 bins over a denormal extent would need an infinite
// scale (and 0 x inf is NaN); the builder must not split on such an axis.
TEST_P(BvhQuery, DenormalSpreadsBuildAWellFormedTree) {
  BoxStream boxes;
  for (int i = 0; i < 200; ++i) {
    const float x = float(i) * 1e-41f;  // denormal steps
    boxes.push(Aabb{{x, -1, -1}, {x, 1, 1}});
  }
  Bvh tree(boxes);
  checkStructure(tree, boxes);
  const Aabb all{{-1, -1, -1}, {1, 1, 1}};
  EXPECT_EQ(sortedQuery(tree, all), bruteForceQuery(boxes, all));
}

TEST_P(BvhQuery, RefitAnswersLikeARebuild) {
  BoxStream boxes = test::randomBoxes(23, 2000, 40, 0.2f, 2);
  Bvh tree(boxes);
  // Move every box; the refitted tree must answer exactly as a new one (and as brute force).
  workloads::Random r(24);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    Vec3f move(r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5));
    boxes.set(i, {boxes[i].min + move, boxes[i].max + move});
  }
  tree.refit(boxes);
  checkStructure(tree, boxes);
  Bvh rebuilt(boxes);
  for (std::size_t i = 0; i < boxes.size(); i += 13)
    ASSERT_EQ(sortedQuery(tree, boxes[i]), sortedQuery(rebuilt, boxes[i])) << "box " << i;
}

// Subtrees are built as parallel tasks and spliced in slot order: the tree must be the same,
// node for node, whatever the number of threads.
// Node for node, bit for bit: the same splits give the same unions (empty slots are +-inf).
void expectSameTree(const Bvh& one, const Bvh& other) {
  ASSERT_EQ(one.nodes().size(), other.nodes().size());
  for (std::size_t n = 0; n < one.nodes().size(); ++n) {
    const BvhNode &a = one.nodes()[n], &b = other.nodes()[n];
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      ASSERT_EQ(a.child[k], b.child[k]) << "node " << n << " slot " << k;
      ASSERT_EQ(a.minX[k], b.minX[k]);
      ASSERT_EQ(a.minY[k], b.minY[k]);
      ASSERT_EQ(a.minZ[k], b.minZ[k]);
      ASSERT_EQ(a.maxX[k], b.maxX[k]);
      ASSERT_EQ(a.maxY[k], b.maxY[k]);
      ASSERT_EQ(a.maxZ[k], b.maxZ[k]);
    }
  }
  EXPECT_EQ(one.depth(), other.depth());
  ASSERT_TRUE(std::equal(one.order().begin(), one.order().end(), other.order().begin(),
                         other.order().end()));
}

TEST(Bvh, BuildIsIndependentOfTheThreadCount) {
  BoxStream boxes = test::randomBoxes(27, 60'000, 100, 0.1f, 2);  // several parallel subtrees
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  Bvh one(boxes);
  omp_set_num_threads(4);
  Bvh four(boxes);
  omp_set_num_threads(before);
  expectSameTree(one, four);
}

// The builder's binning and partitioning run on the active SIMD target; every target must split
// alike, so a tree built on one path answers the same on all.
TEST(Bvh, BuildIsIndependentOfThePath) {
  const BoxStream boxes = test::randomBoxes(28, 20'000, 100, 0.1f, 2);
  std::vector<Aabb> bounds(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) bounds[i] = boxes[i];
  const std::string before = activePath();
  std::optional<Bvh> first, firstLeaves;
  for (const std::string& path : availablePaths()) {
    SCOPED_TRACE(path);
    setPath(path);
    Bvh tree(boxes), leaves;
    leaves.build(bounds, {8, 8});
    if (!first) {
      first = std::move(tree), firstLeaves = std::move(leaves);
      continue;
    }
    expectSameTree(*first, tree);
    expectSameTree(*firstLeaves, leaves);
  }
  setPath(before);
}

TEST(Bvh, RefitRejectsAnotherStream) {
  BoxStream boxes = test::randomBoxes(25, 10, 5, 0.1f, 1);
  Bvh tree(boxes);
  boxes.push({Vec3f::Zero(), Vec3f::Ones()});
  EXPECT_THROW(tree.refit(boxes), Error);
}

TEST(Bvh, RejectsBadQueries) {
  BoxStream boxes = test::randomBoxes(26, 10, 5, 0.1f, 1);
  Bvh tree(boxes);
  std::vector<std::uint32_t> ids;
  float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(tree.query({Vec3f(nan, 0, 0), Vec3f::Ones()}, ids), Error);
  EXPECT_THROW(tree.query({Vec3f::Ones(), Vec3f::Zero()}, ids), Error);  // min > max
  std::vector<Aabb> qs{{Vec3f::Zero(), Vec3f(1, nan, 1)}};
  EXPECT_THROW(tree.countOverlaps(qs), Error);
}

}  // namespace
}  // namespace simdphys

// Tests of the quadtree (include/simdphys/geometry2d/quadtree.hpp), in float and in double: a
// hand-worked tree whose placement, queries and pairs are derived in the comments, and random
// trees (fixed seeds) whose queries and pairs must equal brute force over all objects exactly,
// through inserts, removals and updates, at the origin and at coordinates of 1e5. Coordinates are
// snapped to a grid of 0.5 so that many boxes touch each other and lie on the split lines, where
// the placement rule matters.
#include "simdphys/geometry2d.hpp"

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "workloads.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace simdphys {
namespace {

using test::expectError;
using Ids = std::vector<std::uint32_t>;

template <class T>
Vec2<T> v(double x, double y) {
  return Vec2<T>(T(x), T(y));
}
template <class T>
RectT<T> rect(double x0, double y0, double x1, double y1) {
  return {v<T>(x0, y0), v<T>(x1, y1)};
}

struct ScalarName {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};
using Scalars = ::testing::Types<float, double>;
template <class T>
class Quadtree2d : public ::testing::Test {};
TYPED_TEST_SUITE(Quadtree2d, Scalars, ScalarName);

// ---- brute force ----------------------------------------------------------------------------

template <class T>
using Truth = std::map<std::uint32_t, RectT<T>>;  // ordered by id: results come out sorted

template <class T, class Test>
Ids bruteQuery(const Truth<T>& truth, Test&& test) {
  Ids out;
  for (const auto& [id, box] : truth)
    if (test(box)) out.push_back(id);
  return out;
}

template <class T>
std::vector<Pair> brutePairs(const Truth<T>& truth) {
  std::vector<Pair> out;
  for (auto a = truth.begin(); a != truth.end(); ++a)
    for (auto b = std::next(a); b != truth.end(); ++b)
      if (intersects(a->second, b->second)) out.push_back(Pair{a->first, b->first});
  return out;  // a < b and sorted, by the map's order
}

// ---- hand-worked ----------------------------------------------------------------------------

TYPED_TEST(Quadtree2d, HandWorkedPlacementQueriesAndPairs) {
  using T = TypeParam;
  // Bounds [0, 8]^2, one object per node, depth at most 3. The root splits at (4, 4), its -x-y
  // quadrant [0, 4]^2 at (2, 2).
  QuadtreeT<T> tree(rect<T>(0, 0, 8, 8), {3, 1});
  tree.insert(1, rect<T>(1, 1, 2, 2));  // A: alone in the root
  EXPECT_EQ(tree.depthOf(1), 0);
  EXPECT_EQ(tree.nodeCount(), 1u);
  tree.insert(2, rect<T>(5, 5, 6, 6));  // B: two in the root > 1: it splits; A goes to -x-y
  EXPECT_EQ(tree.depthOf(1), 1);        // (max 2 < 4), B to +x+y (min 5 > 4)
  EXPECT_EQ(tree.depthOf(2), 1);
  EXPECT_EQ(tree.nodeCount(), 5u);
  tree.insert(3, rect<T>(3, 3, 5, 5));  // C crosses both split lines: stays in the root
  tree.insert(4, rect<T>(2, 2, 4, 3));  // D touches x = 4 (max.x == 4): stays in the root
  EXPECT_EQ(tree.depthOf(3), 0);
  EXPECT_EQ(tree.depthOf(4), 0);
  // E goes to [0,4]^2, which then holds two and splits at (2, 2): A touches x = 2 and stays at
  // depth 1; E (max 1 < 2) goes down to depth 2.
  tree.insert(5, rect<T>(0.5, 0.5, 1, 1));
  EXPECT_EQ(tree.depthOf(1), 1);
  EXPECT_EQ(tree.depthOf(5), 2);
  EXPECT_EQ(tree.nodeCount(), 9u);
  EXPECT_EQ(tree.depth(), 2);
  tree.checkInvariants();
  // Pairs (closed): A-D share the corner (2,2), A-E the corner (1,1), B-C the corner (5,5), C-D
  // overlap on [3,4] x [3,3]. A-C: 2 < 3; B-D: 4 < 5; D-E: 1 < 2; the rest are far apart. A and D
  // (or B and C) sit in different nodes that share a border: found through the parent.
  EXPECT_EQ(tree.pairs(), (std::vector<Pair>{{1, 4}, {1, 5}, {2, 3}, {3, 4}}));
  EXPECT_EQ(tree.query(v<T>(2, 2)), (Ids{1, 4}));            // A's corner, D's corner
  EXPECT_EQ(tree.query(v<T>(4, 4)), (Ids{3}));               // in C only (D's y ends at 3)
  EXPECT_EQ(tree.query(rect<T>(4, 4, 4, 4)), (Ids{3}));      // the same as a zero-size rect
  EXPECT_EQ(tree.query(rect<T>(4.5, 0, 8, 4.5)), (Ids{3}));  // C's corner region only
  EXPECT_EQ(tree.query(rect<T>(0, 0, 8, 8)), (Ids{1, 2, 3, 4, 5}));
  EXPECT_EQ(tree.query(CircleT<T>{v<T>(1, 1), T(0)}), (Ids{1, 5}));  // the shared corner
  // (7,7) is sqrt 2 = 1.414 from B's corner (6,6) and 2.83 from C's (5,5).
  EXPECT_EQ(tree.query(CircleT<T>{v<T>(7, 7), T(1.5)}), (Ids{2}));
  EXPECT_EQ(tree.query(CircleT<T>{v<T>(7, 7), T(1.4)}), (Ids{}));

  // Removing E leaves A alone below [0,4]^2 (count 1 > capacity / 2 = 0): no merge. Removing A
  // empties it: its children merge back into it (9 - 4 nodes).
  EXPECT_TRUE(tree.remove(5));
  EXPECT_FALSE(tree.remove(5));
  EXPECT_EQ(tree.nodeCount(), 9u);
  EXPECT_TRUE(tree.remove(1));
  EXPECT_EQ(tree.nodeCount(), 5u);
  tree.checkInvariants();
  // B moves into [0,4]^2 (a different node: removed and reinserted); C grows but still crosses
  // the split lines (the same node: updated in place).
  tree.update(2, rect<T>(0.5, 0.5, 1, 1));
  EXPECT_EQ(tree.depthOf(2), 1);
  tree.update(3, rect<T>(3, 3, 5, 5.5));
  EXPECT_EQ(tree.depthOf(3), 0);
  EXPECT_EQ(tree.box(3).max, v<T>(5, 5.5));
  EXPECT_EQ(tree.pairs(), (std::vector<Pair>{{3, 4}}));
  // Objects outside the bounds stay in the root and are found: F entirely outside, G sticking
  // out and touching B (0.5, 0.5) and F (-1, -1) at corners.
  tree.insert(6, rect<T>(-3, -3, -1, -1));
  tree.insert(7, rect<T>(-1, -1, 0.5, 0.5));
  EXPECT_EQ(tree.depthOf(6), 0);
  EXPECT_EQ(tree.depthOf(7), 0);
  EXPECT_EQ(tree.query(v<T>(-2, -2)), (Ids{6}));
  EXPECT_EQ(tree.pairs(), (std::vector<Pair>{{2, 7}, {3, 4}, {6, 7}}));
  EXPECT_EQ(tree.size(), 5u);
  tree.checkInvariants();
  tree.clear();
  EXPECT_EQ(tree.size(), 0u);
  EXPECT_EQ(tree.nodeCount(), 1u);
  EXPECT_TRUE(tree.pairs().empty());
  EXPECT_FALSE(tree.contains(3));
}

TYPED_TEST(Quadtree2d, ErrorsSayWhatAndWhere) {
  using T = TypeParam;
  expectError([] { QuadtreeT<T>(rect<T>(0, 0, -1, 1)); },
              "Quadtree: bounds: min.x (0) > max.x (-1)");
  expectError([] { QuadtreeT<T>(rect<T>(0, 0, 1, 1), {31, 4}); }, "maxDepth is 31");
  expectError([] { QuadtreeT<T>(rect<T>(0, 0, 1, 1), {4, 0}); }, "nodeCapacity");
  QuadtreeT<T> tree(rect<T>(0, 0, 8, 8));
  tree.insert(7, rect<T>(1, 1, 2, 2));
  expectError([&] { tree.insert(7, rect<T>(1, 1, 2, 2)); }, "Quadtree::insert: id 7 already");
  const T nan = std::numeric_limits<T>::quiet_NaN();
  expectError(
      [&] {
        tree.insert(3, RectT<T>{Vec2<T>(nan, 0), v<T>(1, 1)});
      },
      "Quadtree::insert: box of id 3: min.x is nan");
  expectError([&] { tree.update(7, rect<T>(2, 2, 1, 1)); }, "Quadtree::update: box of id 7: min.x");
  expectError([&] { tree.update(9, rect<T>(1, 1, 2, 2)); }, "Quadtree::update: id 9 is absent");
  expectError([&] { tree.box(9); }, "Quadtree::box: id 9 is absent");
  EXPECT_FALSE(tree.remove(9));
  EXPECT_EQ(tree.size(), 1u);  // failed calls changed nothing
  tree.checkInvariants();
}

// ---- random trees against brute force ------------------------------------------------------

// A box on the 0.5 grid: corner in [-4, 68) around bounds [0, 64]^2 (some stick out or lie
// outside), sides of 0 to 6 (zero-size boxes included).
template <class T>
RectT<T> randomBox(workloads::Random& r, double offset) {
  const auto snap = [](float x) { return std::floor(double(x) * 2) / 2; };
  const double x = snap(r.uniform(-4, 68)), y = snap(r.uniform(-4, 68));
  const double w = snap(r.uniform(0, 6.5f)), h = snap(r.uniform(0, 6.5f));
  return rect<T>(offset + x, offset + y, offset + x + w, offset + y + h);
}

// Queries: rects like the boxes but up to 20 wide, points on the grid and off it, circles with
// radii on the grid (exact touching) and off it.
template <class T>
void expectQueriesMatch(const QuadtreeT<T>& tree, const Truth<T>& truth, workloads::Random& r,
                        double offset, const std::string& where) {
  tree.checkInvariants();
  ASSERT_EQ(tree.size(), truth.size()) << where;
  ASSERT_EQ(tree.pairs(), brutePairs(truth)) << where;
  for (int q = 0; q < 60; ++q) {
    const RectT<T> box = randomBox<T>(r, offset);
    const RectT<T> wide{box.min, Vec2<T>(box.max + Vec2<T>::Constant(T(q % 4 * 5)))};
    ASSERT_EQ(tree.query(wide),
              bruteQuery(truth, [&](const RectT<T>& b) { return intersects(wide, b); }))
        << where << ", rect query " << q;
    const Vec2<T> p = q % 2 ? box.min : Vec2<T>(box.min + Vec2<T>(T(0.3), T(0.7)));
    ASSERT_EQ(tree.query(p), bruteQuery(truth, [&](const RectT<T>& b) { return contains(b, p); }))
        << where << ", point query " << q;
    const T radius = q % 2 ? T(std::floor(r.uniform(0, 12)) / 2) : T(r.uniform(0, 6));
    const CircleT<T> c{p, radius};
    ASSERT_EQ(tree.query(c), bruteQuery(truth, [&](const RectT<T>& b) { return intersects(c, b); }))
        << where << ", circle query " << q;
  }
}

template <class T>
void randomScenario(typename QuadtreeT<T>::Config config, std::uint64_t seed, double offset) {
  const std::string where = "capacity " + std::to_string(config.nodeCapacity) + ", depth " +
                            std::to_string(config.maxDepth) + ", offset " + std::to_string(offset);
  workloads::Random r(seed);
  QuadtreeT<T> tree(rect<T>(offset, offset, offset + 64, offset + 64), config);
  Truth<T> truth;
  std::vector<std::uint32_t> ids;
  std::uint32_t next = 1;
  const auto add = [&](int n) {
    for (int i = 0; i < n; ++i) {
      const std::uint32_t id = next++ * 2654435761u;  // sparse ids, distinct (odd multiplier)
      const RectT<T> box = randomBox<T>(r, offset);
      tree.insert(id, box);
      truth[id] = box;
      ids.push_back(id);
    }
  };
  const auto pick = [&]() {
    const std::size_t k = std::size_t(r.next() % ids.size());
    const std::uint32_t id = ids[k];
    return std::pair{k, id};
  };
  add(400);
  expectQueriesMatch(tree, truth, r, offset, where + ", after inserts");
  for (int i = 0; i < 120; ++i) {  // removals
    const auto [k, id] = pick();
    ASSERT_TRUE(tree.remove(id));
    truth.erase(id);
    ids.erase(ids.begin() + std::ptrdiff_t(k));
  }
  expectQueriesMatch(tree, truth, r, offset, where + ", after removals");
  for (int i = 0; i < 200; ++i) {  // motion: small steps on the grid, and some teleports
    const auto [k, id] = pick();
    RectT<T> box = truth[id];
    if (i % 4 == 0) {
      box = randomBox<T>(r, offset);
    } else {
      const Vec2<T> step(T(std::floor(r.uniform(-3, 3)) / 2), T(std::floor(r.uniform(-3, 3)) / 2));
      box.min += step;
      box.max += step;
    }
    tree.update(id, box);
    truth[id] = box;
    ASSERT_EQ(tree.box(id).min, box.min);
  }
  expectQueriesMatch(tree, truth, r, offset, where + ", after updates");
  add(100);
  expectQueriesMatch(tree, truth, r, offset, where + ", after more inserts");
  for (const std::uint32_t id : ids) ASSERT_TRUE(tree.remove(id));
  truth.clear();
  expectQueriesMatch(tree, truth, r, offset, where + ", emptied");
  EXPECT_EQ(tree.nodeCount(), 1u) << where;  // everything merged back into the root
}

TYPED_TEST(Quadtree2d, RandomQueriesAndPairsEqualBruteForce) {
  using T = TypeParam;
  randomScenario<T>({6, 1}, 11, 0);
  randomScenario<T>({8, 4}, 12, 0);
  randomScenario<T>({3, 16}, 13, 0);
  randomScenario<T>({10, 2}, 14, 0);
  randomScenario<T>({0, 8}, 15, 0);  // depth 0: a list, brute force by construction
}

// At 1e5 the grid of 0.5 is still exact in float (an ulp of 1e5 is 2^-7), and so are the split
// lines down to depth 6 (64 / 2^6 = 1).
TYPED_TEST(Quadtree2d, CoordinatesAt1e5EqualBruteForce) {
  using T = TypeParam;
  randomScenario<T>({6, 2}, 21, 1e5);
}

TYPED_TEST(Quadtree2d, PairsDoNotDependOnInsertionOrder) {
  using T = TypeParam;
  workloads::Random r(31);
  std::vector<RectT<T>> boxes;
  for (int i = 0; i < 300; ++i) boxes.push_back(randomBox<T>(r, 0));
  QuadtreeT<T> forward(rect<T>(0, 0, 64, 64), {6, 2}), backward(rect<T>(0, 0, 64, 64), {6, 2});
  for (std::uint32_t i = 0; i < boxes.size(); ++i) forward.insert(i, boxes[i]);
  for (std::uint32_t i = std::uint32_t(boxes.size()); i-- > 0;) backward.insert(i, boxes[i]);
  const std::vector<Pair> pairs = forward.pairs();
  EXPECT_FALSE(pairs.empty());
  EXPECT_EQ(backward.pairs(), pairs);
  EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
  EXPECT_TRUE(std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end());  // each once
  for (const Pair& p : pairs) EXPECT_LT(p.a, p.b);
}

}  // namespace
}  // namespace simdphys

// Pair events of the 3D and 2D pair finders: which pairs began, persisted and ended between two
// updates, exact on scripted moves and on random ones, for every method on every path.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

#include "box_sets.hpp"
#include "paths.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

constexpr PairMethod kMethods3d[] = {PairMethod::kGridSweep, PairMethod::kSweep, PairMethod::kBvh};
constexpr PairMethod2d kMethods2d[] = {PairMethod2d::kAuto, PairMethod2d::kBandedSweep,
                                       PairMethod2d::kSweep, PairMethod2d::kBrute,
                                       PairMethod2d::kQuadtree};

using test::bruteForcePairs;

// The oracle: set operations on the brute-force lists, not the finders' merge.
PairEvents expectedEvents(const std::vector<Pair>& before, const std::vector<Pair>& now) {
  PairEvents e;
  std::set_difference(now.begin(), now.end(), before.begin(), before.end(),
                      std::back_inserter(e.began));
  std::set_intersection(now.begin(), now.end(), before.begin(), before.end(),
                        std::back_inserter(e.persisted));
  std::set_difference(before.begin(), before.end(), now.begin(), now.end(),
                      std::back_inserter(e.ended));
  return e;
}

void expectEvents(const PairEvents& got, const std::vector<Pair>& began,
                  const std::vector<Pair>& persisted, const std::vector<Pair>& ended) {
  EXPECT_EQ(got.began, began);
  EXPECT_EQ(got.persisted, persisted);
  EXPECT_EQ(got.ended, ended);
}

// Three unit boxes (squares in 2D): 0 at [0, 1], 2 at [0.5, 1.5] overlapping it throughout, and 1
// at [d, d + 1] along x, which approaches, touches 0 (closed: it overlaps), leaves 0 while still
// overlapping 2, and separates.
BoxStream boxesAt(float d) {
  BoxStream b;
  for (float x : {0.0f, d, 0.5f}) b.push({Vec3f(x, 0, 0), Vec3f(x + 1, 1, 1)});
  return b;
}
RectStream rectsAt(float d) {
  RectStream r;
  for (float x : {0.0f, d, 0.5f}) r.push({Vec2f(x, 0), Vec2f(x + 1, 1)});
  return r;
}

template <class Finder, class Method, class Make>
void scriptedMoves(Method method, Make at) {
  SCOPED_TRACE("method " + std::to_string(int(method)));
  using P = std::vector<Pair>;
  Finder finder;
  expectEvents(finder.events(), {}, {}, {});  // before the first update: nothing
  // The first update: every pair began.
  expectEvents(finder.update(at(3.0f), method), P{{0, 2}}, {}, {});
  expectEvents(finder.update(at(1.0f), method), P{{0, 1}, {1, 2}}, P{{0, 2}}, {});
  EXPECT_EQ(finder.pairs(), (P{{0, 1}, {0, 2}, {1, 2}}));
  expectEvents(finder.update(at(1.25f), method), {}, P{{0, 2}, {1, 2}}, P{{0, 1}});
  expectEvents(finder.update(at(3.0f), method), {}, P{{0, 2}}, P{{1, 2}});
  expectEvents(finder.update(at(3.0f), method), {}, P{{0, 2}}, {});  // no move: all persisted
  EXPECT_EQ(finder.events().persisted, (P{{0, 2}}));  // events() is what update returned
  // find() neither reads nor changes what update() keeps.
  P found;
  finder.find(at(1.0f), found, method);
  EXPECT_EQ(found, (P{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(finder.pairs(), (P{{0, 2}}));
  expectEvents(finder.events(), {}, P{{0, 2}}, {});
  // reset(): forgotten, so the next update reports every pair as began and none as ended.
  finder.reset();
  EXPECT_TRUE(finder.pairs().empty());
  expectEvents(finder.events(), {}, {}, {});
  expectEvents(finder.update(at(1.0f), method), P{{0, 1}, {0, 2}, {1, 2}}, {}, {});
  // An empty stream ends every pair.
  expectEvents(finder.update(decltype(at(0.0f))(), method), {}, {}, P{{0, 1}, {0, 2}, {1, 2}});
  EXPECT_TRUE(finder.pairs().empty());
}

// Random elements moved step by step: each update's events equal the oracle's, and the finder's
// pairs equal brute force, on this path; and the same events come on the reference path.
template <class Finder, class Method, class Stream, class Move>
void randomMoves(Method method, Stream stream, Move move) {
  SCOPED_TRACE("method " + std::to_string(int(method)));
  Finder finder, onReference;
  std::vector<Pair> before;
  for (int step = 0; step < 5; ++step) {
    SCOPED_TRACE("step " + std::to_string(step));
    const std::vector<Pair> now = bruteForcePairs(stream);
    const PairEvents want = expectedEvents(before, now);
    ASSERT_FALSE(want.began.empty());  // the moves exercise every event
    if (step > 0) {
      ASSERT_FALSE(want.ended.empty() || want.persisted.empty());
    }
    const PairEvents& got = finder.update(stream, method);
    EXPECT_EQ(got.began, want.began);
    EXPECT_EQ(got.persisted, want.persisted);
    EXPECT_EQ(got.ended, want.ended);
    EXPECT_EQ(finder.pairs(), now);
    {
      ScopedPath reference("reference");
      const PairEvents& ref = onReference.update(stream, method);
      EXPECT_EQ(got.began, ref.began);
      EXPECT_EQ(got.persisted, ref.persisted);
      EXPECT_EQ(got.ended, ref.ended);
    }
    before = now;
    move(stream, step);
  }
}

class PairEventsTest : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(PairEventsTest);

TEST_P(PairEventsTest, ScriptedMoves3d) {
  for (PairMethod m : kMethods3d) scriptedMoves<PairFinder>(m, boxesAt);
}

TEST_P(PairEventsTest, ScriptedMoves2d) {
  for (PairMethod2d m : kMethods2d) scriptedMoves<PairFinder2d>(m, rectsAt);
}

TEST_P(PairEventsTest, RandomMoves3d) {
  // Every box jumps by up to a box size each step, so many pairs begin and end.
  auto move = [](BoxStream& b, int step) {
    workloads::Random r(100 + std::uint64_t(step));
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec3f d(r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-2, 2));
      b.set(i, {b[i].min + d, b[i].max + d});
    }
  };
  for (PairMethod m : kMethods3d)
    randomMoves<PairFinder>(m, test::randomBoxes(41, 1200, 25, 0.1f, 2), move);
}

TEST_P(PairEventsTest, RandomMoves2d) {
  auto move = [](RectStream& s, int step) {
    workloads::Random r(200 + std::uint64_t(step));
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Vec2f d(r.uniform(-2, 2), r.uniform(-2, 2));
      s.set(i, {s[i].min + d, s[i].max + d});
    }
  };
  RectStream rects;
  workloads::Random r(42);
  for (int i = 0; i < 1200; ++i) {
    const Vec2f c(r.uniform(-40, 40), r.uniform(-40, 40));
    rects.push(Rect::fromCenter(c, Vec2f(r.uniform(0, 2), r.uniform(0, 2))));
  }
  for (PairMethod2d m : kMethods2d) randomMoves<PairFinder2d>(m, rects, move);
}

// A finder moved from keeps nothing behind: the moved-to one carries on where it left off.
TEST_P(PairEventsTest, MovedFinderKeepsItsPairs) {
  PairFinder finder;
  finder.update(boxesAt(1.0f));
  PairFinder moved = std::move(finder);
  const PairEvents& e = moved.update(boxesAt(1.25f));
  expectEvents(e, {}, {{0, 2}, {1, 2}}, {{0, 1}});
}

}  // namespace
}  // namespace simdphys

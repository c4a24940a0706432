// Batch forms of the 2D tests and the 2D broadphase: on every path, exactly the answers of the
// scalar functions of geometry2d/ applied element by element (the same indices: no tolerance, as
// the kernels mirror the scalar arithmetic), and the broadphase pairs of every method equal to
// brute force over intersects(Rect, Rect) (exact comparisons, so exact equality).
//
// Rotations given as literals go through opaque(): GCC may fold std::cos of a constant at compile
// time (correctly rounded), while the streams and batch queries call the library's cosf at run
// time, which can differ by an ulp; the scalar oracle must see the same axes as the code under
// test.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "box_sets.hpp"
#include "expect_error.hpp"
#include "paths.hpp"
#include "simdphys/geometry2d/batch.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
#include "testing/kernels.hpp"
#include "testing/pairs.hpp"
#include "workloads.hpp"

namespace simdphys {
namespace {

using test::expectError;
using test::OnEveryPath;
using Ids = std::vector<std::uint32_t>;

constexpr float kPi = std::numbers::pi_v<float>;

float opaque(float x) {
  volatile float v = x;
  return v;
}

OrientedRect orect(float x, float y, float hx, float hy, float rotation) {
  return {{x, y}, {hx, hy}, opaque(rotation)};
}

// The oracle: the scalar function applied to every element.
template <class Stream, class Test>
Ids each(const Stream& s, Test test) {
  Ids ids;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    if (test(s[i])) ids.push_back(i);
  return ids;
}

CircleStream randomCircles(std::uint64_t seed, std::size_t n, float spread, Vec2f offset = {0, 0}) {
  workloads::Random r(seed);
  CircleStream s;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2f c(r.uniform(-spread, spread), r.uniform(-spread, spread));
    // Every tenth a point (zero radius).
    s.push({c + offset, i % 10 == 0 ? 0.0f : r.uniform(0, 3)});
  }
  return s;
}

RectStream randomRects(std::uint64_t seed, std::size_t n, float spread, Vec2f offset = {0, 0}) {
  workloads::Random r(seed);
  RectStream s;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2f c(r.uniform(-spread, spread), r.uniform(-spread, spread));
    Vec2f h(r.uniform(0, 3), r.uniform(0, 3));
    if (i % 10 == 0) h.x() = 0;  // flat: a segment, or a point
    if (i % 20 == 0) h.y() = 0;
    s.push(Rect::fromCenter(c + offset, h));
  }
  return s;
}

// Rotations mix arbitrary angles with the ones that make edges parallel to the axes or to other
// rectangles' edges (multiples of pi/4), where the separation test meets its ties.
OrientedRectStream randomOrientedRects(std::uint64_t seed, std::size_t n, float spread,
                                       Vec2f offset = {0, 0}) {
  workloads::Random r(seed);
  OrientedRectStream s;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2f c(r.uniform(-spread, spread), r.uniform(-spread, spread));
    Vec2f h(r.uniform(0, 3), r.uniform(0, 3));
    if (i % 10 == 0) h.x() = 0;
    if (i % 20 == 0) h.y() = 0;
    const float rotation = i % 3 == 0 ? float(int(r.uniform(0, 8))) * (kPi / 4) : r.uniform(-4, 4);
    s.push({c + offset, h, rotation});
  }
  return s;
}

// Checks every batch query of one shape against the scalar functions.
void expectSameAsScalar(const Circle& c, const CircleStream& circles) {
  Ids got;
  overlapping(c, circles, got);
  ASSERT_EQ(got, each(circles, [&](const Circle& e) { return intersects(c, e); }))
      << "circle (" << c.center.x() << ", " << c.center.y() << ") r " << c.radius;
  containing(c.center, circles, got);
  ASSERT_EQ(got, each(circles, [&](const Circle& e) { return contains(e, c.center); }));
}
void expectSameAsScalar(const Rect& q, const RectStream& rects) {
  Ids got;
  overlapping(q, rects, got);
  ASSERT_EQ(got, each(rects, [&](const Rect& e) { return intersects(q, e); }));
  containing(q.min, rects, got);
  ASSERT_EQ(got, each(rects, [&](const Rect& e) { return contains(e, q.min); }));
}
void expectSameAsScalar(const OrientedRect& q, const OrientedRectStream& rects) {
  Ids got;
  overlapping(q, rects, got);
  ASSERT_EQ(got, each(rects, [&](const OrientedRect& e) { return intersects(q, e); }))
      << "oriented rect (" << q.center.x() << ", " << q.center.y() << ") half ("
      << q.halfExtents.x() << ", " << q.halfExtents.y() << ") rotation " << q.rotation;
  containing(q.center, rects, got);
  ASSERT_EQ(got, each(rects, [&](const OrientedRect& e) { return contains(e, q.center); }));
}

class Batch2d : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Batch2d);

TEST_P(Batch2d, RandomQueriesEqualTheScalarTests) {
  // Sizes that leave a partial last vector on every width.
  const CircleStream circles = randomCircles(51, 1001, 30);
  const RectStream rects = randomRects(52, 1003, 30);
  const OrientedRectStream orects = randomOrientedRects(53, 1005, 30);
  workloads::Random r(54);
  for (int q = 0; q < 300; ++q) {
    const Vec2f c(r.uniform(-35, 35), r.uniform(-35, 35));
    expectSameAsScalar(Circle{c, r.uniform(0, 6)}, circles);
    expectSameAsScalar(Rect::fromCenter(c, Vec2f(r.uniform(0, 6), r.uniform(0, 6))), rects);
    expectSameAsScalar(OrientedRect{c, Vec2f(r.uniform(0, 6), r.uniform(0, 6)), r.uniform(-4, 4)},
                       orects);
  }
  // Queries that are elements of the streams: identical shapes, shared centres.
  for (std::size_t i = 0; i < 1000; i += 37) {
    expectSameAsScalar(circles[i], circles);
    expectSameAsScalar(rects[i], rects);
    expectSameAsScalar(orects[i], orects);
  }
}

// Shapes placed to touch in exact arithmetic, so rounding and the tolerance decide: the cases
// where a kernel that computed anything differently from the scalar function would disagree.
TEST_P(Batch2d, NearlyTouchingShapesEqualTheScalarTests) {
  workloads::Random r(55);
  for (float scale : {1.0f, 1e5f}) {  // at 1e5 an ulp of a coordinate is 0.0078
    const Vec2f at(scale, -scale);
    CircleStream circles;
    OrientedRectStream orects;
    std::vector<Vec2f> points;
    for (int i = 0; i < 400; ++i) {
      const Vec2f c = at + Vec2f(r.uniform(-20, 20), r.uniform(-20, 20));
      const float radius = i % 7 == 0 ? 0.0f : r.uniform(0, 3);
      circles.push({c, radius});
      const float angle = r.uniform(-4, 4);
      points.push_back(c + radius * Vec2f(std::cos(angle), std::sin(angle)));  // on the circle
      const float rotation = i % 2 ? r.uniform(-4, 4) : float(int(r.uniform(0, 8))) * (kPi / 4);
      const OrientedRect b{c, Vec2f(r.uniform(0, 3), r.uniform(0, 3)), rotation};
      orects.push(b);
      const Mat2f axes = b.axes();
      points.push_back(c + axes * Vec2f(b.halfExtents.x(), r.uniform(-1, 1) * b.halfExtents.y()));
      points.push_back(c + axes * b.halfExtents);  // a corner
    }
    for (std::size_t i = 0; i < circles.size(); i += 3) {
      // A circle around another's centre point, its radius the distance to a third circle's edge.
      const Circle e = circles[(i * 7 + 1) % circles.size()];
      const Vec2f c = circles[i].center;
      expectSameAsScalar(Circle{c, std::max(0.0f, (e.center - c).norm() - e.radius)}, circles);
      // An oriented rectangle touching another along the other's local x axis.
      const OrientedRect b = orects[i];
      const float rotation = i % 2 ? b.rotation : r.uniform(-4, 4);
      OrientedRect q{b.center, Vec2f(r.uniform(0, 2), r.uniform(0, 2)), rotation};
      const Vec2f u = b.axes().col(0);
      const Mat2f qa = q.axes();
      const float reach = q.halfExtents.x() * std::abs(qa.col(0).dot(u)) +
                          q.halfExtents.y() * std::abs(qa.col(1).dot(u));
      q.center = b.center + (b.halfExtents.x() + reach) * u;
      expectSameAsScalar(q, orects);
    }
    Ids got;
    for (const Vec2f& p : points) {
      containing(p, circles, got);
      ASSERT_EQ(got, each(circles, [&](const Circle& e) { return contains(e, p); }));
      containing(p, orects, got);
      ASSERT_EQ(got, each(orects, [&](const OrientedRect& e) { return contains(e, p); }));
    }
  }
}

// Hand-worked: values exact in float, so the expected indices follow from the definitions.
TEST_P(Batch2d, TouchingAndZeroSizeShapesHandWorked) {
  CircleStream circles;
  circles.push({{3, 4}, 3});     // 0: centre distance 5 = 2 + 3, touches
  circles.push({{3, 4}, 2.5f});  // 1: 0.5 short of touching
  circles.push({{0, 0}, 0});     // 2: a point at the query's centre
  circles.push({{2, 0}, 0});     // 3: a point on the query's circle
  Ids got;
  overlapping(Circle{{0, 0}, 2}, circles, got);
  EXPECT_EQ(got, (Ids{0, 2, 3}));
  overlapping(Circle{{0, 0}, 0}, circles, got);  // a point query meets the point at it only
  EXPECT_EQ(got, (Ids{2}));
  containing({2, 0}, circles, got);  // on circle 0? |(2,0) - (3,4)| = sqrt(17) > 3: no
  EXPECT_EQ(got, (Ids{3}));
  containing({3, 7}, circles, got);  // on circle 0's top
  EXPECT_EQ(got, (Ids{0}));

  RectStream rects;
  rects.push({{2, -1}, {3, 1}});       // 0: left edge on x = 2, touches the query's right edge
  rects.push({{2.5f, 0}, {2.5f, 0}});  // 1: a point outside
  rects.push({{-1, -1}, {1, 1}});      // 2: inside
  rects.push({{-2, 2}, {2, 2}});       // 3: a segment along the query's top edge
  const Rect q{{-2, -2}, {2, 2}};
  overlapping(q, rects, got);
  EXPECT_EQ(got, (Ids{0, 2, 3}));
  containing({2, 0}, rects, got);  // on rect 0's left edge
  EXPECT_EQ(got, (Ids{0}));
  containing({2.5f, 0}, rects, got);  // the point rect
  EXPECT_EQ(got, (Ids{0, 1}));

  OrientedRectStream orects;
  orects.push(orect(4, 0, 2, 1, 0));        // 0: unrotated, left edge x = 2: touches
  orects.push(orect(4.5f, 0, 2, 1, 0));     // 1: a gap of 0.5
  orects.push(orect(0, 0, 0, 0, 0));        // 2: a point at the query's centre
  orects.push(orect(0, 3, 1, 1, kPi / 2));  // 3: a quarter turn, its edge at y = 2 +- rounding
  const OrientedRect box = orect(0, 0, 2, 2, 0);
  overlapping(box, orects, got);
  // Rect 3: cos(pi/2) is -4.4e-8 in float, so its extent along y is 1 + 4.4e-8 in exact
  // arithmetic, 1 once rounded: it reaches y = 2 and touches (and a gap of 4.4e-8 would still be
  // within the tolerance, 16 eps (3 + 2 + 2 + 1 + 1) = 1.7e-5).
  EXPECT_EQ(got, (Ids{0, 2, 3}));
  containing({2, 0}, orects, got);  // on rect 0's left edge
  EXPECT_EQ(got, (Ids{0}));
  containing({0, 0}, orects, got);  // the point rect
  EXPECT_EQ(got, (Ids{2}));
}

// Many equal rotations (parallel edges, both SAT axes tied), and the query an element.
TEST_P(Batch2d, ParallelEdgesAndLargeCoordinates) {
  for (const Vec2f& offset : {Vec2f(0, 0), Vec2f(1e5f, 1e5f), Vec2f(-1e5f, 3e4f)}) {
    OrientedRectStream orects;
    // A lattice of unit squares turned by the same angle, side by side along their own axes:
    // neighbours share edges in exact arithmetic.
    for (float rotation : {0.0f, 0.3f, kPi / 4, kPi / 2}) {
      const OrientedRect unit = orect(0, 0, 0.5f, 0.5f, rotation);
      const Mat2f axes = unit.axes();
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          orects.push({offset + axes * Vec2f(float(i), float(j)), unit.halfExtents, unit.rotation});
    }
    for (std::size_t i = 0; i < orects.size(); i += 5) expectSameAsScalar(orects[i], orects);
    const CircleStream circles = randomCircles(56, 300, 10, offset);
    const RectStream rects = randomRects(57, 300, 10, offset);
    for (std::size_t i = 0; i < 300; i += 7) {
      expectSameAsScalar(circles[i], circles);
      expectSameAsScalar(rects[i], rects);
    }
  }
}

TEST_P(Batch2d, EmptyAndTinyStreams) {
  Ids got{7};
  EXPECT_EQ(overlapping(Circle{{0, 0}, 1}, CircleStream(), got), 0u);
  EXPECT_TRUE(got.empty());
  EXPECT_EQ(containing({0, 0}, OrientedRectStream(), got), 0u);
  OrientedRectStream one;
  one.push(orect(0, 0, 1, 1, 0.5f));
  // Padding lanes (half extents -inf) must stay out even for an axis-aligned query, whose
  // projection on them multiplies -inf by 0.
  EXPECT_EQ(overlapping(orect(0, 0, 1, 1, 0), one, got), 1u);
  EXPECT_EQ(got, (Ids{0}));
  EXPECT_EQ(overlapping(orect(100, 0, 1, 1, 0), one, got), 0u);
}

// The plain loops the benchmarks compare against answer the same, on every SIMD target.
TEST_P(Batch2d, PlainLoopBaselinesAgree) {
  if (referencePathActive()) GTEST_SKIP() << "the baselines are compiled per SIMD target";
  const CircleStream circles = randomCircles(58, 500, 20);
  const RectStream rects = randomRects(59, 500, 20);
  const OrientedRectStream orects = randomOrientedRects(60, 500, 20);
  workloads::Random r(61);
  Ids simdIds, loopIds;
  auto both = [&](auto kernel, auto plain, const auto& query, const auto& stream) {
    simdIds.resize(stream.padded()), loopIds.resize(stream.padded());
    simdIds.resize(kernel(query2d(query), view(stream), simdIds.data()));
    loopIds.resize(plain(query2d(query), view(stream), loopIds.data()));
    EXPECT_EQ(simdIds, loopIds);
  };
  for (int q = 0; q < 50; ++q) {
    const Vec2f c(r.uniform(-20, 20), r.uniform(-20, 20));
    both(simd::circleOverlapsCircles, simd::circleOverlapsCirclesAutovec,
         Circle{c, r.uniform(0, 5)}, circles);
    both(simd::rectOverlapsRects, simd::rectOverlapsRectsAutovec, Rect::fromCenter(c, Vec2f(3, 2)),
         rects);
    both(simd::orientedRectOverlapsOrientedRects, simd::orientedRectOverlapsOrientedRectsAutovec,
         orect(c.x(), c.y(), 3, 2, r.uniform(-4, 4)), orects);
    both(simd::pointInCircles, simd::pointInCirclesAutovec, c, circles);
    both(simd::pointInRects, simd::pointInRectsAutovec, c, rects);
    both(simd::pointInOrientedRects, simd::pointInOrientedRectsAutovec, c, orects);
  }
}

TEST(Batch2dErrors, RejectBadQueries) {
  const CircleStream circles = randomCircles(62, 10, 5);
  const OrientedRectStream orects = randomOrientedRects(63, 10, 5);
  const RectStream rects = randomRects(64, 10, 5);
  Ids out;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expectError([&] { overlapping(Circle{{nan, 0}, 1}, circles, out); }, "overlapping: center.x");
  expectError([&] { overlapping(Circle{{0, 0}, -1}, circles, out); }, "overlapping: radius");
  expectError([&] { overlapping(Rect{{1, 0}, {0, 1}}, rects, out); }, "min.x (1) > max.x (0)");
  expectError([&] { overlapping(orect(0, 0, 1, nan, 0), orects, out); },
              "overlapping: halfExtents.y");
  expectError([&] { containing({0, nan}, circles, out); }, "containing: point.y");
}

TEST(Streams2d, RoundTripAndPadding) {
  CircleStream circles;
  circles.push({{1, 2}, 3});
  EXPECT_EQ(circles[0].center, Vec2f(1, 2));
  EXPECT_EQ(circles[0].radius, 3.0f);
  circles.set(0, {{4, 5}, 0});
  EXPECT_EQ(circles[0].radius, 0.0f);
  ASSERT_EQ(circles.padded(), kStreamPad);
  EXPECT_EQ(circles.field(fields::Circle::r)[1], -std::numeric_limits<float>::infinity());

  RectStream rects;
  rects.push({{1, 2}, {3, 4}});
  EXPECT_EQ(rects[0].max, Vec2f(3, 4));
  EXPECT_EQ(rects.field(fields::Rect::minX)[5], std::numeric_limits<float>::infinity());
  EXPECT_EQ(rects.field(fields::Rect::maxY)[5], -std::numeric_limits<float>::infinity());

  OrientedRectStream orects;
  const OrientedRect b = orect(1, 2, 3, 4, 0.7f);
  orects.push(b);
  EXPECT_EQ(orects[0].rotation, b.rotation);
  // The stored axes are OrientedRect::axes()'s, bit for bit.
  EXPECT_EQ(orects.field(fields::OrientedRect::cos)[0], b.axes()(0, 0));
  EXPECT_EQ(orects.field(fields::OrientedRect::sin)[0], b.axes()(1, 0));
  EXPECT_EQ(orects.field(fields::OrientedRect::hx)[3], -std::numeric_limits<float>::infinity());
}

TEST(Streams2d, RejectBadElementsNamingThem) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  CircleStream circles;
  circles.push({{0, 0}, 1});
  expectError([&] { circles.push({{0, nan}, 1}); }, "CircleStream::push: element 1: center.y");
  expectError([&] { circles.push({{0, 0}, -2}); }, "CircleStream::push: element 1: radius is -2");
  expectError([&] { circles.set(3, {{0, 0}, 1}); }, "CircleStream::set: element 3 is out of range");
  expectError([&] { circles.set(0, {{0, 0}, inf}); }, "CircleStream::set: element 0: radius");
  EXPECT_EQ(circles.size(), 1u);  // nothing was added by the failed calls
  RectStream rects;
  expectError(
      [&] {
        rects.push({{0, 3}, {1, 2}});
      },
      "RectStream::push: element 0: min.y (3) > max.y (2)");
  expectError(
      [&] {
        rects.set(0, {{0, 0}, {1, 1}});
      },
      "RectStream::set: element 0 is out of range");
  OrientedRectStream orects;
  expectError(
      [&] {
        orects.push({{0, 0}, {-1, 1}, 0});
      },
      "OrientedRectStream::push: element 0: halfExtents.x is -1");
  expectError(
      [&] {
        orects.push({{0, 0}, {1, 1}, inf});
      },
      "OrientedRectStream::push: element 0: rotation");
}

// ---- broadphase ---------------------------------------------------------------------------------

using test::bruteForcePairs;  // over intersects(Rect, Rect): the oracle (box_sets.hpp)

struct RectSet {
  std::string name;
  RectStream rects;
};

std::vector<RectSet> rectSets() {
  std::vector<RectSet> sets;
  sets.push_back({"random", randomRects(70, 2000, 60)});
  sets.push_back({"few", randomRects(74, 150, 15)});  // below kBruteBelow: kAuto's brute force
  sets.push_back({"random_at_1e5", randomRects(71, 1500, 20, Vec2f(1e5f, -1e5f))});
  // Unit squares on a unit lattice: every neighbour only touches (shared edges and corners), and
  // many minX are equal (ties in the sort).
  RectStream lattice;
  for (int x = 0; x < 30; ++x)
    for (int y = 0; y < 30; ++y)
      lattice.push({Vec2f(float(x), float(y)), Vec2f(x + 1.0f, y + 1.0f)});
  sets.push_back({"touching_lattice", std::move(lattice)});
  // Points, many coincident, some on other rectangles' edges.
  RectStream points;
  workloads::Random r(72);
  for (int i = 0; i < 800; ++i) {
    const Vec2f p(float(int(r.uniform(0, 8))), float(int(r.uniform(0, 8))));
    points.push({p, p});
    if (i % 3 == 0) points.push({p, p + Vec2f(1, 0)});  // a segment
  }
  sets.push_back({"zero_size", std::move(points)});
  RectStream same;
  for (int i = 0; i < 300; ++i) same.push({Vec2f(0, 0), Vec2f(1, 1)});
  sets.push_back({"identical", std::move(same)});
  RectStream mixed = randomRects(73, 1500, 50);
  for (int i = 0; i < 5; ++i) mixed.push({Vec2f::Constant(-60.0f + i), Vec2f::Constant(60.0f - i)});
  sets.push_back({"huge_among_small", std::move(mixed)});
  // Everything on the line y = 0: no height to cut into bands.
  RectStream flat;
  for (int i = 0; i < 700; ++i)
    flat.push({Vec2f(float(i % 50), 0), Vec2f(float(i % 50) + 1.5f, 0)});
  sets.push_back({"flat", std::move(flat)});
  // Many bands: a tall thin world, rectangles spanning from one band to several.
  RectStream tall;
  workloads::Random t(74);
  for (int i = 0; i < 3000; ++i) {
    const Vec2f c(t.uniform(-3, 3), t.uniform(-3000, 3000));
    tall.push(Rect::fromCenter(c, Vec2f(t.uniform(0, 1), i % 50 == 0 ? 200.0f : t.uniform(0, 2))));
  }
  sets.push_back({"tall_many_bands", std::move(tall)});
  RectStream tiny;
  tiny.push({{0, 0}, {1, 1}});
  sets.push_back({"one", std::move(tiny)});
  sets.push_back({"empty", RectStream()});
  return sets;
}

class Broadphase2d : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Broadphase2d);

TEST_P(Broadphase2d, EveryMethodEqualsBruteForce) {
  PairFinder2d finder;  // reused: its scratch memory must not leak between calls
  std::vector<Pair> pairs;
  for (const RectSet& set : rectSets()) {
    const std::vector<Pair> want = bruteForcePairs(set.rects);
    for (PairMethod2d method :
         {PairMethod2d::kAuto, PairMethod2d::kBandedSweep, PairMethod2d::kSweep,
          PairMethod2d::kBrute, PairMethod2d::kQuadtree}) {
      finder.find(set.rects, pairs, method);
      EXPECT_EQ(pairs, want) << set.name << ", method " << int(method);
    }
    findPairs(set.rects, pairs);  // the default method
    EXPECT_EQ(pairs, want) << set.name;
  }
}

// Bands whose pairs fill several of the pair sorter's chunks, over two buckets of a: the sweeps
// deal them to the sorter in parts, and the parts come out as one sorted list.
TEST_P(Broadphase2d, ManyBandsOfManyPairsComeOutSorted) {
  static const RectStream rects = [] {
    RectStream s;
    workloads::Random r(75);
    for (int i = 0; i < 8000; ++i)
      s.push(Rect::fromCenter(Vec2f(r.uniform(-1, 1), r.uniform(-2000, 2000)),
                              Vec2f(r.uniform(0, 1), r.uniform(0, 4))));
    return s;
  }();
  static const std::vector<Pair> want = bruteForcePairs(rects);  // the same on every path
  ASSERT_GT(want.size(), 40'000u);
  PairFinder2d finder;
  std::vector<Pair> pairs;
  for (PairMethod2d method : {PairMethod2d::kBandedSweep, PairMethod2d::kSweep}) {
    finder.find(rects, pairs, method);
    EXPECT_EQ(pairs, want) << "method " << int(method);
  }
}

TEST_P(Broadphase2d, PlainLoopBaselinesEqualBruteForce) {
  if (referencePathActive()) GTEST_SKIP() << "the baselines are compiled per SIMD target";
  test::PlainLoopPairFinder2d finder;
  std::vector<Pair> pairs;
  for (const RectSet& set : rectSets()) {
    const std::vector<Pair> want = bruteForcePairs(set.rects);
    for (PairMethod2d method :
         {PairMethod2d::kBandedSweep, PairMethod2d::kSweep, PairMethod2d::kBrute}) {
      finder.find(set.rects, pairs, method);
      EXPECT_EQ(pairs, want) << set.name << ", method " << int(method);
    }
  }
}

// The standard 2D workload (W7): the reference figures of docs/workloads.md, at a size the test
// can brute-force.
TEST_P(Broadphase2d, WorkloadReferenceFigures) {
  const workloads::Shapes2dWorkload w = workloads::makeShapes2dWorkload(3000);
  std::vector<Pair> pairs;
  findPairs(w.bounds, pairs);
  EXPECT_EQ(pairs, bruteForcePairs(w.bounds));
  const workloads::Shapes2dReference& ref = workloads::shapes2dReference(3000);
  EXPECT_EQ(pairs.size(), ref.boundPairs);
  EXPECT_EQ(workloads::collidingPairs(w, pairs), ref.collidingPairs);
}

}  // namespace
}  // namespace simdphys

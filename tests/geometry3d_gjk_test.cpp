// Tests of include/simdphys/geometry3d/gjk.hpp (support functions, GJK distance and
// intersection, EPA penetration), in float and in double.
//
// Every expected value comes from a closed form or an oracle written here, in double, on the
// double shapes the inputs were rounded from (never from another library header): centre-line
// formulas for spheres, clamping for sphere-box, per-axis gaps and overlaps for box-box, a dense
// barycentric sampling for point-triangle, a 15-axis separating-axis test for OBB-OBB, and for
// mixed pairs a certificate (both points lie in their shapes and the direction between them
// separates the shapes by the distance; EPA's depth is the overlap along its normal and no
// sampled direction overlaps less).
//
// Tolerances are in units of eps * L: eps the machine epsilon of the scalar under test (1.19e-7
// for float, 2.22e-16 for double) and L the size of the problem (the span of the coordinates
// involved). One rounding of an input coordinate is eps/2 * L; GJK's answer is a short sum of
// products of such numbers, a few eps * L; the library stops its iterations at 16 eps * L
// (kGjkTolerance). So the bounds are 64 eps * L unless stated, with the measured maxima printed
// as "[ accuracy ]" lines.
#include "simdphys/geometry3d/gjk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "workloads.hpp"

namespace simdphys {
namespace {

template <class T>
constexpr double kEps = std::numeric_limits<T>::epsilon();

// ---- accuracy bookkeeping ------------------------------------------------------------------

// The largest error seen, in absolute terms and in units of eps * L; printed when destroyed.
struct Worst {
  std::string what;
  double eps;
  double units = 0, absolute = 0;
  int count = 0;
  Worst(std::string w, double e) : what(std::move(w)), eps(e) {}
  void add(double error, double scale) {
    ++count;
    absolute = std::max(absolute, error);
    units = std::max(units, error / (eps * scale));
  }
  ~Worst() {
    if (count == 0) return;
    std::printf("[ accuracy ] %-58s %6d cases, max error %.3g = %.2f eps*L\n", what.c_str(), count,
                absolute, units);
  }
};

template <class T>
std::string typeName() {
  return std::is_same_v<T, float> ? "float" : "double";
}

bool finite(const Vec3d& v) { return v.allFinite(); }

// ---- the shapes GJK was given, in double ------------------------------------------------------

// Each coordinate passes through a volatile on its way from T to double. GCC 12.2 at -O3 (its
// SLP vectorizer) was seen to hand on the double a float had been rounded from, in place of that
// float, for two lanes of a Vec3 (double -> float -> double folded away): the reference then
// missed the rounding GJK saw. The volatile keeps the conversion honest.
template <class U>
double seenScalar(U x) {
  volatile U v = x;
  return double(v);
}
template <class U>
Vec3d seenVec(const Vec3<U>& p) {
  const double x = seenScalar(p[0]), y = seenScalar(p[1]);
  return Vec3d(x, y, seenScalar(p[2]));
}
template <class U>
Sphered seen(const SphereT<U>& s) {
  return {seenVec(s.center), seenScalar(s.radius)};
}
template <class U>
Aabbd seen(const AabbT<U>& b) {
  return {seenVec(b.min), seenVec(b.max)};
}
template <class U>
Triangled seen(const TriangleT<U>& t) {
  return {seenVec(t.a), seenVec(t.b), seenVec(t.c)};
}
template <class U>
Segmentd seen(const SegmentT<U>& t) {
  return {seenVec(t.start), seenVec(t.end)};
}

// ---- random shapes (double, float-representable where that matters) -------------------------

struct Rng {
  scenes::Random r;
  explicit Rng(std::uint64_t seed) : r(seed) {}
  double u(double a, double b) { return r.uniform(float(a), float(b)); }
  Vec3d dir() { return r.unitDirection().cast<double>(); }
  Vec3d point(double lo, double hi) {  // x, y, z drawn in this order (arguments are unsequenced)
    const double x = u(lo, hi), y = u(lo, hi);
    return Vec3d(x, y, u(lo, hi));
  }
  // A rotation built in double, orthonormal to rounding in double (the float direction is
  // normalised again in double: AngleAxis needs a unit axis).
  Mat3d rotation() {
    const double angle = u(0, 2 * std::numbers::pi);
    return Eigen::AngleAxisd(angle, dir().normalized()).toRotationMatrix();
  }
};

// ---- closed forms and oracles, in double ----------------------------------------------------

Vec3d clampToAabb(const Vec3d& p, const Aabbd& b) { return p.cwiseMax(b.min).cwiseMin(b.max); }

Vec3d closestOnObb(const Vec3d& p, const Obbd& b) {
  const Vec3d local = b.axes.transpose() * (p - b.center);
  return b.center + b.axes * local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents);
}

Vec3d closestOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double l2 = ab.squaredNorm();
  if (l2 == 0) return a;
  return a + std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) * ab;
}

// Ericson, Real-Time Collision Detection 5.1.5, with a fallback to the edges for a flat triangle.
Vec3d closestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= 1e-24 * ab.squaredNorm() * ac.squaredNorm()) {
    Vec3d best = closestOnSegment(p, a, b);
    for (const Vec3d& q : {closestOnSegment(p, b, c), closestOnSegment(p, c, a)})
      if ((q - p).norm() < (best - p).norm()) best = q;
    return best;
  }
  const Vec3d ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

std::array<Vec3d, 8> corners(const Obbd& b) {
  std::array<Vec3d, 8> c;
  for (int i = 0; i < 8; ++i) {
    Vec3d p = b.center;
    for (int k = 0; k < 3; ++k) p += ((i >> k) & 1 ? 1.0 : -1.0) * b.halfExtents[k] * b.axes.col(k);
    c[std::size_t(i)] = p;
  }
  return c;
}

// A convex hull for the tests: the corners of an OBB (so containment has a closed form), some
// repeated, plus interior points.
template <class T>
struct HullShape {
  Obbd source;
  std::vector<Vec3<T>> points;
  ConvexHullT<T> view() const { return {points}; }
};

HullShape<double> makeHull(const Obbd& box, Rng& rng) {
  HullShape<double> h{box, {}};
  for (const Vec3d& c : corners(box)) h.points.push_back(c);
  h.points.push_back(h.points[3]);  // repeated points
  h.points.push_back(h.points[0]);
  for (int i = 0; i < 4; ++i)  // interior points
    h.points.push_back(box.center + box.axes * rng.point(-0.9, 0.9).cwiseProduct(box.halfExtents));
  return h;
}

template <class U>
HullShape<U> castHull(const HullShape<double>& h) {
  HullShape<U> r{h.source, {}};
  for (const Vec3d& p : h.points) r.points.push_back(p.cast<U>());
  return r;
}

// Distance from a point to each shape (0 inside), the largest and smallest of x.n over the shape.
double distanceTo(const Sphered& s, const Vec3d& p) {
  return std::max(0.0, (p - s.center).norm() - s.radius);
}
double distanceTo(const Aabbd& b, const Vec3d& p) { return (clampToAabb(p, b) - p).norm(); }
double distanceTo(const Obbd& b, const Vec3d& p) { return (closestOnObb(p, b) - p).norm(); }
double distanceTo(const Triangled& t, const Vec3d& p) {
  return (closestOnTriangle(p, t.a, t.b, t.c) - p).norm();
}
double distanceTo(const Segmentd& s, const Vec3d& p) {
  return (closestOnSegment(p, s.start, s.end) - p).norm();
}
double distanceTo(const HullShape<double>& h, const Vec3d& p) { return distanceTo(h.source, p); }

double maxDot(const Sphered& s, const Vec3d& n) { return s.center.dot(n) + s.radius * n.norm(); }
double maxDot(const Aabbd& b, const Vec3d& n) {
  double m = 0;
  for (int k = 0; k < 3; ++k) m += std::max(b.min[k] * n[k], b.max[k] * n[k]);
  return m;
}
double maxDot(const Obbd& b, const Vec3d& n) {
  double m = -INFINITY;
  for (const Vec3d& c : corners(b)) m = std::max(m, c.dot(n));
  return m;
}
double maxDot(const Triangled& t, const Vec3d& n) {
  return std::max({t.a.dot(n), t.b.dot(n), t.c.dot(n)});
}
double maxDot(const Segmentd& s, const Vec3d& n) { return std::max(s.start.dot(n), s.end.dot(n)); }
double maxDot(const HullShape<double>& h, const Vec3d& n) {
  double m = -INFINITY;
  for (const Vec3d& p : h.points) m = std::max(m, p.dot(n));
  return m;
}
template <class S>
double minDot(const S& s, const Vec3d& n) {
  return -maxDot(s, Vec3d(-n));
}

// The size of a shape: the span of its coordinates from the origin.
double extent(const Sphered& s) { return s.center.cwiseAbs().maxCoeff() + s.radius; }
double extent(const Aabbd& b) {
  return std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
}
double extent(const Obbd& b) { return b.center.cwiseAbs().maxCoeff() + b.halfExtents.sum(); }
double extent(const Triangled& t) {
  return std::max(
      {t.a.cwiseAbs().maxCoeff(), t.b.cwiseAbs().maxCoeff(), t.c.cwiseAbs().maxCoeff()});
}
double extent(const Segmentd& s) {
  return std::max(s.start.cwiseAbs().maxCoeff(), s.end.cwiseAbs().maxCoeff());
}
double extent(const HullShape<double>& h) { return extent(h.source); }

[[maybe_unused]] Sphered translated(const Sphered& s, const Vec3d& t) {
  return {s.center + t, s.radius};
}
Aabbd translated(const Aabbd& b, const Vec3d& t) { return {b.min + t, b.max + t}; }
Obbd translated(const Obbd& b, const Vec3d& t) { return {b.center + t, b.halfExtents, b.axes}; }
Triangled translated(const Triangled& s, const Vec3d& t) { return {s.a + t, s.b + t, s.c + t}; }
Segmentd translated(const Segmentd& s, const Vec3d& t) { return {s.start + t, s.end + t}; }
HullShape<double> translated(const HullShape<double>& h, const Vec3d& t) {
  HullShape<double> r{translated(h.source, t), h.points};
  for (Vec3d& p : r.points) p += t;
  return r;
}

// The shape in scalar U, as GJK takes it.
template <class U>
SphereT<U> inScalar(const Sphered& s) {
  return cast<U>(s);
}
template <class U>
AabbT<U> inScalar(const Aabbd& s) {
  return cast<U>(s);
}
template <class U>
ObbT<U> inScalar(const Obbd& s) {
  return cast<U>(s);
}
template <class U>
TriangleT<U> inScalar(const Triangled& s) {
  return cast<U>(s);
}
template <class U>
SegmentT<U> inScalar(const Segmentd& s) {
  return cast<U>(s);
}
template <class U>
HullShape<U> inScalar(const HullShape<double>& s) {
  return castHull<U>(s);
}
template <class S>
const S& view(const S& s) {
  return s;
}
template <class U>
ConvexHullT<U> view(const HullShape<U>& h) {
  return h.view();
}

// Separating-axis oracle for two OBBs, in double: the largest separation over the 15 axes
// (normalised), and that axis oriented from A to B. Positive: separated (by at least that much).
// Negative: overlapping, and since the faces of the Minkowski difference of two boxes have
// exactly these 15 normals, minus it is the penetration depth.
struct Sat {
  double separation = -INFINITY;
  Vec3d axis = Vec3d::UnitX();
  double runnerUp = -INFINITY;  // the next largest, on an axis not parallel to the first
};
Sat satOracle(const Obbd& a, const Obbd& b) {
  std::vector<Vec3d> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(a.axes.col(i)), axes.push_back(b.axes.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3d c = a.axes.col(i).cross(b.axes.col(j));
      if (c.norm() > 1e-9) axes.push_back(c.normalized());  // parallel edges: a face axis covers it
    }
  const Vec3d t = b.center - a.center;
  Sat s;
  std::vector<std::pair<double, Vec3d>> all;
  for (const Vec3d& l : axes) {
    double ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i)
      ra += a.halfExtents[i] * std::abs(a.axes.col(i).dot(l)),
          rb += b.halfExtents[i] * std::abs(b.axes.col(i).dot(l));
    const double sep = std::abs(t.dot(l)) - ra - rb;
    all.emplace_back(sep, t.dot(l) >= 0 ? l : Vec3d(-l));
  }
  std::sort(all.begin(), all.end(), [](auto& x, auto& y) { return x.first > y.first; });
  s.separation = all[0].first, s.axis = all[0].second;
  for (std::size_t i = 1; i < all.size(); ++i)
    if (std::abs(all[i].second.dot(s.axis)) < 1 - 1e-9) {
      s.runnerUp = all[i].first;
      break;
    }
  return s;
}

template <class T>
class Gjk : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Gjk, Scalars);

template <class T>
Vec3<T> v3(double x, double y, double z) {
  return Vec3<T>(T(x), T(y), T(z));
}

// Largest absolute component difference, in double.
template <class DA, class DB>
double maxDiff(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  return (a.template cast<double>() - b.template cast<double>()).cwiseAbs().maxCoeff();
}

// ---- support functions ----------------------------------------------------------------------

TYPED_TEST(Gjk, SupportHandWorked) {
  using T = TypeParam;
  const double tol = 4 * kEps<T> * 4;  // a normalisation and one product, on values up to 4
  const SphereT<T> s{v3<T>(1, 2, 3), T(2)};
  // (3, 0, 4) / 5 * 2 = (1.2, 0, 1.6); the direction's length does not matter.
  EXPECT_LE(maxDiff(support(s, v3<T>(30, 0, 40)), Vec3d(2.2, 2, 4.6)), tol);
  EXPECT_LE(maxDiff(support(s, v3<T>(3e-30, 0, 4e-30)), Vec3d(2.2, 2, 4.6)), tol);  // no underflow
  EXPECT_EQ(support(s, Vec3<T>::Zero()), s.center);  // zero direction: the centre
  const AabbT<T> b{v3<T>(-1, -2, -3), v3<T>(1, 2, 3)};
  EXPECT_EQ(support(b, v3<T>(1, -1, 0)), v3<T>(1, -2, 3));  // 0 picks max
  EXPECT_EQ(support(b, Vec3<T>::Zero()), b.max);
  // An OBB turned a quarter about z: local x is world y, local y is world -x.
  ObbT<T> o{v3<T>(10, 0, 0), v3<T>(1, 2, 3), Mat3<T>::Identity()};
  o.axes << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  // Along (1, 1, -1): local x (+y world) +1, local y (-x world) -2 -> +2 in x, local z -3.
  EXPECT_LE(maxDiff(support(o, v3<T>(1, 1, -1)), Vec3d(12, 1, -3)), 0.0);
  const TriangleT<T> t{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_EQ(support(t, v3<T>(1, 0.5, 0)), t.b);
  EXPECT_EQ(support(t, v3<T>(-1, 2, 0)), t.c);
  EXPECT_EQ(support(t, v3<T>(0, 0, 1)), t.a);  // a tie goes to the first vertex
  const SegmentT<T> g{v3<T>(0, 0, 0), v3<T>(0, 0, 5)};
  EXPECT_EQ(support(g, v3<T>(0, 0, 1)), g.end);
  EXPECT_EQ(support(g, v3<T>(0, 1, -1)), g.start);
  const std::vector<Vec3<T>> pts = {v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 3, 0)};
  const ConvexHullT<T> h{pts};
  EXPECT_EQ(support(h, v3<T>(1, 0.1, 0)), pts[1]);
  EXPECT_EQ(support(h, v3<T>(0, 1, 0)), pts[3]);
  EXPECT_EQ(support(h, Vec3<T>::Zero()), pts[0]);
  EXPECT_THROW(support(ConvexHullT<T>{}, v3<T>(1, 0, 0)), Error);
  // A capsule as segment + sphere: the segment's end plus the radius along the direction.
  const MinkowskiSumT<SegmentT<T>, SphereT<T>> capsule{g, {Vec3<T>::Zero(), T(1)}};
  EXPECT_LE(maxDiff(support(capsule, v3<T>(0, 3, 4)), Vec3d(0, 0.6, 5.8)), tol);
  const MinkowskiDifferenceT<AabbT<T>, SegmentT<T>> diff{b, g};
  EXPECT_EQ(support(diff, v3<T>(1, 1, 1)), v3<T>(1, 2, 3));  // max of b minus min of g (start)
}

// ---- sphere pairs ---------------------------------------------------------------------------

TYPED_TEST(Gjk, SphereSphereRandomAgainstCentreLine) {
  using T = TypeParam;
  Worst dist("sphere-sphere distance, " + typeName<T>(), kEps<T>);
  Worst points("sphere-sphere closest points, " + typeName<T>(), kEps<T>);
  Worst depth("sphere-sphere EPA depth, " + typeName<T>(), kEps<T>);
  Worst normal("sphere-sphere EPA normal (|n - u|, L = 1), " + typeName<T>(), kEps<T>);
  Rng rng(101);
  for (int i = 0; i < 4000; ++i) {
    const Sphered a{rng.point(-10, 10), rng.u(0.1, 3)};
    const double rb = rng.u(0.1, 3);
    // Half the pairs within 1e-3 of touching, the others anywhere up to 3 apart or deep.
    const double gap = i % 2 ? rng.u(-1e-3, 1e-3) : rng.u(-3, 3);
    const Vec3d u = rng.dir();
    const Sphered b{a.center + (a.radius + rb + gap) * u, rb};
    const SphereT<T> at = inScalar<T>(a), bt = inScalar<T>(b);
    const Sphered ar = seen(at), br = seen(bt);  // the shapes GJK saw
    const Vec3d cr = br.center - ar.center;
    const double truth = cr.norm() - ar.radius - br.radius;
    const Vec3d ur = cr.normalized();
    const double L = extent(ar) + extent(br);
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(at, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    ASSERT_TRUE(finite(r.pointA.template cast<double>()) && std::isfinite(double(r.distance)));
    if (truth > tol) {
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      const Vec3d pa = ar.center + ar.radius * ur, pb = br.center - br.radius * ur;
      points.add(std::max(maxDiff(r.pointA, pa), maxDiff(r.pointB, pb)), L);
      ASSERT_LE(maxDiff(r.pointA, pa), tol) << i;
      ASSERT_LE(maxDiff(r.pointB, pb), tol) << i;
      EXPECT_FALSE(epa(at, bt).has_value());
    } else if (truth < -tol) {
      ASSERT_TRUE(r.intersecting) << i;
      EXPECT_EQ(r.distance, T(0));
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value()) << i;
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      depth.add(std::abs(p->depth + truth), L);
      ASSERT_LE(std::abs(p->depth + truth), tol) << i;
      // The normal is the centre line: its error is the centres' rounding over their distance.
      if (cr.norm() > 1e-3 * L) {
        const double ntol = 64 * kEps<T> * L / cr.norm();
        normal.add(maxDiff(p->normal, ur), 1);
        ASSERT_LE(maxDiff(p->normal, ur), ntol) << i;
      }
      // pointA - pointB = depth * normal, both on their spheres.
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
      ASSERT_LE(std::abs((p->pointA.template cast<double>() - ar.center).norm() - ar.radius), tol);
      ASSERT_LE(std::abs((p->pointB.template cast<double>() - br.center).norm() - br.radius), tol);
    } else {
      // Within rounding of touching: whatever the flag, the distance is tiny.
      ASSERT_LE(double(r.distance), 2 * tol) << i;
    }
  }
}

// ---- sphere-AABB ----------------------------------------------------------------------------

TYPED_TEST(Gjk, SphereAabbRandomAgainstClamping) {
  using T = TypeParam;
  Worst dist("sphere-AABB distance, " + typeName<T>(), kEps<T>);
  Worst points("sphere-AABB closest points, " + typeName<T>(), kEps<T>);
  Worst depth("sphere-AABB EPA depth (centre outside or inside), " + typeName<T>(), kEps<T>);
  Rng rng(202);
  int inside = 0, shallow = 0, apart = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3d lo = rng.point(-5, 5);
    const Aabbd box{lo, lo + rng.point(0.1, 4)};
    const double radius = i % 5 == 0 ? 0.0 : rng.u(0.05, 2);
    // Centres around the box; a third of them pushed onto a face, edge or corner + radius + tiny.
    Vec3d c = box.center() + (box.halfExtents() * 1.6).cwiseProduct(rng.point(-1, 1));
    if (i % 3 == 0) {
      const Vec3d q = clampToAabb(c, box);
      if ((c - q).norm() > 0) c = q + (c - q).normalized() * (radius + rng.u(-1e-3, 1e-3));
    }
    const SphereT<T> st{c.cast<T>(), T(radius)};
    const AabbT<T> bt = inScalar<T>(box);
    const Sphered s = seen(st);
    const Aabbd b = seen(bt);
    const double L = extent(s) + extent(b);
    const double tol = 64 * kEps<T> * L;
    const Vec3d q = clampToAabb(s.center, b);
    const double outside = (s.center - q).norm();
    const double truth = outside - s.radius;  // valid when the centre is outside
    const GjkResultT<T> r = gjkDistance(st, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (outside > 0 && truth > tol) {
      ++apart;
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      const Vec3d n = (q - s.center) / outside;
      points.add(std::max(maxDiff(r.pointA, s.center + s.radius * n), maxDiff(r.pointB, q)), L);
      ASSERT_LE(maxDiff(r.pointB, q), tol) << i;
      ASSERT_LE(maxDiff(r.pointA, s.center + s.radius * n), tol) << i;
    } else if (outside > tol && truth < -tol) {
      ++shallow;  // the centre outside the box, the sphere dipping in: along centre to clamp
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(st, bt);
      ASSERT_TRUE(p.has_value());
      depth.add(std::abs(p->depth + truth), L);
      ASSERT_LE(std::abs(p->depth + truth), tol) << i;
      ASSERT_LE(maxDiff(p->normal, (q - s.center) / outside), 64 * kEps<T> * L / outside) << i;
    } else if (outside == 0) {
      // The centre inside: out through the nearest face, depth = that gap + radius, normal minus
      // the face's outward normal (B moves the other way). Checked where the nearest face is
      // clear (the next is 1e-3 L farther).
      std::array<std::pair<double, Vec3d>, 6> faces;
      for (int k = 0; k < 3; ++k) {
        faces[2 * k] = {b.max[k] - s.center[k], -Vec3d::Unit(k)};
        faces[2 * k + 1] = {s.center[k] - b.min[k], Vec3d::Unit(k)};
      }
      std::sort(faces.begin(), faces.end(), [](auto& x, auto& y) { return x.first < y.first; });
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(st, bt);
      ASSERT_TRUE(p.has_value());
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      const double expected = faces[0].first + s.radius;
      if (faces[1].first - faces[0].first > 1e-3 * L) {
        ++inside;
        depth.add(std::abs(p->depth - expected), L);
        ASSERT_LE(std::abs(p->depth - expected), tol) << i;
        ASSERT_LE(maxDiff(p->normal, faces[0].second), 64 * kEps<T>) << i;
      }
    }
  }
  // The generator must hit every branch often (a test that skips everything cannot fail).
  EXPECT_GT(apart, 500);
  EXPECT_GT(shallow, 200);
  EXPECT_GT(inside, 200);
}

// ---- AABB pairs -----------------------------------------------------------------------------

TYPED_TEST(Gjk, AabbAabbRandomAgainstAxisGaps) {
  using T = TypeParam;
  Worst dist("AABB-AABB distance (per-axis gaps), " + typeName<T>(), kEps<T>);
  Worst depth("AABB-AABB EPA depth (least overlap axis), " + typeName<T>(), kEps<T>);
  Rng rng(303);
  int separated = 0, overlapping = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3d lo = rng.point(-3, 3);
    const Aabbd a0{lo, lo + rng.point(0.1, 3)};
    const Vec3d h = rng.point(0.05, 1.5);
    Vec3d c = a0.center() + (a0.halfExtents() + h).cwiseProduct(rng.point(-1.3, 1.3));
    if (i % 3 == 0) {  // snap one axis to within 1e-3 of touching
      const int k = i % 9 / 3;
      c[k] = a0.center()[k] +
             (c[k] > a0.center()[k] ? 1 : -1) * (a0.halfExtents()[k] + h[k] + rng.u(-1e-3, 1e-3));
    }
    const AabbT<T> at = inScalar<T>(a0), bt = inScalar<T>(Aabbd::fromCenter(c, h));
    const Aabbd a = seen(at), b = seen(bt);
    const double L = extent(a) + extent(b);
    const double tol = 64 * kEps<T> * L;
    const Vec3d gaps = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0);
    const double truth = gaps.norm();
    const GjkResultT<T> r = gjkDistance(at, bt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (truth > tol) {
      ++separated;
      ASSERT_FALSE(r.intersecting) << i;
      dist.add(std::abs(r.distance - truth), L);
      ASSERT_LE(std::abs(r.distance - truth), tol) << i;
      // The closest points lie in their boxes and differ by the gap vector (B - A per axis).
      ASSERT_LE(distanceTo(a, r.pointA.template cast<double>()), tol);
      ASSERT_LE(distanceTo(b, r.pointB.template cast<double>()), tol);
    } else if (gaps.maxCoeff() == 0) {
      // Overlap on every axis: B must move by the least of the six overlaps.
      std::array<std::pair<double, Vec3d>, 6> moves;
      for (int k = 0; k < 3; ++k) {
        moves[2 * k] = {a.max[k] - b.min[k], Vec3d::Unit(k)};
        moves[2 * k + 1] = {b.max[k] - a.min[k], -Vec3d::Unit(k)};
      }
      std::sort(moves.begin(), moves.end(), [](auto& x, auto& y) { return x.first < y.first; });
      ASSERT_TRUE(r.intersecting) << i;
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value());
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      ++overlapping;
      depth.add(std::abs(p->depth - moves[0].first), L);
      ASSERT_LE(std::abs(p->depth - moves[0].first), tol) << i;
      if (moves[1].first - moves[0].first > 1e-3 * L) {  // a clear minimum: the axis is known
        ASSERT_LE(maxDiff(p->normal, moves[0].second), 64 * kEps<T>) << i;
      }
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
    }
  }
  EXPECT_GT(separated, 1000);
  EXPECT_GT(overlapping, 300);
}

// ---- point-triangle -------------------------------------------------------------------------

TYPED_TEST(Gjk, PointTriangleAgainstBarycentricSampling) {
  using T = TypeParam;
  Worst dist("point-triangle distance vs sampling (minus its bound), " + typeName<T>(), kEps<T>);
  Rng rng(404);
  constexpr int N = 300;  // grid steps per edge: 45,451 samples per triangle
  for (int i = 0; i < 150; ++i) {
    const TriangleT<T> tt{rng.point(-2, 2).cast<T>(), rng.point(-2, 2).cast<T>(),
                          rng.point(-2, 2).cast<T>()};
    const Triangled t = seen(tt);
    // Points near the plane, the edges and the corners, some on the triangle itself.
    Vec3d p = rng.point(-3, 3);
    if (i % 4 == 1) p = (t.a + t.b) / 2 + rng.u(-0.01, 0.01) * rng.dir();
    if (i % 4 == 2) p = t.c + rng.u(0, 0.5) * rng.dir();
    if (i % 4 == 3) p = (t.a + t.b + t.c) / 3 + rng.u(-1, 1) * t.normal().normalized();
    const SphereT<T> point{p.cast<T>(), T(0)};
    const Vec3d pr = seenVec(point.center);
    const Vec3d e1 = t.b - t.a, e2 = t.c - t.a;
    double oracle = INFINITY;
    for (int u = 0; u <= N; ++u)
      for (int v = 0; u + v <= N; ++v)
        oracle = std::min(oracle, (t.a + (u * e1 + v * e2) / N - pr).norm());
    // The nearest grid point to the true closest point is at most (|e1| + |e2|) / N away.
    const double grid = (e1.norm() + e2.norm()) / N;
    const double L = extent(t) + pr.cwiseAbs().maxCoeff();
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(point, tt);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    ASSERT_LE(double(r.distance), oracle + tol) << i;
    ASSERT_GE(double(r.distance), oracle - grid - tol) << i;
    dist.add(std::max(0.0, std::abs(double(r.distance) - oracle) - grid), L);
    // The point on the triangle lies on it, and is the distance away.
    ASSERT_LE(distanceTo(t, r.pointB.template cast<double>()), tol) << i;
    if (!r.intersecting) {
      ASSERT_LE(std::abs((r.pointB - r.pointA).norm() - r.distance), tol) << i;
    }
  }
}

// ---- OBB pairs against the 15-axis SAT ------------------------------------------------------

TYPED_TEST(Gjk, ObbObbRandomAgainstSat) {
  using T = TypeParam;
  Worst depth("OBB-OBB EPA depth vs SAT least overlap, " + typeName<T>(), kEps<T>);
  Worst lower("OBB-OBB distance below SAT separation, " + typeName<T>(), kEps<T>);
  Rng rng(505);
  int agree = 0, ambiguous = 0, maxGjk = 0, maxEpa = 0;
  for (int i = 0; i < 3000; ++i) {
    const Obbd a0{rng.point(-2, 2), rng.point(0.1, 2), rng.rotation()};
    Obbd b0{Vec3d::Zero(), rng.point(0.1, 2), rng.rotation()};
    // B's centre at (1 + s) times the sum of the two boxes' radii along a random direction, s
    // within 0.1 (many near-touching), sometimes deep inside.
    const Vec3d u = rng.dir();
    double reach = 0;
    for (int k = 0; k < 3; ++k)
      reach += a0.halfExtents[k] * std::abs(a0.axes.col(k).dot(u)) +
               b0.halfExtents[k] * std::abs(b0.axes.col(k).dot(u));
    b0.center = a0.center + u * reach * (i % 4 == 0 ? rng.u(0, 0.9) : 1 + rng.u(-0.1, 0.1));
    const ObbT<T> at = inScalar<T>(a0), bt = inScalar<T>(b0);
    // The oracle sees the double boxes; the float ones differ by input rounding (within tol).
    const Sat sat = satOracle(a0, b0);
    const double L = extent(a0) + extent(b0);
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(at, bt);
    maxGjk = std::max(maxGjk, r.iterations);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    EXPECT_EQ(gjkIntersect(bt, at), gjkIntersect(at, bt)) << i;
    if (std::abs(sat.separation) <= tol) {
      ++ambiguous;
      ASSERT_LE(double(r.distance), 2 * tol);
      continue;
    }
    ++agree;
    ASSERT_EQ(r.intersecting, sat.separation < 0) << i << " sat " << sat.separation;
    if (sat.separation > 0) {
      // The SAT separation is a lower bound of the distance.
      lower.add(std::max(0.0, sat.separation - r.distance), L);
      ASSERT_GE(double(r.distance), sat.separation - tol) << i;
      ASSERT_LE(distanceTo(a0, r.pointA.template cast<double>()), tol);
      ASSERT_LE(distanceTo(b0, r.pointB.template cast<double>()), tol);
      EXPECT_FALSE(epa(at, bt).has_value());
    } else {
      const auto p = epa(at, bt);
      ASSERT_TRUE(p.has_value()) << i;
      maxEpa = std::max(maxEpa, p->iterations);
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      depth.add(std::abs(p->depth + sat.separation), L);
      ASSERT_LE(std::abs(p->depth + sat.separation), tol) << i;
      if (sat.runnerUp - sat.separation < -1e-3 * L) {       // a clear least-overlap axis
        ASSERT_LE(maxDiff(p->normal, sat.axis), 1e-3) << i;  // see below
      }
      ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
    }
  }
  // The normal bound: a normal off by angle a changes the overlap by about a^2 / 2 * L only when
  // the axis is a minimum, so a 1e-3 L clear minimum pins the normal to well under 1e-3.
  std::printf(
      "[ accuracy ] OBB-OBB %s: %d decided, %d within tolerance of touching, max GJK "
      "iterations %d, max EPA iterations %d\n",
      typeName<T>().c_str(), agree, ambiguous, maxGjk, maxEpa);
  EXPECT_GT(agree, 2800);
}

// ---- mixed random pairs: certificates -------------------------------------------------------

// Sample directions for EPA's minimality check: the 3 axes, 200 random unit vectors.
std::vector<Vec3d> sampleDirections() {
  std::vector<Vec3d> d = {Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ()};
  Rng rng(9);
  for (int i = 0; i < 200; ++i) d.push_back(rng.dir());
  return d;
}

struct MixedStats {
  int separated = 0, intersecting = 0, ambiguous = 0, maxGjk = 0, maxEpa = 0;
};

template <class T, class SA, class SB>
void checkPair(const SA& a, const SB& b, const std::vector<Vec3d>& dirs, Worst& gap, Worst& pen,
               Worst& vsDouble, MixedStats& stats, const std::string& where) {
  const auto at = inScalar<T>(a);
  const auto bt = inScalar<T>(b);
  const double L = extent(a) + extent(b);
  const double tol = 64 * kEps<T> * L;
  const GjkResultT<T> r = gjkDistance(view(at), view(bt));
  SCOPED_TRACE(where);
  stats.maxGjk = std::max(stats.maxGjk, r.iterations);
  ASSERT_LT(r.iterations, kGjkMaxIterations);
  const Vec3d pa = r.pointA.template cast<double>(), pb = r.pointB.template cast<double>();
  ASSERT_TRUE(finite(pa) && finite(pb) && std::isfinite(double(r.distance)));
  // Both points lie in their shapes.
  ASSERT_LE(distanceTo(a, pa), tol);
  ASSERT_LE(distanceTo(b, pb), tol);
  // Symmetric: B against A gives the same distance.
  const GjkResultT<T> s = gjkDistance(view(bt), view(at));
  ASSERT_LE(std::abs(double(s.distance) - double(r.distance)), tol);
  // The double answer, certified below; a float answer agrees with it to the float bound.
  const GjkResultd d = gjkDistance(view(inScalar<double>(a)), view(inScalar<double>(b)));
  if constexpr (std::is_same_v<T, float>) {
    vsDouble.add(std::abs(double(r.distance) - d.distance), L);
    ASSERT_LE(std::abs(double(r.distance) - d.distance), tol);
  }
  if (r.intersecting != d.intersecting) {
    // Float and double disagree only within the float bound of touching.
    ASSERT_LE(d.distance, 2 * tol);
    ++stats.ambiguous;
    return;
  }
  if (!r.intersecting) {
    ++stats.separated;
    ASSERT_GT(r.distance, T(0));
    ASSERT_LE(std::abs((pb - pa).norm() - double(r.distance)), tol);
    // The certificate, on the double answer: along n = (pb - pa) / |pb - pa| the shapes are
    // apart by the distance, so no two of their points are closer. The direction carries the
    // points' rounding (eps L) over their distance: the separation along it may fall short by
    // that angle times the shapes' size, eps L * L / distance.
    const Vec3d n = (d.pointB - d.pointA).normalized();
    const double separation = minDot(b, n) - maxDot(a, n);
    const double dtol = 64 * kEps<double> * L * (1 + 2 * L / d.distance);
    gap.add(std::max(0.0, d.distance - separation), L * (1 + 2 * L / d.distance));
    ASSERT_GE(separation, d.distance - dtol);
    ASSERT_FALSE(epa(view(at), view(bt)).has_value());
    return;
  }
  // Intersecting: the common point is in both shapes (checked above, pa == pb).
  ASSERT_LE(maxDiff(r.pointA, r.pointB), 0.0);
  const auto p = epa(view(at), view(bt));
  ASSERT_TRUE(p.has_value());
  ++stats.intersecting;
  stats.maxEpa = std::max(stats.maxEpa, p->iterations);
  ASSERT_LT(p->iterations, kEpaMaxIterations);
  const Vec3d n = p->normal.template cast<double>();
  ASSERT_LE(std::abs(n.norm() - 1), 8 * kEps<T>);
  ASSERT_GE(p->depth, T(0));
  ASSERT_LE(maxDiff(p->pointA - p->pointB, p->depth * p->normal), tol);
  // The depth is the overlap along the normal (moving B by it makes them touch) ...
  const double along = maxDot(a, n) - minDot(b, n);
  pen.add(std::abs(double(p->depth) - along), L);
  ASSERT_LE(std::abs(double(p->depth) - along), tol);
  // ... and no other direction overlaps less: it is the least translation (within tol).
  for (const Vec3d& l : dirs)
    for (const Vec3d& m : {l, Vec3d(-l)})
      ASSERT_GE(maxDot(a, m) - minDot(b, m), double(p->depth) - tol) << m.transpose();
  ASSERT_LE(distanceTo(a, p->pointA.template cast<double>()), tol);
  ASSERT_LE(distanceTo(b, p->pointB.template cast<double>()), tol);
}

TYPED_TEST(Gjk, MixedRandomPairsCertified) {
  using T = TypeParam;
  Worst gap("mixed pairs: double distance above certified separation (L(1+2L/d))", kEps<double>);
  Worst pen("mixed pairs: EPA depth vs overlap along its normal, " + typeName<T>(), kEps<T>);
  Worst vsDouble("mixed pairs: float distance vs double GJK, float", kEps<T>);
  const std::vector<Vec3d> dirs = sampleDirections();
  MixedStats stats;
  Rng rng(606);
  for (int i = 0; i < 150; ++i) {
    const Vec3d c = rng.point(-1, 1);
    auto near = [&]() -> Vec3d { return c + rng.point(-1.5, 1.5); };
    const Sphered sphere{near(), rng.u(0.1, 1)};
    const Vec3d lo = near();
    const Aabbd aabb{lo, lo + rng.point(0.1, 1.5)};
    const Obbd obb{near(), rng.point(0.1, 1), rng.rotation()};
    const Triangled tri{near(), near(), near()};
    const Segmentd seg{near(), near()};
    const HullShape<double> hull = makeHull(Obbd{near(), rng.point(0.1, 1), rng.rotation()}, rng);
    // Each pair as generated, and moved to within 1e-3 of touching along GJK's direction (or,
    // if it overlaps, pushed in by up to 10% of its depth from touching).
    auto both = [&](const auto& a, const auto& b, const char* name) {
      const std::string where = std::string(name) + " #" + std::to_string(i);
      checkPair<T>(a, b, dirs, gap, pen, vsDouble, stats, where);
      const GjkResultd d = gjkDistance(view(a), view(b));
      if (!d.intersecting) {
        const Vec3d n = (d.pointB - d.pointA) / d.distance;
        const auto moved = translated(b, -n * (d.distance + rng.u(-1e-3, 1e-3)));
        checkPair<T>(a, moved, dirs, gap, pen, vsDouble, stats, where + " near touching");
      } else if (const auto p = epa(view(a), view(b))) {
        const auto moved = translated(b, p->normal * p->depth * rng.u(0.9, 1.001));
        checkPair<T>(a, moved, dirs, gap, pen, vsDouble, stats, where + " nearly apart");
      }
    };
    both(sphere, aabb, "sphere-aabb");
    both(sphere, obb, "sphere-obb");
    both(sphere, tri, "sphere-triangle");
    both(sphere, seg, "sphere-segment");
    both(sphere, hull, "sphere-hull");
    both(aabb, obb, "aabb-obb");
    both(aabb, tri, "aabb-triangle");
    both(obb, tri, "obb-triangle");
    both(obb, seg, "obb-segment");
    both(obb, hull, "obb-hull");
    both(hull, tri, "hull-triangle");
    both(hull, seg, "hull-segment");
    both(tri, seg, "triangle-segment");
    both(seg, Segmentd{near(), near()}, "segment-segment");
    both(tri, Triangled{near(), near(), near()}, "triangle-triangle");
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf(
      "[ accuracy ] mixed pairs %s: %d separated, %d intersecting, %d within the float "
      "bound of touching, max GJK iterations %d, max EPA iterations %d\n",
      typeName<T>().c_str(), stats.separated, stats.intersecting, stats.ambiguous, stats.maxGjk,
      stats.maxEpa);
  EXPECT_GT(stats.separated, 1000);
  EXPECT_GT(stats.intersecting, 1000);
}

// ---- named hard cases -----------------------------------------------------------------------

// Touching shapes: distance exactly 0 in exact arithmetic. Where the inputs are exact (small
// integers) GJK's arithmetic is exact too and the answer is 0; otherwise within 64 eps * L.
TYPED_TEST(Gjk, TouchingFaceFace) {
  using T = TypeParam;
  const AabbT<T> a{v3<T>(0, 0, 0), v3<T>(1, 1, 1)}, b{v3<T>(1, 0.25, -0.5), v3<T>(2, 3, 0.5)};
  const GjkResultT<T> r = gjkDistance(a, b);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(std::abs(double(r.pointA.x()) - 1), 4 * kEps<T>);  // on the shared face
  const auto p = epa(a, b);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0));
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), 0.0);
  // The same with two OBBs turned alike (rounded axes): within tolerance.
  const Mat3<T> rot = Eigen::AngleAxis<T>(T(0.7), v3<T>(1, 2, 3).normalized()).toRotationMatrix();
  const ObbT<T> oa{v3<T>(0.5, 0.5, 0.5), v3<T>(0.5, 1, 1), rot};
  const ObbT<T> ob{oa.center + rot.col(0) * T(1.25), v3<T>(0.75, 0.5, 0.5), rot};
  const double tol = 64 * kEps<T> * 4;  // L = 4
  const GjkResultT<T> s = gjkDistance(oa, ob);
  EXPECT_TRUE(s.intersecting);
  EXPECT_LE(double(s.distance), tol);
  const auto q = epa(oa, ob);
  ASSERT_TRUE(q.has_value());
  EXPECT_LE(double(q->depth), tol);
  EXPECT_LE(maxDiff(q->normal, rot.col(0)), 1e-3);  // the face normal (rounding: far below)
}

TYPED_TEST(Gjk, TouchingEdgeEdge) {
  using T = TypeParam;
  // Two crossing segments meeting at the origin.
  const SegmentT<T> a{v3<T>(-1, 0, 0), v3<T>(1, 0, 0)}, b{v3<T>(0, -1, 0), v3<T>(0, 3, 0)};
  const GjkResultT<T> r = gjkDistance(a, b);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(maxDiff(r.pointA, Vec3d::Zero()), 4 * kEps<T>);  // barycentric weights' rounding
  // Two boxes turned 45 degrees, one about z (top edge along z at y = 2s), one about x (bottom
  // edge along x at y = 2s): their edges cross at (0, 2s, 0). s = sqrt(1/2) rounded, the same
  // in both boxes, so the touching is exact up to the rounding of 4s - 2s.
  const T s = std::sqrt(T(0.5));
  ObbT<T> za{Vec3<T>::Zero(), v3<T>(1, 1, 1), Mat3<T>::Identity()};
  za.axes << s, -s, 0, s, s, 0, 0, 0, 1;
  ObbT<T> xb{v3<T>(0, 4 * s, 0), v3<T>(1, 1, 1), Mat3<T>::Identity()};
  xb.axes << 1, 0, 0, 0, s, -s, 0, s, s;
  const double tol = 64 * kEps<T> * 6;  // L = 6
  const GjkResultT<T> g = gjkDistance(za, xb);
  EXPECT_TRUE(g.intersecting);
  EXPECT_LE(double(g.distance), tol);
  EXPECT_LE(maxDiff(g.pointA, Vec3d(0, 2 * double(s), 0)), tol);
  const auto p = epa(za, xb);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(double(p->depth), tol);
  // Apart by 1e-3 along y: the distance is exactly that gap, between the crossing edges.
  const ObbT<T> apart{xb.center + v3<T>(0, 0.001, 0), xb.halfExtents, xb.axes};
  const GjkResultT<T> d = gjkDistance(za, apart);
  EXPECT_FALSE(d.intersecting);
  EXPECT_LE(std::abs(double(d.distance) - 0.001), tol);
}

TYPED_TEST(Gjk, TouchingVertexFace) {
  using T = TypeParam;
  // A triangle standing on the top face of a box with one vertex; a hull doing the same.
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  const TriangleT<T> t{v3<T>(0.25, 1, 0.5), v3<T>(2, 3, 0), v3<T>(-1, 4, 1)};
  const GjkResultT<T> r = gjkDistance(t, box);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(maxDiff(r.pointA, Vec3d(0.25, 1, 0.5)), 64 * kEps<T> * 4);
  const auto p = epa(box, t);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(double(p->depth), 64 * kEps<T> * 4);
  const std::vector<Vec3<T>> pyramid = {v3<T>(0, 1, 0), v3<T>(-1, 2, -1), v3<T>(1, 2, -1),
                                        v3<T>(0, 2, 1)};
  EXPECT_TRUE(gjkIntersect(box, ConvexHullT<T>{pyramid}));
  // Touching spheres: centres r1 + r2 apart on an axis.
  EXPECT_TRUE(gjkIntersect(SphereT<T>{v3<T>(0, 0, 0), T(1)}, SphereT<T>{v3<T>(3, 0, 0), T(2)}));
  EXPECT_EQ(
      gjkDistance(SphereT<T>{v3<T>(0, 0, 0), T(1)}, SphereT<T>{v3<T>(3, 0, 0), T(2)}).distance,
      T(0));
}

// Deep penetration: one shape wholly inside the other.
TYPED_TEST(Gjk, DeepPenetration) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 10;  // L = 10
  const AabbT<T> big{v3<T>(-4, -3, -5), v3<T>(4, 3, 5)};
  const AabbT<T> small{v3<T>(0.5, 1, -1), v3<T>(1.5, 2, 1)};
  // B (small) leaves by moving +y by big.max.y - small.min.y = 2, the least of 3.5 (+x),
  // 5.5 (-x), 2 (+y), 5 (-y), 6 (+z), 6 (-z).
  auto p = epa(big, small);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2), tol);
  EXPECT_LE(maxDiff(p->normal, Vec3d(0, 1, 0)), tol);
  // A sphere inside the box: its centre 1 from the -x face, radius 0.5: depth 1.5 along +x
  // (the box, as B, moves +x).
  p = epa(SphereT<T>{v3<T>(-3, 0, 0), T(0.5)}, big);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1.5), tol);
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), tol);
  // Concentric spheres: depth r1 + r2, any unit normal.
  p = epa(SphereT<T>{v3<T>(1, 2, 3), T(2)}, SphereT<T>{v3<T>(1, 2, 3), T(0.5)});
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2.5), tol);
  EXPECT_LE(std::abs(double(p->normal.norm()) - 1), tol);
  // An OBB deep in an OBB turned the same way: the same as boxes in that frame.
  const Mat3<T> rot =
      Eigen::AngleAxis<T>(T(1.1), v3<T>(-1, 2, 0.5).normalized()).toRotationMatrix();
  const ObbT<T> outer{v3<T>(1, 1, 1), v3<T>(4, 3, 5), rot};
  const ObbT<T> inner{outer.center + rot * v3<T>(2.5, 0, 0), v3<T>(0.5, 0.5, 0.5), rot};
  p = epa(outer, inner);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2), tol);  // 4 - 2.5 + 0.5 along local +x
  EXPECT_LE(maxDiff(p->normal, rot.col(0)), tol);
}

TYPED_TEST(Gjk, IdenticalShapes) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 8;
  const Mat3<T> rot = Eigen::AngleAxis<T>(T(0.4), v3<T>(0, 1, 1).normalized()).toRotationMatrix();
  const ObbT<T> o{v3<T>(3, -2, 1), v3<T>(0.5, 2, 1), rot};
  const GjkResultT<T> r = gjkDistance(o, o);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  auto p = epa(o, o);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1), tol);  // twice the least half extent, 0.5
  EXPECT_LE(std::abs(std::abs(double(p->normal.dot(rot.col(0)))) - 1), tol);
  const SphereT<T> s{v3<T>(1, 1, 1), T(0.75)};
  p = epa(s, s);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1.5), tol);
  // A triangle against itself: flat, so the depth is 0 along its normal.
  const TriangleT<T> t{v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 2, 0)};
  p = epa(t, t);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0));
  EXPECT_LE(std::abs(std::abs(double(p->normal.z())) - 1), tol);
  const std::vector<Vec3<T>> pts = {v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(0, 0, 1)};
  p = epa(ConvexHullT<T>{pts}, ConvexHullT<T>{pts});
  ASSERT_TRUE(p.has_value());
  // The tetrahedron against itself: the least translation is its least width, the distance
  // from a vertex to the opposite face: 1/sqrt(3) (from the origin to x + y + z = 1).
  EXPECT_LE(std::abs(double(p->depth) - 1 / std::sqrt(3.0)), tol);
}

TYPED_TEST(Gjk, DegenerateTriangleAndRepeatedPoints) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 8;
  // Collinear vertices: the triangle is the segment from (0,0,0) to (4,0,0).
  const TriangleT<T> line{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(1, 0, 0)};
  for (const auto& [p, expected] : std::vector<std::pair<Vec3<T>, double>>{{v3<T>(2, 3, 4), 5.0},
                                                                           {v3<T>(-3, 0, 4), 5.0},
                                                                           {v3<T>(7, 4, 0), 5.0},
                                                                           {v3<T>(2, 0, 0), 0.0}}) {
    const GjkResultT<T> r = gjkDistance(SphereT<T>{p, T(0)}, line);
    EXPECT_TRUE(std::isfinite(r.distance));
    EXPECT_LE(std::abs(double(r.distance) - expected), tol) << p.transpose();
  }
  // All three vertices the same: a point.
  const TriangleT<T> dot{v3<T>(1, 1, 1), v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  EXPECT_LE(std::abs(double(gjkDistance(SphereT<T>{v3<T>(1, 1, 4), T(1)}, dot).distance) - 2), tol);
  // A flat triangle cutting a box: finite depth (the box must leave the plane's way).
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  const auto p = epa(box, line);
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(std::isfinite(p->depth) && p->normal.allFinite());
  // The segment through the box from x = 0 to 4 leaves by moving it 1 in y or z, or 1 in -x.
  EXPECT_LE(std::abs(double(p->depth) - 1), tol);
  // Hulls with repeated and collinear points; a zero-size box; a zero-length segment.
  const std::vector<Vec3<T>> rep = {v3<T>(3, 0, 0), v3<T>(3, 0, 0), v3<T>(3, 0, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(ConvexHullT<T>{rep}, box).distance) - 2), tol);
  const std::vector<Vec3<T>> col = {v3<T>(3, 0, 0), v3<T>(5, 0, 0), v3<T>(4, 0, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(ConvexHullT<T>{col}, box).distance) - 2), tol);
  const AabbT<T> point{v3<T>(0, 5, 0), v3<T>(0, 5, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(point, box).distance) - 4), tol);
  const SegmentT<T> zero{v3<T>(0, 0, 3), v3<T>(0, 0, 3)};
  EXPECT_LE(std::abs(double(gjkDistance(zero, box).distance) - 2), tol);
  const auto q = epa(zero, AabbT<T>{v3<T>(-1, -1, 2.5), v3<T>(1, 1, 4)});
  ASSERT_TRUE(q.has_value());  // a point inside a box: out through the nearest face, 0.5 away
  EXPECT_LE(std::abs(double(q->depth) - 0.5), tol);
  EXPECT_LE(maxDiff(q->normal, Vec3d(0, 0, 1)), tol);  // the box (B) moves +z
}

// Coordinates of 1e5 with sizes of 1e-2. A float there is spaced 2^-7 = 0.0078, so a float
// computation in world coordinates would be wrong by about the size of the shapes. GJK works
// relative to a point of A, from each shape's own data: the distance keeps float's relative
// precision of the 1e-2 problem (bound 64 eps * L with L = 0.1, not 1e5); only the returned points
// carry their world rounding (bound: half a spacing, 2^-8, plus that).
TYPED_TEST(Gjk, LargeCoordinatesSmallShapes) {
  using T = TypeParam;
  Worst dist("at 1e5, sizes 1e-2: distance (L = 0.1), " + typeName<T>(), kEps<T>);
  Worst pen("at 1e5, sizes 1e-2: EPA depth (L = 0.1), " + typeName<T>(), kEps<T>);
  const double L = 0.1;
  const double tol = 64 * kEps<T> * L;
  const double pointTol = 0.5 * 0x1p-7 + tol;  // for T = double, a tiny part of this is used
  Rng rng(707);
  for (int i = 0; i < 500; ++i) {
    // The shapes in float (what a float user has), then exactly in double for the reference.
    const Vec3f base(1e5f + float(rng.u(-1, 1)), 1e5f, -1e5f);
    const Vec3f h1 = rng.point(0.002, 0.01).cast<float>();
    const Vec3f h2 = rng.point(0.002, 0.01).cast<float>();
    const Vec3f off = (rng.point(-0.03, 0.03)).cast<float>();
    const Aabb af = Aabb::fromCenter(base, h1), bf = Aabb::fromCenter(base + off, h2);
    const Aabbd a = seen(af), b = seen(bf);
    const Vec3d gaps = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0);
    const GjkResultT<T> r = gjkDistance(inScalar<T>(a), inScalar<T>(b));
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (gaps.norm() > tol) {
      dist.add(std::abs(double(r.distance) - gaps.norm()), L);
      ASSERT_LE(std::abs(double(r.distance) - gaps.norm()), tol) << i;
      ASSERT_LE(distanceTo(a, r.pointA.template cast<double>()), pointTol) << i;
    } else if (gaps.maxCoeff() == 0) {
      double least = INFINITY;
      for (int k = 0; k < 3; ++k)
        least = std::min({least, a.max[k] - b.min[k], b.max[k] - a.min[k]});
      const auto p = epa(inScalar<T>(a), inScalar<T>(b));
      ASSERT_TRUE(p.has_value()) << i;
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      pen.add(std::abs(double(p->depth) - least), L);
      ASSERT_LE(std::abs(double(p->depth) - least), tol) << i;
    }
    // OBBs (turned in float) and a point against a triangle, whose supports compute at 1e5:
    // the double reference runs on the same float shapes, exactly converted; the OBB verdict
    // also against the SAT oracle, the point-triangle distance against the closed form.
    const Mat3f rot = Eigen::AngleAxisf(float(rng.u(0, 6.28)), rng.dir().cast<float>().normalized())
                          .toRotationMatrix();
    const Obb oa{base, h1, rot}, ob{base + off, h2, rot * Eigen::AngleAxisf(0.5f, Vec3f::UnitZ())};
    const Obbd oad{seenVec(oa.center), seenVec(oa.halfExtents), oa.axes.cast<double>()};
    const Obbd obd{seenVec(ob.center), seenVec(ob.halfExtents), ob.axes.cast<double>()};
    const GjkResultT<T> o = gjkDistance(inScalar<T>(oad), inScalar<T>(obd));
    const GjkResultd od = gjkDistance(oad, obd);
    ASSERT_LT(o.iterations, kGjkMaxIterations);
    dist.add(std::abs(double(o.distance) - od.distance), L);
    ASSERT_LE(std::abs(double(o.distance) - od.distance), tol) << i;
    // The float axes are orthonormal to 1e-7 only: the oracle's face normals are off by that
    // times the 1e-2 sizes, 1e-9, far below tol for float; the verdict is compared past both.
    const Sat sat = satOracle(oad, obd);
    if (std::abs(sat.separation) > tol + 1e-8) {
      ASSERT_EQ(o.intersecting, sat.separation < 0) << i;
    }
    const Triangle tf{base + rng.point(-0.02, 0.02).cast<float>(),
                      base + rng.point(-0.02, 0.02).cast<float>(),
                      base + rng.point(-0.02, 0.02).cast<float>()};
    const Vec3f pf = base + rng.point(-0.03, 0.03).cast<float>();
    const Triangled td{seenVec(tf.a), seenVec(tf.b), seenVec(tf.c)};
    const Vec3d pd = seenVec(pf);
    // The oracle too works relative to the shapes (at 1e5 double's own rounding is 1e-11); the
    // subtractions are exact (Sterbenz: the values are within a factor of 2).
    const Vec3d at = base.cast<double>();
    const double toTriangle =
        (closestOnTriangle(pd - at, td.a - at, td.b - at, td.c - at) - (pd - at)).norm();
    const GjkResultT<T> t = gjkDistance(SphereT<T>{pd.cast<T>(), T(0)}, inScalar<T>(td));
    ASSERT_LT(t.iterations, kGjkMaxIterations);
    if (toTriangle > tol) {
      dist.add(std::abs(double(t.distance) - toTriangle), L);
      ASSERT_LE(std::abs(double(t.distance) - toTriangle), tol) << i;
    }
    // Spheres there too: centre line.
    const Sphere sa{base, h1.x()}, sb{base + off, h2.x()};
    const double truth =
        (seen(sb).center - seen(sa).center).norm() - double(sa.radius) - double(sb.radius);
    const GjkResultT<T> s = gjkDistance(inScalar<T>(seen(sa)), inScalar<T>(seen(sb)));
    ASSERT_LT(s.iterations, kGjkMaxIterations);
    if (truth > tol) {
      dist.add(std::abs(double(s.distance) - truth), L);
      ASSERT_LE(std::abs(double(s.distance) - truth), tol) << i;
    }
  }
}

// Tiny shapes (1e-6) near the origin and near 1: the answer scales with them (the tolerances
// are relative to the shapes, L = 1e-5, not to 1).
TYPED_TEST(Gjk, TinyShapes) {
  using T = TypeParam;
  Worst dist("tiny 1e-6 shapes: distance (L = 1e-5), " + typeName<T>(), kEps<T>);
  for (const double where : {0.0, 1.0}) {
    Rng rng(808);
    for (int i = 0; i < 300; ++i) {
      const Vec3d c0 = Vec3d::Constant(where);
      const Vec3d c1 = c0 + rng.point(-3e-6, 3e-6);
      // Round the shapes to T first; the oracle uses exactly those.
      const SphereT<T> st{c0.cast<T>(), T(rng.u(0.2e-6, 1e-6))};
      const AabbT<T> bt{c1.cast<T>(), (c1 + rng.point(0.2e-6, 1e-6)).cast<T>()};
      const Sphered s = seen(st);
      const Aabbd b = seen(bt);
      const double L = 1e-5;  // the shapes' own span, wherever they are
      const double tol = 64 * kEps<T> * L;
      const Vec3d q = clampToAabb(s.center, b);
      const double truth = (q - s.center).norm() - s.radius;
      const GjkResultT<T> r = gjkDistance(st, bt);
      ASSERT_LT(r.iterations, kGjkMaxIterations);
      if ((q - s.center).norm() > 0 && truth > tol) {
        dist.add(std::abs(double(r.distance) - truth), L);
        ASSERT_LE(std::abs(double(r.distance) - truth), tol)
            << i << " at " << where << " d " << r.distance << " truth " << truth << " q "
            << q.transpose() << " c " << s.center.transpose() << " r " << s.radius << " bmin "
            << b.min.transpose() << " btmin " << bt.min.transpose().template cast<double>();
      } else if (truth < -tol && (q - s.center).norm() > 0) {
        const auto p = epa(st, bt);
        ASSERT_TRUE(p.has_value());
        ASSERT_LE(std::abs(double(p->depth) + truth), tol) << i;
      }
    }
  }
}

// Parallel box faces: the Minkowski difference of two boxes turned alike has large flat faces
// made of coplanar triangles, where EPA's new points are coplanar with old faces.
TYPED_TEST(Gjk, ParallelBoxFacesEpa) {
  using T = TypeParam;
  Worst pen("parallel faces: EPA depth vs per-axis overlap, " + typeName<T>(), kEps<T>);
  const AabbT<T> a{v3<T>(0, 0, 0), v3<T>(2, 2, 2)};
  // Equal y and z extents, overlapping by 1 in x: depth 1 along +x.
  auto p = epa(a, AabbT<T>{v3<T>(1, 0, 0), v3<T>(3, 2, 2)});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(1));
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), 0.0);
  // Flat on flat: the same footprint, 0.5 deep in z.
  p = epa(a, AabbT<T>{v3<T>(0, 0, 1.5), v3<T>(2, 2, 3.5)});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0.5));
  EXPECT_LE(maxDiff(p->normal, Vec3d(0, 0, 1)), 0.0);
  // Random boxes turned alike (rounded axes), with coincident face planes on some axes.
  Rng rng(909);
  for (int i = 0; i < 500; ++i) {
    const Mat3d rot = rng.rotation();
    const Vec3d ha = rng.point(0.2, 2);
    Vec3d hb = rng.point(0.2, 2);
    Vec3d local((ha + hb).cwiseProduct(rng.point(-0.9, 0.9)));
    if (i % 2) hb[i % 3] = ha[i % 3], local[i % 3] = 0;  // coincident faces on one axis
    const Obbd ad{rng.point(-3, 3), ha, rot};
    const Obbd bd{ad.center + rot * local, hb, rot};
    double least = INFINITY;
    for (int k = 0; k < 3; ++k) least = std::min(least, ha[k] + hb[k] - std::abs(local[k]));
    const double L = extent(ad) + extent(bd);
    const double tol = 64 * kEps<T> * L;
    const auto q = epa(inScalar<T>(ad), inScalar<T>(bd));
    ASSERT_TRUE(q.has_value()) << i;
    ASSERT_LT(q->iterations, kEpaMaxIterations);
    pen.add(std::abs(double(q->depth) - least), L);
    ASSERT_LE(std::abs(double(q->depth) - least), tol) << i;
  }
}

// A capsule (segment + sphere as a Minkowski sum) against a sphere: distance between the
// segment and the centre minus both radii.
TYPED_TEST(Gjk, CapsuleAsMinkowskiSum) {
  using T = TypeParam;
  Rng rng(1010);
  for (int i = 0; i < 500; ++i) {
    const Segmentd seg{rng.point(-2, 2), rng.point(-2, 2)};
    const double rc = rng.u(0.1, 1), rs = rng.u(0.1, 1);
    const Vec3d c = rng.point(-3, 3);
    const MinkowskiSumT<SegmentT<T>, SphereT<T>> capsule{inScalar<T>(seg),
                                                         {Vec3<T>::Zero(), T(rc)}};
    const SphereT<T> sphere{c.cast<T>(), T(rs)};
    const double truth =
        (closestOnSegment(seenVec(sphere.center), seen(capsule.a).start, seen(capsule.a).end) -
         seenVec(sphere.center))
            .norm() -
        double(T(rc)) - double(T(rs));
    const double L = 8;
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(capsule, sphere);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (truth > tol) {
      ASSERT_LE(std::abs(double(r.distance) - truth), tol) << i;
    } else if (truth < -tol) {
      ASSERT_TRUE(r.intersecting);
      const auto p = epa(capsule, sphere);
      ASSERT_TRUE(p.has_value());
      // Centre off the segment: the depth is the centre-line one.
      if (truth + double(T(rc)) + double(T(rs)) > 1e-3) {
        ASSERT_LE(std::abs(double(p->depth) + truth), tol) << i;
      }
    }
  }
}

// A translation of B by slightly more than EPA's depth along its normal separates the shapes,
// and slightly less does not: the answer is usable as a contact.
TYPED_TEST(Gjk, EpaTranslationSeparates) {
  using T = TypeParam;
  Rng rng(1111);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Obbd a{rng.point(-1, 1), rng.point(0.2, 1), rng.rotation()};
    const Obbd b{rng.point(-1, 1), rng.point(0.2, 1), rng.rotation()};
    const auto p = epa(inScalar<T>(a), inScalar<T>(b));
    if (!p || p->depth < T(0.01)) continue;
    ASSERT_LT(p->iterations, kEpaMaxIterations);
    ++checked;
    const Vec3d n = p->normal.template cast<double>();
    const double d = double(p->depth);
    const double L = extent(a) + extent(b);
    const double margin = 1e3 * kEps<T> * L;  // well beyond GJK's touching tolerance
    EXPECT_FALSE(gjkIntersect(inScalar<T>(a), inScalar<T>(translated(b, n * (d + margin))))) << i;
    EXPECT_TRUE(gjkIntersect(inScalar<T>(a), inScalar<T>(translated(b, n * (d - margin))))) << i;
  }
  EXPECT_GT(checked, 100);
}

// GJK on the Minkowski difference A - B against a point at the origin is GJK on A and B: the
// same distance (the difference's core and radius are built from A's and B's). Sums and
// differences nest.
TYPED_TEST(Gjk, MinkowskiDifferenceAgainstOrigin) {
  using T = TypeParam;
  Rng rng(1212);
  const SphereT<T> origin{Vec3<T>::Zero(), T(0)};
  for (int i = 0; i < 300; ++i) {
    const ObbT<T> a = inScalar<T>(Obbd{rng.point(-2, 2), rng.point(0.1, 1), rng.rotation()});
    const SphereT<T> b{rng.point(-2, 2).cast<T>(), T(rng.u(0.1, 1))};
    const double tol = 64 * kEps<T> * 8;  // L = 8: coordinates and sizes up to 4 each
    const GjkResultT<T> direct = gjkDistance(a, b);
    const GjkResultT<T> viaDifference =
        gjkDistance(MinkowskiDifferenceT<ObbT<T>, SphereT<T>>{a, b}, origin);
    ASSERT_LT(viaDifference.iterations, kGjkMaxIterations);
    ASSERT_EQ(direct.intersecting, viaDifference.intersecting) << i;
    ASSERT_LE(std::abs(double(direct.distance) - double(viaDifference.distance)), tol) << i;
  }
  // A sum holding a difference: (segment - point) + sphere is a capsule moved by -point.
  const SegmentT<T> seg{v3<T>(0, 0, 0), v3<T>(4, 0, 0)};
  const MinkowskiSumT<MinkowskiDifferenceT<SegmentT<T>, SphereT<T>>, SphereT<T>> capsule{
      {seg, {v3<T>(1, 0, 0), T(0)}}, {Vec3<T>::Zero(), T(0.5)}};
  // The capsule spans x in [-1, 3] with radius 0.5: a point at (2, 3, 0) is 2.5 away.
  EXPECT_LE(std::abs(double(gjkDistance(capsule, SphereT<T>{v3<T>(2, 3, 0), T(0)}).distance) - 2.5),
            64 * kEps<T> * 4);
}

// Non-finite input is the caller's to reject (validate()); it must still not hang or crash:
// every loop is capped.
TYPED_TEST(Gjk, NonFiniteInputTerminates) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  for (const SphereT<T>& bad : {SphereT<T>{v3<T>(nan, 0, 0), T(1)}, SphereT<T>{v3<T>(0, 0, 0), nan},
                                SphereT<T>{v3<T>(inf, 0, 0), T(1)}}) {
    const GjkResultT<T> r = gjkDistance(bad, box);
    EXPECT_LE(r.iterations, kGjkMaxIterations);
    const auto p = epa(bad, box);
    if (p) {
      EXPECT_LE(p->iterations, kEpaMaxIterations);
    }
  }
}

}  // namespace
}  // namespace simdphys

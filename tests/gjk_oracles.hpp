// Shared by the GJK/EPA suites (geometry3d_gjk_test.cpp, geometry3d_gjk_hard_test.cpp): accuracy
// bookkeeping, the shapes in double, random shapes, and the closed forms and oracles in double
// that every expected value comes from (never from another library header).
#pragma once

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

#include "simdphys/geometry3d/epa.hpp"
#include "typed.hpp"
#include "workloads.hpp"

namespace simdphys::test {

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

inline bool finite(const Vec3d& v) { return v.allFinite(); }

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
  workloads::Random r;
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

inline Vec3d clampToAabb(const Vec3d& p, const Aabbd& b) {
  return p.cwiseMax(b.min).cwiseMin(b.max);
}

inline Vec3d closestOnObb(const Vec3d& p, const Obbd& b) {
  const Vec3d local = b.axes.transpose() * (p - b.center);
  return b.center + b.axes * local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents);
}

inline Vec3d closestOnSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double l2 = ab.squaredNorm();
  if (l2 == 0) return a;
  return a + std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) * ab;
}

// Ericson, Real-Time Collision Detection 5.1.5, with a fallback to the edges for a flat triangle.
inline Vec3d closestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
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

inline std::array<Vec3d, 8> corners(const Obbd& b) {
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

inline HullShape<double> makeHull(const Obbd& box, Rng& rng) {
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
inline double distanceTo(const Sphered& s, const Vec3d& p) {
  return std::max(0.0, (p - s.center).norm() - s.radius);
}
inline double distanceTo(const Aabbd& b, const Vec3d& p) { return (clampToAabb(p, b) - p).norm(); }
inline double distanceTo(const Obbd& b, const Vec3d& p) { return (closestOnObb(p, b) - p).norm(); }
inline double distanceTo(const Triangled& t, const Vec3d& p) {
  return (closestOnTriangle(p, t.a, t.b, t.c) - p).norm();
}
inline double distanceTo(const Segmentd& s, const Vec3d& p) {
  return (closestOnSegment(p, s.start, s.end) - p).norm();
}
inline double distanceTo(const HullShape<double>& h, const Vec3d& p) {
  return distanceTo(h.source, p);
}

inline double maxDot(const Sphered& s, const Vec3d& n) {
  return s.center.dot(n) + s.radius * n.norm();
}
inline double maxDot(const Aabbd& b, const Vec3d& n) {
  double m = 0;
  for (int k = 0; k < 3; ++k) m += std::max(b.min[k] * n[k], b.max[k] * n[k]);
  return m;
}
inline double maxDot(const Obbd& b, const Vec3d& n) {
  double m = -INFINITY;
  for (const Vec3d& c : corners(b)) m = std::max(m, c.dot(n));
  return m;
}
inline double maxDot(const Triangled& t, const Vec3d& n) {
  return std::max({t.a.dot(n), t.b.dot(n), t.c.dot(n)});
}
inline double maxDot(const Segmentd& s, const Vec3d& n) {
  return std::max(s.start.dot(n), s.end.dot(n));
}
inline double maxDot(const HullShape<double>& h, const Vec3d& n) {
  double m = -INFINITY;
  for (const Vec3d& p : h.points) m = std::max(m, p.dot(n));
  return m;
}
template <class S>
double minDot(const S& s, const Vec3d& n) {
  return -maxDot(s, Vec3d(-n));
}

// The size of a shape: the span of its coordinates from the origin.
inline double extent(const Sphered& s) { return s.center.cwiseAbs().maxCoeff() + s.radius; }
inline double extent(const Aabbd& b) {
  return std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
}
inline double extent(const Obbd& b) { return b.center.cwiseAbs().maxCoeff() + b.halfExtents.sum(); }
inline double extent(const Triangled& t) {
  return std::max(
      {t.a.cwiseAbs().maxCoeff(), t.b.cwiseAbs().maxCoeff(), t.c.cwiseAbs().maxCoeff()});
}
inline double extent(const Segmentd& s) {
  return std::max(s.start.cwiseAbs().maxCoeff(), s.end.cwiseAbs().maxCoeff());
}
inline double extent(const HullShape<double>& h) { return extent(h.source); }

[[maybe_unused]] Sphered translated(const Sphered& s, const Vec3d& t) {
  return {s.center + t, s.radius};
}
inline Aabbd translated(const Aabbd& b, const Vec3d& t) { return {b.min + t, b.max + t}; }
inline Obbd translated(const Obbd& b, const Vec3d& t) {
  return {b.center + t, b.halfExtents, b.axes};
}
inline Triangled translated(const Triangled& s, const Vec3d& t) {
  return {s.a + t, s.b + t, s.c + t};
}
inline Segmentd translated(const Segmentd& s, const Vec3d& t) { return {s.start + t, s.end + t}; }
inline HullShape<double> translated(const HullShape<double>& h, const Vec3d& t) {
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
inline Sat satOracle(const Obbd& a, const Obbd& b) {
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

// Largest absolute component difference, in double.
template <class DA, class DB>
double maxDiff(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  return (a.template cast<double>() - b.template cast<double>()).cwiseAbs().maxCoeff();
}

}  // namespace simdphys::test

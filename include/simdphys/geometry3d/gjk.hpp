// GJK and EPA (the book's appendix): distance, closest points, intersection and penetration of
// convex shapes given only by their support functions.
//
// A convex shape is anything with `support(shape, direction)`, its farthest point along a
// direction: the primitives of primitives.hpp, a ConvexHullT (a view of points), a Minkowski sum
// or difference of two shapes, or a user type found by argument-dependent lookup (which also
// names its scalar as a member `using Scalar = float;` or by specialising ShapeScalar).
//
// gjkDistance is Gilbert-Johnson-Keerthi with the signed-volume sub-algorithm of Montanari,
// Petrinic and Barbieri (2017): the closest point of each simplex to the origin is found from
// signed lengths, areas and volumes, sub-simplices are searched only across the faces whose sign
// says the origin lies beyond them, and degenerate simplices (repeated, collinear, coplanar
// points) are reduced to their faces instead of divided by a vanishing determinant, so no NaN is
// produced. epa is the Expanding Polytope Algorithm started from GJK's final simplex.
//
// Robustness measures, beyond the book:
// - Local coordinates. Both shapes are moved by the same offset (a point of A) before any
//   arithmetic, each from its own data (a box's center - offset, then + half extents), so shapes
//   at 1e5 with sizes of 1e-2 keep float's relative precision in their distance; only the
//   returned points carry the rounding of their absolute position.
// - Cores and radii. A sphere is its centre grown by its radius (a Minkowski sum adds its
//   parts' radii): GJK and EPA run on the cores, which are polytopes for every shape here, and
//   the radii are added at the end. Sphere-sphere is then exact, and EPA never has to
//   approximate a curved surface by facets.
// - GJK stops on the first of: the distance bounds |v| and v.w/|v| agree to kGjkTolerance times
//   the size of the problem; |v| is below kTouchTolerance times that size (touching or
//   overlapping); the simplex encloses the origin; a step fails to shorten v (rounding has taken
//   over: the previous, better simplex is kept); kGjkMaxIterations support calls.
// - EPA grows its polytope only across the horizon of the faces the new point sees, checks every
//   new face for a vanishing area and an inward normal before it commits, and otherwise stops
//   with the best face so far; it stops at kEpaTolerance or after kEpaMaxIterations expansions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/math.hpp"

namespace simdphys {

// The convex hull of a set of points, as a view: the points are not copied and must outlive it.
// The points need not be the hull's vertices (interior and repeated points are fine); an empty
// set is not a shape and `support` throws Error on it.
template <class T>
struct ConvexHullT {
  using Scalar = T;
  std::span<const Vec3<T>> points;
};

// The Minkowski sum {a + b}: e.g. a capsule is the sum of a segment and a sphere at the origin.
template <class A, class B>
struct MinkowskiSumT {
  A a;
  B b;
};
// The Minkowski difference {a - b}: it contains the origin exactly when a and b intersect.
template <class A, class B>
struct MinkowskiDifferenceT {
  A a;
  B b;
};

using ConvexHull = ConvexHullT<float>;
using ConvexHulld = ConvexHullT<double>;

// The scalar type of a shape: T for the primitives, the member `Scalar` otherwise.
template <class S>
struct ShapeScalar {
  using type = typename S::Scalar;
};
template <class T>
struct ShapeScalar<SphereT<T>> {
  using type = T;
};
template <class T>
struct ShapeScalar<AabbT<T>> {
  using type = T;
};
template <class T>
struct ShapeScalar<ObbT<T>> {
  using type = T;
};
template <class T>
struct ShapeScalar<TriangleT<T>> {
  using type = T;
};
template <class T>
struct ShapeScalar<SegmentT<T>> {
  using type = T;
};
template <class A, class B>
struct ShapeScalar<MinkowskiSumT<A, B>> {
  using type = typename ShapeScalar<A>::type;
};
template <class A, class B>
struct ShapeScalar<MinkowskiDifferenceT<A, B>> {
  using type = typename ShapeScalar<A>::type;
};
template <class S>
using ShapeScalarT = typename ShapeScalar<std::remove_cvref_t<S>>::type;

// GJK's answer. Touching shapes count as intersecting (closed shapes, like `overlaps`).
template <class T>
struct GjkResultT {
  bool intersecting = false;
  T distance = 0;  // 0 when intersecting
  // The closest points of A and of B, distance apart. When intersecting both are the same point,
  // one that lies in both shapes (where they touch, for touching shapes).
  Vec3<T> pointA = Vec3<T>::Zero(), pointB = Vec3<T>::Zero();
  int iterations = 0;  // support calls, at most kGjkMaxIterations
};

// EPA's answer for intersecting shapes: moving B by depth * normal makes them touch, and no
// shorter translation separates them (the penetration depth, measured in the Minkowski
// difference). pointA is the point of A deepest inside B along the normal, pointB the point of
// B deepest inside A: pointA - pointB = depth * normal.
template <class T>
struct PenetrationT {
  Vec3<T> normal = Vec3<T>::UnitX();  // unit, from A towards B
  T depth = 0;                        // >= 0; 0 for touching shapes
  Vec3<T> pointA = Vec3<T>::Zero(), pointB = Vec3<T>::Zero();
  int iterations = 0;  // polytope expansions, at most kEpaMaxIterations (0: closed form)
};

using GjkResult = GjkResultT<float>;
using GjkResultd = GjkResultT<double>;
using Penetration = PenetrationT<float>;
using Penetrationd = PenetrationT<double>;

// Caps on the work of one query. Every shape of this header is a polytope for GJK and EPA (see
// the cores above), on which both end exactly after walking over a few features: the tests'
// random pairs of spheres, boxes, triangles, segments and hulls take at most 10 GJK iterations
// and 19 EPA expansions, far below the caps. A user's curved shape converges only linearly and
// may reach the cap, which returns the best answer so far.
inline constexpr int kGjkMaxIterations = 64;
inline constexpr int kEpaMaxIterations = 128;
// Tolerances, relative to the size of the problem (the largest |a - b| among the support points
// seen, plus the radii): a few rounding errors of the support and dot products that decide.
template <class T>
inline constexpr T kGjkTolerance = T(16) * std::numeric_limits<T>::epsilon();
template <class T>
inline constexpr T kTouchTolerance = T(16) * std::numeric_limits<T>::epsilon();
template <class T>
inline constexpr T kEpaTolerance = T(64) * std::numeric_limits<T>::epsilon();
// A triangle whose sine of angle, or a tetrahedron whose volume over the product of its edges,
// is below this is treated as flat by GJK's sub-algorithm.
template <class T>
inline constexpr T kGjkFlatTolerance = T(16) * std::numeric_limits<T>::epsilon();

// ---------------------------------------------------------------------------------------------
// Support functions: the point of the shape farthest along `direction`. The direction need not
// be unit; for a zero direction (where every point is farthest) the answer is a point of the
// shape: a sphere's centre, a box's corner selected by the sign bits (+ for 0), a triangle's or
// segment's or hull's first vertex. Ties go to the first vertex.

namespace detail {
// direction / |direction|, computed after dividing by the largest |component| so tiny and huge
// directions neither underflow nor overflow; zero (or NaN) gives zero.
template <class T>
Vec3<T> unitOrZero(const Vec3<T>& d) {
  const T m = d.cwiseAbs().maxCoeff();
  if (!(m > 0) || !std::isfinite(m)) return Vec3<T>::Zero();
  const Vec3<T> s = d / m;
  return s / s.norm();
}
}  // namespace detail

template <class T>
Vec3<T> support(const SphereT<T>& s, const detail::NoDeduce<Vec3<T>>& direction) {
  return s.center + s.radius * detail::unitOrZero<T>(direction);
}

template <class T>
Vec3<T> support(const AabbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction) {
  return Vec3<T>(direction[0] >= 0 ? b.max[0] : b.min[0], direction[1] >= 0 ? b.max[1] : b.min[1],
                 direction[2] >= 0 ? b.max[2] : b.min[2]);
}

template <class T>
Vec3<T> support(const ObbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction) {
  Vec3<T> p = b.center;
  for (int i = 0; i < 3; ++i) {
    const T h = b.axes.col(i).dot(direction) >= 0 ? b.halfExtents[i] : -b.halfExtents[i];
    p += h * b.axes.col(i);
  }
  return p;
}

template <class T>
Vec3<T> support(const TriangleT<T>& t, const detail::NoDeduce<Vec3<T>>& direction) {
  const T da = t.a.dot(direction), db = t.b.dot(direction), dc = t.c.dot(direction);
  if (da >= db && da >= dc) return t.a;
  return db >= dc ? t.b : t.c;
}

template <class T>
Vec3<T> support(const SegmentT<T>& s, const detail::NoDeduce<Vec3<T>>& direction) {
  return s.start.dot(direction) >= s.end.dot(direction) ? s.start : s.end;
}

template <class T>
Vec3<T> support(const ConvexHullT<T>& h, const detail::NoDeduce<Vec3<T>>& direction) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  std::size_t best = 0;
  T bestDot = h.points[0].dot(direction);
  for (std::size_t i = 1; i < h.points.size(); ++i) {
    const T d = h.points[i].dot(direction);
    if (d > bestDot) bestDot = d, best = i;
  }
  return h.points[best];
}

template <class A, class B>
Vec3<ShapeScalarT<A>> support(const MinkowskiSumT<A, B>& m,
                              const detail::NoDeduce<Vec3<ShapeScalarT<A>>>& direction) {
  return support(m.a, direction) + support(m.b, direction);
}

template <class A, class B>
Vec3<ShapeScalarT<A>> support(const MinkowskiDifferenceT<A, B>& m,
                              const detail::NoDeduce<Vec3<ShapeScalarT<A>>>& direction) {
  return support(m.a, direction) - support(m.b, Vec3<ShapeScalarT<A>>(-direction));
}

// ---------------------------------------------------------------------------------------------
// What GJK and EPA see of a shape: its core, given by coreSupport(shape, d, origin) = (the core's
// support along d) - origin, computed from the shape's own data so the subtraction of the large
// origin comes first; its radius (the core grown by it is the shape); and a reference point
// inside it. A shape without overloads here is its own core with radius 0.
namespace detail {

template <class S, class T>
Vec3<T> coreSupport(const S& s, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(s, d) - origin;
}
template <class S>
ShapeScalarT<S> coreRadius(const S&) {
  return 0;
}
template <class S>
Vec3<ShapeScalarT<S>> referencePoint(const S& s) {
  return support(s, Vec3<ShapeScalarT<S>>::UnitX());
}

template <class T>
Vec3<T> coreSupport(const SphereT<T>& s, const Vec3<T>&, const Vec3<T>& origin) {
  return s.center - origin;
}
template <class T>
T coreRadius(const SphereT<T>& s) {
  return s.radius;
}
template <class T>
Vec3<T> referencePoint(const SphereT<T>& s) {
  return s.center;
}

template <class T>
Vec3<T> coreSupport(const AabbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(b, d) - origin;  // every coordinate is data: one rounding
}
template <class T>
Vec3<T> referencePoint(const AabbT<T>& b) {
  return b.center();
}

template <class T>
Vec3<T> coreSupport(const ObbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin) {
  Vec3<T> p = b.center - origin;
  for (int i = 0; i < 3; ++i) {
    const T h = b.axes.col(i).dot(d) >= 0 ? b.halfExtents[i] : -b.halfExtents[i];
    p += h * b.axes.col(i);
  }
  return p;
}
template <class T>
Vec3<T> referencePoint(const ObbT<T>& b) {
  return b.center;
}

// For vertex sets the dot products are taken in local coordinates too: at 1e5 a float dot product
// could not tell apart vertices 1e-2 apart.
template <class T>
Vec3<T> coreSupport(const TriangleT<T>& t, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(TriangleT<T>{t.a - origin, t.b - origin, t.c - origin}, d);
}
template <class T>
Vec3<T> referencePoint(const TriangleT<T>& t) {
  return t.a;
}

template <class T>
Vec3<T> coreSupport(const SegmentT<T>& s, const Vec3<T>& d, const Vec3<T>& origin) {
  return support(SegmentT<T>{s.start - origin, s.end - origin}, d);
}
template <class T>
Vec3<T> referencePoint(const SegmentT<T>& s) {
  return s.start;
}

template <class T>
Vec3<T> coreSupport(const ConvexHullT<T>& h, const Vec3<T>& d, const Vec3<T>& origin) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  Vec3<T> best = h.points[0] - origin;
  T bestDot = best.dot(d);
  for (std::size_t i = 1; i < h.points.size(); ++i) {
    const Vec3<T> p = h.points[i] - origin;
    const T dot = p.dot(d);
    if (dot > bestDot) bestDot = dot, best = p;
  }
  return best;
}
template <class T>
Vec3<T> referencePoint(const ConvexHullT<T>& h) {
  if (h.points.empty()) throw Error("support: the convex hull has no points");
  return h.points[0];
}

// A sum's core is the sum of the cores, its radius the sum of the radii; the origin is taken off
// once, from the first part. (Declared first so sums and differences nest either way.)
template <class A, class B, class T>
Vec3<T> coreSupport(const MinkowskiSumT<A, B>& m, const Vec3<T>& d, const Vec3<T>& origin);
template <class A, class B, class T>
Vec3<T> coreSupport(const MinkowskiDifferenceT<A, B>& m, const Vec3<T>& d, const Vec3<T>& origin);
template <class A, class B>
ShapeScalarT<A> coreRadius(const MinkowskiSumT<A, B>& m);
template <class A, class B>
ShapeScalarT<A> coreRadius(const MinkowskiDifferenceT<A, B>& m);
template <class A, class B>
Vec3<ShapeScalarT<A>> referencePoint(const MinkowskiSumT<A, B>& m);
template <class A, class B>
Vec3<ShapeScalarT<A>> referencePoint(const MinkowskiDifferenceT<A, B>& m);

template <class A, class B, class T>
Vec3<T> coreSupport(const MinkowskiSumT<A, B>& m, const Vec3<T>& d, const Vec3<T>& origin) {
  return coreSupport(m.a, d, origin) + coreSupport(m.b, d, Vec3<T>::Zero().eval());
}
template <class A, class B>
ShapeScalarT<A> coreRadius(const MinkowskiSumT<A, B>& m) {
  return coreRadius(m.a) + coreRadius(m.b);
}
template <class A, class B>
Vec3<ShapeScalarT<A>> referencePoint(const MinkowskiSumT<A, B>& m) {
  return referencePoint(m.a) + referencePoint(m.b);
}

template <class A, class B, class T>
Vec3<T> coreSupport(const MinkowskiDifferenceT<A, B>& m, const Vec3<T>& d, const Vec3<T>& origin) {
  return coreSupport(m.a, d, origin) - coreSupport(m.b, Vec3<T>(-d), Vec3<T>::Zero().eval());
}
template <class A, class B>
ShapeScalarT<A> coreRadius(const MinkowskiDifferenceT<A, B>& m) {
  return coreRadius(m.a) + coreRadius(m.b);
}
template <class A, class B>
Vec3<ShapeScalarT<A>> referencePoint(const MinkowskiDifferenceT<A, B>& m) {
  return referencePoint(m.a) - referencePoint(m.b);
}

// A point of the Minkowski difference of the cores, w = a - b, with the points of A and B it
// came from (all in local coordinates).
template <class T>
struct SupportPoint {
  Vec3<T> w, a, b;
};

template <class T, class SA, class SB>
SupportPoint<T> supportPoint(const SA& A, const SB& B, const Vec3<T>& d, const Vec3<T>& origin) {
  SupportPoint<T> p;
  p.a = coreSupport(A, d, origin);
  p.b = coreSupport(B, Vec3<T>(-d), origin);
  p.w = p.a - p.b;
  return p;
}

// GJK's simplex: up to 4 support points and the barycentric weights of v, its point closest to
// the origin.
template <class T>
struct Simplex {
  std::array<SupportPoint<T>, 4> p;
  std::array<T, 4> lambda{};
  int size = 0;
};

// The closest point to the origin of a sub-simplex, as a set of vertex indices and weights.
template <class T>
struct SubSimplex {
  std::array<int, 4> index{};
  std::array<T, 4> lambda{};
  int size = 0;
  Vec3<T> v = Vec3<T>::Zero();
  T vv = std::numeric_limits<T>::infinity();
};

template <class T>
bool sameSign(T a, T b) {
  return (a > 0 && b > 0) || (a < 0 && b < 0);
}

template <class T>
SubSimplex<T> vertexOnly(const std::array<Vec3<T>, 4>& p, int i) {
  SubSimplex<T> r;
  r.size = 1, r.index[0] = i, r.lambda[0] = 1, r.v = p[i], r.vv = p[i].squaredNorm();
  return r;
}

template <class T>
void keepCloser(SubSimplex<T>& best, const SubSimplex<T>& candidate) {
  if (candidate.vv < best.vv) best = candidate;
}

// Segment p[i] p[j]: the origin's projection on the line, kept if it falls strictly inside.
template <class T>
SubSimplex<T> closestOnSegment(const std::array<Vec3<T>, 4>& p, int i, int j) {
  const Vec3<T> t = p[j] - p[i];
  const T tt = t.squaredNorm();
  if (!(tt > 0)) return vertexOnly(p, j);  // a repeated point
  const T u = -p[i].dot(t) / tt;
  if (u <= 0) return vertexOnly(p, i);
  if (u >= 1) return vertexOnly(p, j);
  SubSimplex<T> r;
  r.size = 2, r.index = {i, j, 0, 0}, r.lambda = {1 - u, u, 0, 0};
  r.v = p[i] + u * t;
  r.vv = r.v.squaredNorm();
  return r;
}

// Triangle p[i] p[j] p[k] (Montanari et al., S2D): project the origin on the plane, then compare
// the signed areas of the three sub-triangles it makes with the whole one, in the coordinate
// plane where the triangle's projection is largest. An edge is searched only when the origin is
// beyond it (its sign differs). A flat (collinear or repeated) triangle is its edges.
template <class T>
SubSimplex<T> closestOnTriangle(const std::array<Vec3<T>, 4>& p, int i, int j, int k) {
  const Vec3<T> e1 = p[j] - p[i], e2 = p[k] - p[i];
  const Vec3<T> n = e1.cross(e2);
  const T nn = n.squaredNorm();
  const T flat = kGjkFlatTolerance<T> * kGjkFlatTolerance<T> * e1.squaredNorm() * e2.squaredNorm();
  std::array<T, 3> c{};
  const std::array<int, 3> idx{i, j, k};
  T mu = 0;
  if (nn > flat && nn > 0) {
    const Vec3<T> q = n * (n.dot(p[i]) / nn);  // the origin projected on the plane
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const int x = (axis + 1) % 3, y = (axis + 2) % 3;
    // Twice the signed area of (a, b, c) in the (x, y) plane; for the triangle itself it is
    // n[axis].
    auto area = [x, y](const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& cc) {
      return (b[x] - a[x]) * (cc[y] - a[y]) - (b[y] - a[y]) * (cc[x] - a[x]);
    };
    mu = n[axis];
    c = {area(q, p[j], p[k]), area(p[i], q, p[k]), area(p[i], p[j], q)};
    if (sameSign(mu, c[0]) && sameSign(mu, c[1]) && sameSign(mu, c[2])) {
      const T sum = c[0] + c[1] + c[2];
      SubSimplex<T> r;
      r.size = 3, r.index = {i, j, k, 0};
      r.lambda = {c[0] / sum, c[1] / sum, c[2] / sum, 0};
      // v is the projection itself: along the plane's normal to rounding, however close the
      // plane passes to the origin (a weighted sum of the vertices would carry their rounding,
      // eps |p|, across it and tilt the direction of a short v).
      r.v = q;
      r.vv = r.v.squaredNorm();
      return r;
    }
  }
  SubSimplex<T> best;
  for (int m = 0; m < 3; ++m) {
    if (mu != 0 && sameSign(mu, c[m])) continue;  // the origin is inside this edge's half-plane
    SubSimplex<T> e = closestOnSegment(p, idx[(m + 1) % 3], idx[(m + 2) % 3]);
    keepCloser(best, e);
  }
  return best;
}

// Tetrahedron p[0..3] (S3D): the signed volumes of the four tetrahedra made with the origin
// against the whole; all of the same sign means the origin is inside. A flat tetrahedron is its
// faces.
template <class T>
SubSimplex<T> closestOnTetrahedron(const std::array<Vec3<T>, 4>& p) {
  const Vec3<T> e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  const T mu = e1.dot(e2.cross(e3));
  const T scale = e1.norm() * e2.norm() * e3.norm();
  std::array<T, 4> c{};
  const bool solid = std::abs(mu) > kGjkFlatTolerance<T> * scale && mu != 0;
  if (solid) {
    // Each volume is a dot product with edge vectors of a vertex, not a determinant of the
    // vertices, so it stays accurate when the simplex is far from the origin.
    c[0] = p[1].dot((p[2] - p[1]).cross(p[3] - p[1]));
    c[1] = -p[0].dot(e2.cross(e3));
    c[2] = -p[0].dot(e3.cross(e1));
    c[3] = -p[0].dot(e1.cross(e2));
    if (sameSign(mu, c[0]) && sameSign(mu, c[1]) && sameSign(mu, c[2]) && sameSign(mu, c[3])) {
      const T sum = c[0] + c[1] + c[2] + c[3];
      SubSimplex<T> r;
      r.size = 4, r.index = {0, 1, 2, 3};
      for (int m = 0; m < 4; ++m) r.lambda[m] = c[m] / sum;
      r.v = Vec3<T>::Zero();
      r.vv = 0;
      return r;
    }
  }
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  SubSimplex<T> best;
  for (int m = 0; m < 4; ++m) {
    if (solid && sameSign(mu, c[m])) continue;  // the origin is on the inner side of this face
    keepCloser(best, closestOnTriangle(p, kFace[m][0], kFace[m][1], kFace[m][2]));
  }
  return best;
}

// Replaces the simplex by the smallest sub-simplex holding its point closest to the origin.
template <class T>
SubSimplex<T> reduce(Simplex<T>& s) {
  std::array<Vec3<T>, 4> w;
  for (int m = 0; m < s.size; ++m) w[m] = s.p[m].w;
  SubSimplex<T> r;
  switch (s.size) {
    case 1:
      r = vertexOnly(w, 0);
      break;
    case 2:
      r = closestOnSegment(w, 0, 1);
      break;
    case 3:
      r = closestOnTriangle(w, 0, 1, 2);
      break;
    default:
      r = closestOnTetrahedron(w);
      break;
  }
  Simplex<T> out;
  out.size = r.size;
  for (int m = 0; m < r.size; ++m) out.p[m] = s.p[r.index[m]], out.lambda[m] = r.lambda[m];
  s = out;
  return r;
}

template <class T>
struct GjkRun {
  Simplex<T> simplex;
  Vec3<T> v = Vec3<T>::Zero();  // the closest point of the cores' difference to the origin
  T vv = 0;
  bool overlap = false;  // the cores overlap or touch: v is (taken as) zero
  int iterations = 0;
  T scale = 0;  // the largest |w| seen: the size of the problem
  Vec3<T> pointA() const {
    Vec3<T> r = Vec3<T>::Zero();
    for (int m = 0; m < simplex.size; ++m) r += simplex.lambda[m] * simplex.p[m].a;
    return r;
  }
  Vec3<T> pointB() const {
    Vec3<T> r = Vec3<T>::Zero();
    for (int m = 0; m < simplex.size; ++m) r += simplex.lambda[m] * simplex.p[m].b;
    return r;
  }
};

// GJK on the cores of A and B, in coordinates relative to `origin`; `towardB` (local) is the
// first search direction.
template <class T, class SA, class SB>
GjkRun<T> runGjk(const SA& A, const SB& B, const Vec3<T>& origin, Vec3<T> towardB) {
  GjkRun<T> run;
  if (!(towardB.squaredNorm() > 0)) towardB = Vec3<T>::UnitX();
  run.simplex.size = 1;
  run.simplex.p[0] = supportPoint(A, B, towardB, origin);
  run.simplex.lambda[0] = 1;
  run.v = run.simplex.p[0].w;
  run.vv = run.v.squaredNorm();
  run.scale = run.v.norm();
  run.iterations = 1;
  for (;;) {
    const T touch = kTouchTolerance<T> * run.scale;
    if (run.vv <= touch * touch) {
      run.overlap = true;
      break;
    }
    if (run.iterations >= kGjkMaxIterations) break;
    const SupportPoint<T> w = supportPoint(A, B, Vec3<T>(-run.v), origin);
    ++run.iterations;
    run.scale = std::max(run.scale, w.w.norm());
    // |v| is an upper bound of the distance, v.w / |v| a lower one: stop when they agree.
    const T gap = run.vv - run.v.dot(w.w);
    if (gap <= kGjkTolerance<T> * std::sqrt(run.vv) * run.scale) break;
    Simplex<T> grown = run.simplex;
    grown.p[grown.size++] = w;
    const SubSimplex<T> r = reduce(grown);
    if (r.size == 4) {  // the origin is inside the tetrahedron
      run.simplex = grown;
      run.v = Vec3<T>::Zero();
      run.vv = 0;
      run.overlap = true;
      break;
    }
    if (!(r.vv < run.vv)) break;  // no progress: rounding has taken over, keep the old simplex
    run.simplex = grown;
    run.v = r.v;
    run.vv = r.vv;
  }
  return run;
}

template <class A, class B>
constexpr void requireSameScalar() {
  static_assert(std::is_same_v<ShapeScalarT<A>, ShapeScalarT<B>>,
                "GJK and EPA need both shapes in the same scalar type");
  static_assert(std::is_floating_point_v<ShapeScalarT<A>>, "float or double expected");
}

// ---- EPA ------------------------------------------------------------------------------------

template <class T>
struct EpaFace {
  std::array<int, 3> v{};     // vertex indices, counter-clockwise seen from outside
  std::array<int, 3> adj{};   // the face across edge m = (v[m], v[m+1])
  std::array<int, 3> edge{};  // which edge of that face it is
  Vec3<T> normal = Vec3<T>::Zero();
  T dist = 0;  // signed distance of the plane from the origin
  bool alive = true;
};

template <class T>
struct EpaCoreResult {
  Vec3<T> normal = Vec3<T>::UnitX();
  T depth = 0;
  Vec3<T> pointA = Vec3<T>::Zero(), pointB = Vec3<T>::Zero();
  int iterations = 0;
};

// A unit vector perpendicular to e (non-zero).
template <class T>
Vec3<T> perpendicular(const Vec3<T>& e) {
  int axis = 0;
  e.cwiseAbs().minCoeff(&axis);
  return unitOrZero<T>(e.cross(Vec3<T>::Unit(axis)));
}

template <class T>
class Polytope {
 public:
  std::vector<SupportPoint<T>> vertices;
  std::vector<EpaFace<T>> faces;
  Vec3<T> inside = Vec3<T>::Zero();  // the first tetrahedron's centroid, inside for good

  // The face (a, b, c) with its outward normal; false if its area vanishes or the normal points
  // towards the inside point.
  bool makeFace(int a, int b, int c, T tol, EpaFace<T>& f) const {
    const Vec3<T>& wa = vertices[a].w;
    const Vec3<T> n = (vertices[b].w - wa).cross(vertices[c].w - wa);
    const T length = n.norm();
    const T edges = (vertices[b].w - wa).norm() * (vertices[c].w - wa).norm();
    if (!(length > kGjkFlatTolerance<T> * edges) || !(length > 0)) return false;
    f = EpaFace<T>{};
    f.v = {a, b, c};
    f.normal = n / length;
    f.dist = f.normal.dot(wa);
    return f.normal.dot(wa - inside) > -tol;
  }
};

// EPA on the cores. `run` is GJK's final state with the cores overlapping or touching; `towardB`
// orients the normal when the cores' difference is flat (no interior: depth 0 either way).
template <class T, class SA, class SB>
EpaCoreResult<T> epaCore(const SA& A, const SB& B, const Vec3<T>& origin, const GjkRun<T>& run,
                         const Vec3<T>& towardB) {
  EpaCoreResult<T> result;
  T scale = run.scale;
  for (int m = 0; m < run.simplex.size; ++m) scale = std::max(scale, run.simplex.p[m].w.norm());
  auto grow = [&](const Vec3<T>& d) {
    SupportPoint<T> p = supportPoint(A, B, d, origin);
    scale = std::max(scale, p.w.norm());
    return p;
  };
  auto tolerance = [&] { return kEpaTolerance<T> * scale; };
  // A flat difference: its interior is empty, so the depth is 0 along `normal`, at GJK's point.
  auto flat = [&](Vec3<T> normal) {
    if (normal.dot(towardB) < 0) normal = -normal;
    result.normal = normal;
    result.depth = 0;
    result.pointA = run.pointA();
    result.pointB = run.pointB();
    return result;
  };
  // Blow GJK's simplex up to a tetrahedron: each new vertex is the simplex's own or a support
  // point, whichever lies farthest from the span of the ones before.
  std::array<SupportPoint<T>, 4> p;
  p[0] = run.simplex.p[0];
  std::vector<SupportPoint<T>> candidates(run.simplex.p.begin() + 1,
                                          run.simplex.p.begin() + run.simplex.size);
  auto pick = [&](auto&& distance, const std::vector<Vec3<T>>& directions, SupportPoint<T>& out) {
    T best = -1;
    for (const SupportPoint<T>& c : candidates)
      if (const T d = distance(c.w); d > best) best = d, out = c;
    if (best > tolerance()) return true;
    for (const Vec3<T>& dir : directions) {
      const SupportPoint<T> c = grow(dir);
      if (const T d = distance(c.w); d > best) best = d, out = c;
    }
    return best > tolerance();
  };
  const std::vector<Vec3<T>> axes = {Vec3<T>::UnitX(),  -Vec3<T>::UnitX(), Vec3<T>::UnitY(),
                                     -Vec3<T>::UnitY(), Vec3<T>::UnitZ(),  -Vec3<T>::UnitZ()};
  if (!pick([&](const Vec3<T>& w) { return (w - p[0].w).norm(); }, axes, p[1]))
    return flat(towardB.squaredNorm() > 0 ? unitOrZero<T>(towardB) : Vec3<T>::UnitX());
  const Vec3<T> e = unitOrZero<T>(Vec3<T>(p[1].w - p[0].w));
  const Vec3<T> u1 = perpendicular(e), u2 = e.cross(u1);
  const std::vector<Vec3<T>> around = {u1, -u1, u2, -u2, u1 + u2, u1 - u2, -u1 + u2, -u1 - u2};
  if (!pick([&](const Vec3<T>& w) { return (w - p[0].w).cross(e).norm(); }, around, p[2])) {
    const Vec3<T> side = towardB - e * e.dot(towardB);
    return flat(side.squaredNorm() > 0 ? unitOrZero<T>(side) : u1);
  }
  const Vec3<T> n = unitOrZero<T>(Vec3<T>((p[1].w - p[0].w).cross(p[2].w - p[0].w)));
  if (!pick([&](const Vec3<T>& w) { return std::abs(n.dot(w - p[0].w)); }, {n, -n}, p[3]))
    return flat(n);
  if ((p[1].w - p[0].w).dot((p[2].w - p[0].w).cross(p[3].w - p[0].w)) < 0) std::swap(p[1], p[2]);

  Polytope<T> poly;
  poly.vertices.assign(p.begin(), p.end());
  poly.inside = (p[0].w + p[1].w + p[2].w + p[3].w) / T(4);
  static constexpr int kTetra[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : kTetra) {
    EpaFace<T> f;
    if (!poly.makeFace(t[0], t[1], t[2], tolerance(), f)) return flat(n);  // a sliver
    poly.faces.push_back(f);
  }
  for (int f = 0; f < 4; ++f)  // adjacency: the face holding the reversed edge
    for (int m = 0; m < 3; ++m)
      for (int g = 0; g < 4; ++g)
        for (int k = 0; k < 3; ++k)
          if (poly.faces[g].v[k] == poly.faces[f].v[(m + 1) % 3] &&
              poly.faces[g].v[(k + 1) % 3] == poly.faces[f].v[m])
            poly.faces[f].adj[m] = g, poly.faces[f].edge[m] = k;

  std::vector<std::pair<int, int>> horizon;  // (kept face, its edge) around the visible region
  std::vector<int> removed;
  std::vector<EpaFace<T>> fresh;
  int closest = 0;
  for (int iteration = 0;; ++iteration) {
    closest = -1;
    for (int f = 0; f < int(poly.faces.size()); ++f)
      if (poly.faces[f].alive && (closest < 0 || poly.faces[f].dist < poly.faces[closest].dist))
        closest = f;
    result.iterations = iteration;
    if (iteration >= kEpaMaxIterations) break;
    const EpaFace<T> face = poly.faces[closest];
    const SupportPoint<T> q = grow(face.normal);
    if (face.normal.dot(q.w) - face.dist <= tolerance()) break;  // the face is on the boundary

    // The faces that see q (or nearly: a face q lies on is replaced too, so no new face is a
    // sliver along its edge), found by walking from the closest face; their outline is the
    // horizon.
    const T tol = tolerance();
    horizon.clear(), removed.clear();
    auto sees = [&](int f) {
      const EpaFace<T>& g = poly.faces[f];
      return g.normal.dot(q.w - poly.vertices[g.v[0]].w) > -tol;
    };
    auto walk = [&](auto&& self, int f, int arrivedBy) -> void {
      if (!poly.faces[f].alive) return;
      if (!sees(f)) {
        horizon.emplace_back(f, arrivedBy);
        return;
      }
      poly.faces[f].alive = false;
      removed.push_back(f);
      for (int m = 1; m < 3; ++m) {
        const int k = (arrivedBy + m) % 3;
        self(self, poly.faces[f].adj[k], poly.faces[f].edge[k]);
      }
    };
    poly.faces[closest].alive = false;
    removed.push_back(closest);
    for (int m = 0; m < 3; ++m) walk(walk, face.adj[m], face.edge[m]);

    // New faces (horizon edge reversed, q), chained so each one's edge 1 meets the next's edge 2;
    // the horizon must be one closed loop and every new face sound, or nothing changes.
    const int qi = int(poly.vertices.size());
    poly.vertices.push_back(q);
    fresh.clear();
    bool sound = horizon.size() >= 3;
    std::vector<int> order;
    if (sound) {
      order.push_back(0);
      std::vector<bool> used(horizon.size(), false);
      used[0] = true;
      auto endOf = [&](std::size_t h) {  // the new face's second vertex: the kept edge's start
        return poly.faces[horizon[h].first].v[horizon[h].second];
      };
      auto startOf = [&](std::size_t h) {
        return poly.faces[horizon[h].first].v[(horizon[h].second + 1) % 3];
      };
      while (sound && order.size() < horizon.size()) {
        const int want = endOf(std::size_t(order.back()));
        int next = -1;
        for (std::size_t h = 0; h < horizon.size(); ++h)
          if (!used[h] && startOf(h) == want) next = int(h);
        if (next < 0)
          sound = false;
        else
          used[std::size_t(next)] = true, order.push_back(next);
      }
      if (sound && endOf(std::size_t(order.back())) != startOf(0)) sound = false;
      for (std::size_t m = 0; sound && m < order.size(); ++m) {
        const auto [g, k] = horizon[std::size_t(order[m])];
        EpaFace<T> f;
        sound = poly.makeFace(poly.faces[g].v[(k + 1) % 3], poly.faces[g].v[k], qi, tol, f);
        fresh.push_back(f);
      }
    }
    if (!sound) {  // keep the polytope as it was and answer with the best face so far
      for (const int f : removed) poly.faces[std::size_t(f)].alive = true;
      poly.vertices.pop_back();
      result.iterations = iteration + 1;
      break;
    }
    const int first = int(poly.faces.size()), count = int(fresh.size());
    for (int m = 0; m < count; ++m) {
      EpaFace<T>& f = fresh[std::size_t(m)];
      const auto [g, k] = horizon[std::size_t(order[std::size_t(m)])];
      f.adj = {g, first + (m + 1) % count, first + (m + count - 1) % count};
      f.edge = {k, 2, 1};
      poly.faces[g].adj[k] = first + m;
      poly.faces[g].edge[k] = 0;
    }
    poly.faces.insert(poly.faces.end(), fresh.begin(), fresh.end());
  }

  // The origin's projection on the closest face, in barycentric weights, gives the witness
  // points. A face of the difference is often split into coplanar triangles of equal distance
  // and the projection lies in only one of them: among the faces tied with the closest (within
  // the tolerance, same normal), take the one whose weights are the least negative, then clamp
  // what rounding leaves.
  auto weights = [&](const EpaFace<T>& g, const Vec3<T>& q) {
    std::array<T, 3> l{};
    for (int m = 0; m < 3; ++m) {
      const Vec3<T>& b = poly.vertices[g.v[(m + 1) % 3]].w;
      const Vec3<T>& c = poly.vertices[g.v[(m + 2) % 3]].w;
      l[m] = g.normal.dot((b - q).cross(c - q));
    }
    const T sum = l[0] + l[1] + l[2];
    if (sum > 0)
      for (T& x : l) x /= sum;
    else
      l = {T(1) / 3, T(1) / 3, T(1) / 3};
    return l;
  };
  const Vec3<T> q = poly.faces[closest].normal * poly.faces[closest].dist;
  std::array<T, 3> l = weights(poly.faces[closest], q);
  const T tol = tolerance();
  for (int g = 0; g < int(poly.faces.size()) && std::min({l[0], l[1], l[2]}) < 0; ++g) {
    const EpaFace<T>& h = poly.faces[g];
    if (!h.alive || g == closest || h.dist > poly.faces[closest].dist + tol ||
        h.normal.dot(poly.faces[closest].normal) < 1 - kEpaTolerance<T>)
      continue;
    const std::array<T, 3> k = weights(h, q);
    if (std::min({k[0], k[1], k[2]}) > std::min({l[0], l[1], l[2]})) l = k, closest = g;
  }
  const EpaFace<T>& f = poly.faces[closest];
  T sum = 0;
  for (T& x : l) sum += (x = std::max(T(0), x));
  for (T& x : l) x /= sum;  // sum > 0: the weights summed to 1 before clamping
  result.normal = f.normal;
  result.depth = std::max(T(0), f.dist);
  result.pointA = result.pointB = Vec3<T>::Zero();
  for (int m = 0; m < 3; ++m) {
    result.pointA += l[m] * poly.vertices[f.v[m]].a;
    result.pointB += l[m] * poly.vertices[f.v[m]].b;
  }
  return result;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Distance and closest points of two convex shapes (see the top of this file). Shapes whose
// distance is below kTouchTolerance times the size of the problem count as intersecting, with
// distance 0 and a common point.
template <class A, class B>
GjkResultT<ShapeScalarT<A>> gjkDistance(const A& a, const B& b) {
  detail::requireSameScalar<A, B>();
  using T = ShapeScalarT<A>;
  const Vec3<T> origin = detail::referencePoint(a);
  const Vec3<T> towardB = detail::referencePoint(b) - origin;
  const detail::GjkRun<T> run = detail::runGjk(a, b, origin, towardB);
  const T ra = detail::coreRadius(a), rb = detail::coreRadius(b);
  const Vec3<T> ca = run.pointA(), cb = run.pointB();
  GjkResultT<T> result;
  result.iterations = run.iterations;
  const T core = run.overlap ? T(0) : std::sqrt(run.vv);
  const T distance = core - ra - rb;
  if (distance <= kTouchTolerance<T> * (run.scale + ra + rb)) {
    result.intersecting = true;
    result.distance = 0;
    // A common point: where the cores meet, or on the segment between the cores' closest
    // points, at a distance t from B's within rb and from A's within ra (the middle of
    // [core - ra, rb] clipped to the segment).
    Vec3<T> p = (ca + cb) / T(2);
    if (!run.overlap) {
      const T lo = std::max(T(0), core - ra), hi = std::min(core, rb);
      p = cb + (ca - cb) * (std::min(std::max((lo + hi) / 2, T(0)), core) / core);
    }
    result.pointA = result.pointB = p + origin;
    return result;
  }
  const Vec3<T> n = run.v / core;  // from B towards A
  result.distance = distance;
  result.pointA = ca - ra * n + origin;
  result.pointB = cb + rb * n + origin;
  return result;
}

// Whether two convex shapes intersect (touching counts): exactly gjkDistance(a, b).intersecting.
template <class A, class B>
bool gjkIntersect(const A& a, const B& b) {
  return gjkDistance(a, b).intersecting;
}

// Penetration of two intersecting convex shapes (std::nullopt exactly when gjkIntersect is
// false). The normal is unit and points from A to B. When the cores are apart and only the radii
// overlap, the answer is closed-form along the line between the cores' closest points. When the
// cores' Minkowski difference has no interior (e.g. two coplanar triangles, a sphere whose centre
// is inside a triangle), the cores' depth is 0 and the normal is that of the flat difference,
// signed towards B; for a difference that is a point (concentric spheres) it is the direction
// between the shapes' reference points, or +x if they coincide.
template <class A, class B>
std::optional<PenetrationT<ShapeScalarT<A>>> epa(const A& a, const B& b) {
  detail::requireSameScalar<A, B>();
  using T = ShapeScalarT<A>;
  const Vec3<T> origin = detail::referencePoint(a);
  const Vec3<T> towardB = detail::referencePoint(b) - origin;
  const detail::GjkRun<T> run = detail::runGjk(a, b, origin, towardB);
  const T ra = detail::coreRadius(a), rb = detail::coreRadius(b);
  const T core = run.overlap ? T(0) : std::sqrt(run.vv);
  if (core - ra - rb > kTouchTolerance<T> * (run.scale + ra + rb)) return std::nullopt;
  PenetrationT<T> result;
  if (!run.overlap) {
    result.normal = -run.v / core;
    result.depth = std::max(T(0), ra + rb - core);
    result.pointA = run.pointA() + ra * result.normal + origin;
    result.pointB = run.pointB() - rb * result.normal + origin;
    return result;
  }
  const detail::EpaCoreResult<T> e = detail::epaCore(a, b, origin, run, towardB);
  result.normal = e.normal;
  result.depth = e.depth + ra + rb;
  result.pointA = e.pointA + ra * e.normal + origin;
  result.pointB = e.pointB - rb * e.normal + origin;
  result.iterations = e.iterations;
  return result;
}

}  // namespace simdphys

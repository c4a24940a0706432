// GJK and EPA (the book's appendix): distance, closest points, intersection and penetration of
// convex shapes given only by their support functions.
//
// The shapes are anything with a support function (support.hpp), within the supported range of
// math.hpp (their points up to kMaxCoordinate in magnitude); they are not validated here.
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
// - Scaled coordinates. The local coordinates are multiplied by a power of two that keeps the
//   support points near 1 (GjkRun::unit, rescaled when a larger one appears), so the areas and
//   volumes of the sub-algorithm and EPA (products of up to four lengths) neither overflow nor
//   underflow for shapes anywhere in the supported range (math.hpp); the scaling is exact.
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
#include <type_traits>

#include "simdphys/geometry3d/support.hpp"

namespace simdphys {

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

using GjkResult = GjkResultT<float>;
using GjkResultd = GjkResultT<double>;

// Caps on the work of one query. Every shape of this header is a polytope for GJK and EPA (see
// the cores above), on which both end exactly after walking over a few features: the tests'
// random pairs of spheres, boxes, triangles, segments and hulls take at most 10 GJK iterations
// and 19 EPA expansions, far below the caps. A user's curved shape converges only linearly and
// may reach the cap, which returns the best answer so far.
inline constexpr int kGjkMaxIterations = 64;
// Tolerances, relative to the size of the problem (the largest |a - b| among the support points
// seen, plus the radii): a few rounding errors of the support and dot products that decide.
template <class T>
inline constexpr T kGjkTolerance = T(16) * std::numeric_limits<T>::epsilon();
template <class T>
inline constexpr T kTouchTolerance = T(16) * std::numeric_limits<T>::epsilon();
// A triangle whose sine of angle, or a tetrahedron whose volume over the product of its edges,
// is below this is treated as flat by GJK's sub-algorithm.
template <class T>
inline constexpr T kGjkFlatTolerance = T(16) * std::numeric_limits<T>::epsilon();

namespace detail {

// A point of the Minkowski difference of the cores, w = a - b, with the points of A and B it
// came from (all in local coordinates).
template <class T>
struct SupportPoint {
  Vec3<T> w, a, b;
};

// `unit` is the power of two the local coordinates are multiplied by (see GjkRun::unit).
template <class T, class SA, class SB>
SupportPoint<T> supportPoint(const SA& A, const SB& B, const Vec3<T>& d, const Vec3<T>& origin,
                             T unit) {
  SupportPoint<T> p;
  p.a = coreSupport(A, d, origin) * unit;
  p.b = coreSupport(B, Vec3<T>(-d), origin) * unit;
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

template <class T>
struct GjkRun {
  Simplex<T> simplex;
  Vec3<T> v = Vec3<T>::Zero();  // the closest point of the cores' difference to the origin
  T vv = 0;
  bool overlap = false;  // the cores overlap or touch: v is (taken as) zero
  int iterations = 0;
  T scale = 0;  // the largest |w| seen: the size of the problem
  // Every point of the run is in local coordinates times `unit`, a power of two that keeps the
  // largest |w| near 1: the sub-algorithm's areas and volumes are products of up to four
  // lengths, which would overflow float from lengths of about 4e9 (and underflow below 1e-9).
  // Scaling by a power of two is exact, so the run is the unscaled one, bit for bit, wherever
  // that one is finite.
  T unit = 1;
  // Multiplies every point by f (a power of two).
  void rescale(T f) {
    for (int m = 0; m < simplex.size; ++m)
      simplex.p[m].w *= f, simplex.p[m].a *= f, simplex.p[m].b *= f;
    v *= f, vv *= f * f, scale *= f, unit *= f;
  }
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

// The cores of two shapes as GJK and EPA query them: supportPoint behind one function pointer, so
// that the algorithms are compiled once per scalar (src/reference/geometry3d/gjk.cpp, epa.cpp),
// not in every translation unit for every pair of shape types.
template <class T>
struct CorePair {
  const void* a;
  const void* b;
  SupportPoint<T> (*point)(const void* a, const void* b, const Vec3<T>& d, const Vec3<T>& origin,
                           T unit);
  SupportPoint<T> operator()(const Vec3<T>& d, const Vec3<T>& origin, T unit) const {
    return point(a, b, d, origin, unit);
  }
};
template <class T, class SA, class SB>
CorePair<T> corePair(const SA& A, const SB& B) {
  return {&A, &B,
          [](const void* a, const void* b, const Vec3<T>& d, const Vec3<T>& origin, T unit) {
            return supportPoint(*static_cast<const SA*>(a), *static_cast<const SB*>(b), d, origin,
                                unit);
          }};
}

// GJK on the cores of A and B, in coordinates relative to `origin`; `towardB` (local) is the
// first search direction.
template <class T>
GjkRun<T> runGjk(const CorePair<T>& cores, const Vec3<T>& origin, Vec3<T> towardB);

template <class A, class B>
constexpr void requireSameScalar() {
  static_assert(std::is_same_v<ShapeScalarT<A>, ShapeScalarT<B>>,
                "GJK and EPA need both shapes in the same scalar type");
  static_assert(std::is_floating_point_v<ShapeScalarT<A>>, "float or double expected");
}

// Two shapes as GJK and EPA see them: their cores, reference points and radii.
template <class T>
struct Cores {
  CorePair<T> pair;
  Vec3<T> referenceA, referenceB;
  T ra, rb;
};
template <class A, class B>
Cores<ShapeScalarT<A>> coresOf(const A& a, const B& b) {
  requireSameScalar<A, B>();
  using T = ShapeScalarT<A>;
  return {corePair<T>(a, b), referencePoint(a), referencePoint(b), coreRadius(a), coreRadius(b)};
}

// gjkDistance on the cores, compiled once per scalar (src/reference/geometry3d/gjk.cpp).
template <class T>
GjkResultT<T> gjkDistance(const Cores<T>& shapes);

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Distance and closest points of two convex shapes (see the top of this file). Shapes whose
// distance is below kTouchTolerance times the size of the problem count as intersecting, with
// distance 0 and a common point.
template <class A, class B>
GjkResultT<ShapeScalarT<A>> gjkDistance(const A& a, const B& b) {
  return detail::gjkDistance(detail::coresOf(a, b));
}

// Whether two convex shapes intersect (touching counts): exactly gjkDistance(a, b).intersecting.
template <class A, class B>
bool gjkIntersect(const A& a, const B& b) {
  return gjkDistance(a, b).intersecting;
}

}  // namespace simdphys

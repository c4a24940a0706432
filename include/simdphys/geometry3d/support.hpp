// Convex shapes as GJK and EPA see them (gjk.hpp, epa.hpp): support functions, Minkowski sums and
// differences, convex hulls, and each shape's core and radius.
//
// A convex shape is anything with `support(shape, direction)`, its farthest point along a
// direction: the primitives of primitives.hpp, a ConvexHullT (a view of points), a Minkowski sum
// or difference of two shapes, or a user type found by argument-dependent lookup (which also
// names its scalar as a member `using Scalar = float;` or by specialising ShapeScalar).
//
// Robustness measures, beyond the book:
// - Local coordinates. coreSupport(shape, d, origin) subtracts the origin (a point of A) from the
//   shape's own data first (a box's center - origin, then + half extents), so shapes at 1e5 with
//   sizes of 1e-2 keep float's relative precision in their distance.
// - Cores and radii. A sphere is its centre grown by its radius (a Minkowski sum adds its
//   parts' radii): GJK and EPA run on the cores, which are polytopes for every shape here, and
//   the radii are added at the end.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <type_traits>

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

// ---------------------------------------------------------------------------------------------
// Support functions: the point of the shape farthest along `direction`. The direction need not
// be unit; for a zero direction (where every point is farthest) the answer is a point of the
// shape: a sphere's centre, a box's corner selected by the sign bits (+ for 0), a triangle's or
// segment's or hull's first vertex. Ties go to the first vertex.

template <class T>
Vec3<T> support(const SphereT<T>& s, const detail::NoDeduce<Vec3<T>>& direction);

template <class T>
Vec3<T> support(const AabbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction);

template <class T>
Vec3<T> support(const ObbT<T>& b, const detail::NoDeduce<Vec3<T>>& direction);

template <class T>
Vec3<T> support(const TriangleT<T>& t, const detail::NoDeduce<Vec3<T>>& direction);

template <class T>
Vec3<T> support(const SegmentT<T>& s, const detail::NoDeduce<Vec3<T>>& direction);

template <class T>
Vec3<T> support(const ConvexHullT<T>& h, const detail::NoDeduce<Vec3<T>>& direction);

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
Vec3<T> coreSupport(const SphereT<T>& s, const Vec3<T>&, const Vec3<T>& origin);
template <class T>
T coreRadius(const SphereT<T>& s);
template <class T>
Vec3<T> referencePoint(const SphereT<T>& s);

template <class T>
Vec3<T> coreSupport(const AabbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin);
template <class T>
Vec3<T> referencePoint(const AabbT<T>& b);

template <class T>
Vec3<T> coreSupport(const ObbT<T>& b, const Vec3<T>& d, const Vec3<T>& origin);
template <class T>
Vec3<T> referencePoint(const ObbT<T>& b);

// For vertex sets the dot products are taken in local coordinates too: at 1e5 a float dot product
// could not tell apart vertices 1e-2 apart.
template <class T>
Vec3<T> coreSupport(const TriangleT<T>& t, const Vec3<T>& d, const Vec3<T>& origin);
template <class T>
Vec3<T> referencePoint(const TriangleT<T>& t);

template <class T>
Vec3<T> coreSupport(const SegmentT<T>& s, const Vec3<T>& d, const Vec3<T>& origin);
template <class T>
Vec3<T> referencePoint(const SegmentT<T>& s);

template <class T>
Vec3<T> coreSupport(const ConvexHullT<T>& h, const Vec3<T>& d, const Vec3<T>& origin);
template <class T>
Vec3<T> referencePoint(const ConvexHullT<T>& h);

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

}  // namespace detail
}  // namespace simdphys

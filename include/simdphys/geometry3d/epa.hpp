// EPA, the Expanding Polytope Algorithm (the book's appendix): penetration depth, normal and
// points of two intersecting convex shapes (support.hpp), started from GJK's final simplex
// (gjk.hpp). It grows its polytope only across the horizon of the faces the new point sees,
// checks every new face for a vanishing area and an inward normal before it commits, and
// otherwise stops with the best face so far; it stops at kEpaTolerance or after
// kEpaMaxIterations expansions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "simdphys/geometry3d/gjk.hpp"

namespace simdphys {

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

using Penetration = PenetrationT<float>;
using Penetrationd = PenetrationT<double>;

// Caps and tolerance: see gjk.hpp.
inline constexpr int kEpaMaxIterations = 128;
template <class T>
inline constexpr T kEpaTolerance = T(64) * std::numeric_limits<T>::epsilon();

namespace detail {

// ---- EPA ------------------------------------------------------------------------------------

template <class T>
struct EpaCoreResult {
  Vec3<T> normal = Vec3<T>::UnitX();
  T depth = 0;
  Vec3<T> pointA = Vec3<T>::Zero(), pointB = Vec3<T>::Zero();
  int iterations = 0;
};

// EPA on the cores. `run` is GJK's final state with the cores overlapping or touching; `towardB`
// orients the normal when the cores' difference is flat (no interior: depth 0 either way).
template <class T>
EpaCoreResult<T> epaCore(const CorePair<T>& cores, const Vec3<T>& origin, const GjkRun<T>& run,
                         const Vec3<T>& towardB);

// epa on the cores, compiled once per scalar (src/reference/geometry3d/epa.cpp).
template <class T>
std::optional<PenetrationT<T>> epa(const Cores<T>& shapes);

}  // namespace detail

// Penetration of two intersecting convex shapes (std::nullopt exactly when gjkIntersect is
// false). The normal is unit and points from A to B. When the cores are apart and only the radii
// overlap, the answer is closed-form along the line between the cores' closest points. When the
// cores' Minkowski difference has no interior (e.g. two coplanar triangles, a sphere whose centre
// is inside a triangle), the cores' depth is 0 and the normal is that of the flat difference,
// signed towards B; for a difference that is a point (concentric spheres) it is the direction
// between the shapes' reference points, or +x if they coincide.
template <class A, class B>
std::optional<PenetrationT<ShapeScalarT<A>>> epa(const A& a, const B& b) {
  return detail::epa(detail::coresOf(a, b));
}

}  // namespace simdphys

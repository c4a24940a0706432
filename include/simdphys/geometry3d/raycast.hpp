// Raycasts and linetests against the 3D primitives (book chapters 10 and 11): sphere, AABB, OBB,
// plane and triangle, with a hit record. Templates on the scalar (float is the API, double the
// reference), declared here and compiled once for both in src/reference/raycast.cpp.
//
// Conventions
// - `raycast(shape, ray, tMax)` returns the first hit with t in [0, tMax] (closed), or nothing.
//   t is the distance along the ray's unit direction and `point` is origin + t * direction
//   (for an AABB the coordinate on the hit axis is then set to the face exactly and the others
//   clamped into the box, so the point lies on the box). Rays and shapes are not validated here:
//   validate them where they enter (a non-unit direction gives t in units of its length); they
//   are assumed within the supported range of math.hpp (what validate() accepts), where no
//   computation overflows and the batch forms (batch.hpp) agree with these on every path.
// - `normal` is unit and faces the ray: dot(normal, direction) <= 0, exactly for AABBs,
//   triangles and plane raycasts, to rounding (a few eps) for spheres, OBBs and plane linecasts.
// - Solids (sphere, AABB, OBB) are closed: touching counts. Along the ray the solid occupies an
//   interval [tEnter, tExit]. If tEnter >= 0 the hit is the entry, inside = false, normal = the
//   outward normal there. Otherwise the ray starts inside and the hit is the exit (tExit >= 0):
//   inside = true, and the normal is the outward normal there *negated*, so that it faces the
//   ray like every other normal (the book returns the outward one, which points along the ray).
//   Hence a ray starting on the surface: heading in (or tangent to a sphere) hits at t = 0 with
//   inside = false; heading out hits at t = 0 with inside = true; sliding along a box face from a
//   point on it is inside the closed box and exits where it leaves the face.
// - At a box edge or corner (several faces at the same t) the normal is that of the lowest axis.
// - Planes and triangles are two-sided surfaces: hits from either side, inside is always false,
//   the normal is the surface normal or its negation, whichever faces the ray. A ray lying in
//   the plane (parallel, n.d == 0) does not hit it, whether or not it lies on it. A plane's
//   n.p + d is evaluated in double for float input (it cancels at large coordinates).
// - Triangles use the watertight test of Woop, Benthin and Wald (2013): a ray through an edge or
//   vertex shared by triangles of a mesh hits at least one of them. A degenerate triangle (its
//   normal (b - a) x (c - a), computed in double, is exactly zero) is never hit.
// - `linecast(shape, segment)` is the raycast from segment.start towards segment.end limited to
//   the segment, with t the distance from start in [0, length]; it reports the same surface
//   crossings as a raycast, so a segment wholly inside a solid, or lying in a plane, has none.
// - `linetest(shape, segment)` is true when the closed segment and the closed shape share a
//   point: linecast(...) has a value, or the start is inside a solid, or the segment lies in the
//   plane (for a triangle: in its plane, meeting it). A degenerate segment (squared length below
//   the smallest normal number) is a point: linetest is the point test, linecast returns nothing.
//
// Watertightness needs each product of the triangle edge functions rounded on its own: a fused
// a * b - c * d is not exactly antisymmetric and can open cracks along shared edges. The inline
// parts of this header (intersectTriangle) are compiled with their users' flags, so it turns
// contraction off for its own functions; the library builds the rest with -ffp-contract=off.
#pragma once

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>

#include "simdphys/detail/float_math.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/math.hpp"

#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#endif

namespace simdphys {

// Where a ray or segment meets a shape.
template <class T>
struct RayHitT {
  T t;             // distance from the origin along the unit direction, >= 0
  Vec3<T> point;   // on the surface
  Vec3<T> normal;  // unit, facing the ray: dot(normal, direction) <= 0
  bool inside;     // the ray started inside the solid and this is where it leaves
};

// A ray's precomputation for the watertight triangle test, reused for every triangle it meets.
// The axis kz of the largest |direction| component becomes the depth axis; kx, ky are the other
// two, swapped when direction[kz] < 0 so that the winding of triangles is preserved; the shear
// (sx, sy) maps the direction onto the kz axis, so every triangle is tested in 2D around the ray.
template <class T>
struct WatertightRayT {
  Vec3<T> origin, direction;
  int kx = 0, ky = 1, kz = 2;
  T sx = 0, sy = 0, sz = 1;

  WatertightRayT() = default;
  explicit WatertightRayT(const RayT<T>& ray) : WatertightRayT(ray.origin, ray.direction) {}
  // Any non-zero direction; t is then in units of its length.
  WatertightRayT(const Vec3<T>& o, const Vec3<T>& d) : origin(o), direction(d) {
    d.cwiseAbs().maxCoeff(&kz);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = T(1) / d[kz];
  }
};

// A watertight ray-triangle hit: t along the ray and the barycentric weights of a, b, c
// (u + v + w = 1 up to rounding; the point is u a + v b + w c).
template <class T>
struct TriangleHitT {
  T t, u, v, w;
};

using RayHit = RayHitT<float>;
using RayHitd = RayHitT<double>;
using WatertightRay = WatertightRayT<float>;
using WatertightRayd = WatertightRayT<double>;
using TriangleHit = TriangleHitT<float>;
using TriangleHitd = TriangleHitT<double>;

namespace detail::rays {

template <class T>
inline constexpr T kInfinity = std::numeric_limits<T>::infinity();

// a * b - c * d with the sign exact when the rounded result is 0 (detail/float_math.hpp).
using detail::differenceOfProducts;

// The triangle's normal (b - a) x (c - a), not normalised, computed in double.
template <class T>
Vec3d triangleNormalWide(const TriangleT<T>& tri) {
  const Vec3d a = tri.a.template cast<double>();
  return (tri.b.template cast<double>() - a).cross(tri.c.template cast<double>() - a);
}

// 2D orientation (twice the signed area of p, q, r), in double: exact for float coordinates
// whose differences are exact in double (inputs within a factor 2^29 of each other).
inline double orient2d(const Vec2d& p, const Vec2d& q, const Vec2d& r) {
  const double left = (q[0] - p[0]) * (r[1] - p[1]);
  const double right = (q[1] - p[1]) * (r[0] - p[0]);
  return left - right;
}

// A segment shorter than sqrt(smallest normal number) is a point: its squared length, which the
// sphere test divides by, would be subnormal or zero.
template <class T>
bool isPointSegment(const SegmentT<T>& s) {
  return !(s.direction().squaredNorm() >= std::numeric_limits<T>::min());
}

// The solids (sphere, AABB, OBB): their raycasts, linecasts and linetests are one function each,
// over the hit test of the kind.
template <class S, class T>
concept Solid =
    std::same_as<S, SphereT<T>> || std::same_as<S, AabbT<T>> || std::same_as<S, ObbT<T>>;

}  // namespace detail::rays

// ---- the watertight triangle test ------------------------------------------------------------

// Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013, two-sided.
// The vertices are moved into the ray's sheared frame, where the ray is the kz axis through the
// origin; the 2D edge functions u, v, w then depend only on an edge's two vertices, so triangles
// sharing an edge compute it identically (with opposite signs), and a point exactly on it is
// accepted by both (>= 0 tests). When an edge function rounds to exactly 0 it is recomputed with
// more precision (see differenceOfProducts), so that "on the edge" is decided exactly. Returns
// the hit with t in [0, tMax] (in units of the ray's direction), or nothing; det == 0 (the ray
// parallel to the triangle's plane, or a triangle with no area in the ray's view) is a miss.
// Degenerate triangles are not filtered here (meshes reject them); see raycast for that.
template <class T>
std::optional<TriangleHitT<T>> intersectTriangle(
    const WatertightRayT<T>& ray, const TriangleT<T>& tri,
    detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  const Vec3<T> a = tri.a - ray.origin, b = tri.b - ray.origin, c = tri.c - ray.origin;
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const T ax = a[kx] - ray.sx * a[kz], ay = a[ky] - ray.sy * a[kz];
  const T bx = b[kx] - ray.sx * b[kz], by = b[ky] - ray.sy * b[kz];
  const T cx = c[kx] - ray.sx * c[kz], cy = c[ky] - ray.sy * c[kz];
  const T u = detail::rays::differenceOfProducts(cx, by, cy, bx);
  const T v = detail::rays::differenceOfProducts(ax, cy, ay, cx);
  const T w = detail::rays::differenceOfProducts(bx, ay, by, ax);
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return std::nullopt;
  const T det = u + v + w;
  if (!(det != 0)) return std::nullopt;
  const T scaledT = u * (ray.sz * a[kz]) + v * (ray.sz * b[kz]) + w * (ray.sz * c[kz]);
  // Near the edges of the supported range u * depth (about L^2 times the distance) overflows;
  // the barycentric form cannot (u / det is in [0, 1] for a hit) and is taken only then, so
  // every other t keeps its bits. The SIMD kernels (watertight-inl.hpp) do the same.
  const T t = std::isfinite(scaledT) ? scaledT / det
                                     : u / det * (ray.sz * a[kz]) + v / det * (ray.sz * b[kz]) +
                                           w / det * (ray.sz * c[kz]);
  if (!(t >= 0 && t <= tMax)) return std::nullopt;
  return TriangleHitT<T>{t + T(0), u / det, v / det, w / det};
}

// ---- raycasts --------------------------------------------------------------------------------

// A solid: sphere, AABB or OBB.
template <class S, class T>
requires detail::rays::Solid<S, T> std::optional<RayHitT<T>> raycast(
    const S& solid, const RayT<T>& ray, detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>);

template <class T>
std::optional<RayHitT<T>> raycast(const PlaneT<T>& plane, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>);

// With the ray's watertight precomputation, for casting one ray against many triangles.
template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>);

template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>);

// ---- linecasts -------------------------------------------------------------------------------

template <class S, class T>
requires detail::rays::Solid<S, T> std::optional<RayHitT<T>> linecast(const S& solid,
                                                                      const SegmentT<T>& s);

// The crossing comes from the signed distances of the two ends, so that it lies in [0, length]
// exactly when they have opposite signs or one is zero (and differ).
template <class T>
std::optional<RayHitT<T>> linecast(const PlaneT<T>& plane, const SegmentT<T>& s);

template <class T>
std::optional<RayHitT<T>> linecast(const TriangleT<T>& tri, const SegmentT<T>& s);

// ---- linetests -------------------------------------------------------------------------------

// A solid: the segment starts in it or its linecast hits.
template <class S, class T>
requires detail::rays::Solid<S, T>
bool linetest(const S& solid, const SegmentT<T>& s);

// The ends' signed distances have opposite signs or one is zero; a segment in the plane touches it.
template <class T>
bool linetest(const PlaneT<T>& plane, const SegmentT<T>& s);

template <class T>
bool linetest(const TriangleT<T>& tri, const SegmentT<T>& s);

}  // namespace simdphys

#if defined(__clang__)
#pragma clang fp contract(on)
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

// Raycasts and linetests against the 3D primitives (book chapters 10 and 11): sphere, AABB, OBB,
// plane and triangle, with a hit record. Header-only templates on the scalar (float is the API,
// double the reference).
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
// a * b - c * d is not exactly antisymmetric and can open cracks along shared edges. This header
// is compiled with its users' flags, so it turns contraction off for its own functions.
#pragma once

#include <algorithm>
#include <cmath>
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

// v / |v| without overflow or underflow of |v|^2 (math.hpp's unitOr); `fallback` when v is zero
// or not finite.
template <class T>
Vec3<T> unitOr(const Vec3<T>& v, const Vec3<T>& fallback) {
  return detail::unitOr(v, fallback);
}

// a * b - c * d with the sign exact when the rounded result is 0 (detail/float_math.hpp).
using detail::differenceOfProducts;

// The slab test of the line o + t d against the closed box [lo, hi], t in units of d. Near and far
// planes are chosen by the sign bit of d (that of 1/d; -0 counts as negative, as 1/-0 = -inf), so
// tNear <= tFar whenever both are numbers. A direction component of +-0 with the origin exactly
// on that slab's plane gives 0/0 = NaN: the comparisons below are false for NaN, so that plane
// puts no bound on t and the closed slab contains the whole line (no NaN reaches the result).
// Ties keep the lowest axis.
template <class T>
struct SlabHit {
  T t;
  int axis;
  bool inside;  // the origin is in the box and t is the exit
};

template <class T>
std::optional<SlabHit<T>> slabs(const Vec3<T>& lo, const Vec3<T>& hi, const Vec3<T>& o,
                                const Vec3<T>& d, T tMax) {
  T tEnter = -kInfinity<T>, tExit = kInfinity<T>;
  int enterAxis = 0, exitAxis = 0;
  for (int a = 0; a < 3; ++a) {
    const bool negative = std::signbit(d[a]);
    const T tNear = ((negative ? hi[a] : lo[a]) - o[a]) / d[a];
    const T tFar = ((negative ? lo[a] : hi[a]) - o[a]) / d[a];
    if (tNear > tEnter) {
      tEnter = tNear;
      enterAxis = a;
    }
    if (tFar < tExit) {
      tExit = tFar;
      exitAxis = a;
    }
  }
  if (!(tEnter <= tExit)) return std::nullopt;
  // + 0 turns a -0 (from 0 / -d) into +0.
  if (tEnter >= 0) {
    if (!(tEnter <= tMax)) return std::nullopt;
    return SlabHit<T>{tEnter + T(0), enterAxis, false};
  }
  if (!(tExit >= 0 && tExit <= tMax)) return std::nullopt;
  return SlabHit<T>{tExit + T(0), exitAxis, true};
}

template <class T>
std::optional<RayHitT<T>> hitAabb(const Vec3<T>& lo, const Vec3<T>& hi, const Vec3<T>& o,
                                  const Vec3<T>& d, T tMax) {
  const auto h = slabs(lo, hi, o, d, tMax);
  if (!h) return std::nullopt;
  const int a = h->axis;
  const bool negative = std::signbit(d[a]);
  // Entering, the ray crosses the near face (hi if it moves towards -a); leaving, the far one. In
  // both cases the normal facing the ray is -sign(d[a]) along a.
  Vec3<T> p = o + h->t * d;
  for (int k = 0; k < 3; ++k) p[k] = std::clamp(p[k], lo[k], hi[k]);
  p[a] = (h->inside != negative) ? hi[a] : lo[a];
  Vec3<T> n = Vec3<T>::Zero();
  n[a] = negative ? T(1) : T(-1);
  return RayHitT<T>{h->t, p, n, h->inside};
}

// The OBB is the AABB [-halfExtents, halfExtents] in its own frame: the ray is moved there and the
// same slab test is run. A rotation keeps lengths, so t needs no conversion.
template <class T>
std::optional<RayHitT<T>> hitObb(const ObbT<T>& box, const Vec3<T>& o, const Vec3<T>& d, T tMax) {
  const Vec3<T> localOrigin = box.axes.transpose() * (o - box.center);
  const Vec3<T> localDirection = box.axes.transpose() * d;
  const auto h = slabs<T>(-box.halfExtents, box.halfExtents, localOrigin, localDirection, tMax);
  if (!h) return std::nullopt;
  const int a = h->axis;
  const Vec3<T> axis = box.axes.col(a).normalized();
  const Vec3<T> n = std::signbit(localDirection[a]) ? axis : Vec3<T>(-axis);
  return RayHitT<T>{h->t, o + h->t * d, n, h->inside};
}

// |o + t d - c| = r for a non-zero d. The distance of the line from the centre comes from the
// perpendicular vector m (Haines et al., "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems, 2019), not from |e|^2 - (e.d)^2, which cancels catastrophically for a small
// sphere far away; the near root is c0 / q, free of the cancellation of b - f. Whether the origin
// is outside, inside or on the sphere is decided once, by the sign of c0 = |e|^2 - r^2.
template <class T>
std::optional<RayHitT<T>> hitSphere(const SphereT<T>& s, const Vec3<T>& o, const Vec3<T>& d,
                                    T tMax) {
  const Vec3<T> e = s.center - o;
  const T dd = d.squaredNorm();
  const T r2 = s.radius * s.radius;
  const T c0 = e.squaredNorm() - r2;
  const T b = e.dot(d) / dd;  // parameter of the point of the line closest to the centre
  Vec3<T> m = e - b * d;      // from that point to the centre
  m -= (m.dot(d) / dd) * d;   // again: the rounding left a part along d; now m.d ~ eps |m|
  const T h2 = r2 - m.squaredNorm();
  T t;
  Vec3<T> outward;  // p - centre at the hit, up to scale
  bool inside;
  if (c0 > 0) {  // outside: hit the entry if the sphere is ahead and the line meets it
    if (!(b > 0) || !(h2 >= 0)) return std::nullopt;
    const T f = std::sqrt(h2 / dd);  // half the chord, in units of t
    t = (c0 / dd) / (b + f);
    outward = -m - f * d;
    inside = false;
  } else if (c0 < 0) {  // inside: the exit, always ahead
    const T f = std::sqrt(std::max(h2, T(0)) / dd);
    t = b >= 0 ? b + f : (c0 / dd) / (b - f);
    outward = -m + f * d;
    inside = true;
  } else if (c0 == 0) {  // on the surface: entering, tangent (b == 0) or leaving, all at t = 0
    t = 0;
    outward = -e;
    inside = b < 0;
  } else {
    return std::nullopt;  // NaN
  }
  if (!(t <= tMax)) return std::nullopt;
  // A zero-radius sphere has no normal: -direction, which faces the ray.
  const Vec3<T> n = unitOr<T>(inside ? Vec3<T>(-outward) : outward, -d / std::sqrt(dd));
  return RayHitT<T>{t, o + t * d, n, inside};
}

// n.p + d, in double for float input: at coordinates of 1e5 the two terms cancel and float would
// lose the result's leading digits (the products of floats are exact in double).
template <class T>
T planeDistance(const PlaneT<T>& plane, const Vec3<T>& p) {
  return T(plane.normal.template cast<double>().dot(p.template cast<double>()) + double(plane.d));
}

// The plane's signed distance along the line is s0 + t * rate; it is crossed at t = -s0 / rate.
template <class T>
std::optional<RayHitT<T>> hitPlane(const PlaneT<T>& plane, const Vec3<T>& o, const Vec3<T>& d, T s0,
                                   T rate, T tMax) {
  if (!(rate != 0)) return std::nullopt;  // parallel, in the plane or not (or NaN)
  const T t = -s0 / rate;
  if (!(t >= 0 && t <= tMax)) return std::nullopt;
  const Vec3<T> n = rate < 0 ? plane.normal : Vec3<T>(-plane.normal);
  return RayHitT<T>{t + T(0), o + t * d, n, false};
}

// The triangle's normal (b - a) x (c - a), not normalised, computed in double.
template <class T>
Vec3d triangleNormalWide(const TriangleT<T>& tri) {
  const Vec3d a = tri.a.template cast<double>();
  return (tri.b.template cast<double>() - a).cross(tri.c.template cast<double>() - a);
}

template <class T>
std::optional<RayHitT<T>> hitTriangle(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                      T tMax);

// 2D orientation (twice the signed area of p, q, r), in double: exact for float coordinates
// whose differences are exact in double (inputs within a factor 2^29 of each other).
inline double orient2d(const Vec2d& p, const Vec2d& q, const Vec2d& r) {
  const double left = (q[0] - p[0]) * (r[1] - p[1]);
  const double right = (q[1] - p[1]) * (r[0] - p[0]);
  return left - right;
}

// The segment pq lies in the triangle's plane (judged in double) and meets the closed triangle.
template <class T>
bool touchesTriangleInItsPlane(const TriangleT<T>& tri, const Vec3<T>& p3, const Vec3<T>& q3) {
  const Vec3d n = triangleNormalWide(tri);
  if ((n.array() == 0).all()) return false;  // degenerate: never touched
  const Vec3d a3 = tri.a.template cast<double>();
  if (n.dot(p3.template cast<double>() - a3) != 0 || n.dot(q3.template cast<double>() - a3) != 0)
    return false;
  // Drop the axis of the largest normal component: the projection keeps the triangle's area.
  int k;
  n.cwiseAbs().maxCoeff(&k);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const auto flat = [&](const Vec3<T>& v) { return Vec2d(double(v[i]), double(v[j])); };
  const Vec2d v[3] = {flat(tri.a), flat(tri.b), flat(tri.c)};
  const Vec2d p = flat(p3), q = flat(q3);
  const auto inTriangle = [&](const Vec2d& x) {
    const double e0 = orient2d(v[0], v[1], x), e1 = orient2d(v[1], v[2], x),
                 e2 = orient2d(v[2], v[0], x);
    return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
  };
  if (inTriangle(p) || inTriangle(q)) return true;
  // Both ends outside: the segment meets the triangle iff it crosses an edge properly or passes
  // through a vertex (which also covers running along an edge).
  const auto onSegment = [&](const Vec2d& x) {
    return std::min(p[0], q[0]) <= x[0] && x[0] <= std::max(p[0], q[0]) &&
           std::min(p[1], q[1]) <= x[1] && x[1] <= std::max(p[1], q[1]);
  };
  const auto opposite = [](double x, double y) { return (x > 0 && y < 0) || (x < 0 && y > 0); };
  for (int e = 0; e < 3; ++e) {
    const Vec2d& e0 = v[e];
    const Vec2d& e1 = v[(e + 1) % 3];
    const double s0 = orient2d(p, q, e0), s1 = orient2d(p, q, e1);
    if (s0 == 0 && onSegment(e0)) return true;
    if (opposite(s0, s1) && opposite(orient2d(e0, e1, p), orient2d(e0, e1, q))) return true;
  }
  return false;
}

// A segment shorter than sqrt(smallest normal number) is a point: its squared length, which the
// sphere test divides by, would be subnormal or zero.
template <class T>
bool isPointSegment(const SegmentT<T>& s) {
  return !(s.direction().squaredNorm() >= std::numeric_limits<T>::min());
}

// A linecast through one of the hit functions above: t comes back in units of end - start (in
// [0, 1]) and is turned into a distance.
template <class T, class F>
std::optional<RayHitT<T>> alongSegment(const SegmentT<T>& s, F&& hit) {
  if (isPointSegment(s)) return std::nullopt;
  std::optional<RayHitT<T>> h = hit(s.start, s.direction());
  if (h) h->t *= s.length();
  return h;
}

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

template <class T>
std::optional<RayHitT<T>> raycast(const SphereT<T>& sphere, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitSphere(sphere, ray.origin, ray.direction, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const AabbT<T>& box, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitAabb(box.min, box.max, ray.origin, ray.direction, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const ObbT<T>& box, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitObb(box, ray.origin, ray.direction, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const PlaneT<T>& plane, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitPlane(plane, ray.origin, ray.direction,
                                detail::rays::planeDistance(plane, ray.origin),
                                plane.normal.dot(ray.direction), tMax);
}

// With the ray's watertight precomputation, for casting one ray against many triangles.
template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitTriangle(tri, ray, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax = detail::rays::kInfinity<T>) {
  return detail::rays::hitTriangle(tri, WatertightRayT<T>(ray), tMax);
}

namespace detail::rays {
template <class T>
std::optional<RayHitT<T>> hitTriangle(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                      T tMax) {
  const auto h = intersectTriangle(ray, tri, tMax);
  if (!h) return std::nullopt;
  // The normal in double: a float cross product of a small or thin triangle loses its digits.
  const Vec3d wide = triangleNormalWide(tri);
  if ((wide.array() == 0).all()) return std::nullopt;  // degenerate: never hit
  Vec3<T> n = unitOr<double>(wide, Vec3d::Zero()).template cast<T>();
  if (n.dot(ray.direction) > 0) n = -n;  // exact: the negated dot product is the negated sum
  return RayHitT<T>{h->t, ray.origin + h->t * ray.direction, n, false};
}
}  // namespace detail::rays

// ---- linecasts -------------------------------------------------------------------------------

template <class T>
std::optional<RayHitT<T>> linecast(const SphereT<T>& sphere, const SegmentT<T>& s) {
  return detail::rays::alongSegment(s, [&](const Vec3<T>& o, const Vec3<T>& d) {
    return detail::rays::hitSphere(sphere, o, d, T(1));
  });
}

template <class T>
std::optional<RayHitT<T>> linecast(const AabbT<T>& box, const SegmentT<T>& s) {
  return detail::rays::alongSegment(s, [&](const Vec3<T>& o, const Vec3<T>& d) {
    return detail::rays::hitAabb(box.min, box.max, o, d, T(1));
  });
}

template <class T>
std::optional<RayHitT<T>> linecast(const ObbT<T>& box, const SegmentT<T>& s) {
  return detail::rays::alongSegment(
      s, [&](const Vec3<T>& o, const Vec3<T>& d) { return detail::rays::hitObb(box, o, d, T(1)); });
}

// The crossing comes from the signed distances of the two ends, so that it lies in [0, length]
// exactly when they have opposite signs or one is zero (and differ).
template <class T>
std::optional<RayHitT<T>> linecast(const PlaneT<T>& plane, const SegmentT<T>& s) {
  return detail::rays::alongSegment(s, [&](const Vec3<T>& o, const Vec3<T>& d) {
    const T s0 = detail::rays::planeDistance(plane, s.start),
            s1 = detail::rays::planeDistance(plane, s.end);
    return detail::rays::hitPlane(plane, o, d, s0, s1 - s0, T(1));
  });
}

template <class T>
std::optional<RayHitT<T>> linecast(const TriangleT<T>& tri, const SegmentT<T>& s) {
  return detail::rays::alongSegment(s, [&](const Vec3<T>& o, const Vec3<T>& d) {
    return detail::rays::hitTriangle(tri, WatertightRayT<T>(o, d), T(1));
  });
}

// ---- linetests -------------------------------------------------------------------------------

namespace detail::rays {
// Point-in-solid tests written as the hit functions above compute them, so that "the start is
// inside" agrees with the raycast's inside flag.
template <class T>
bool inClosed(const SphereT<T>& s, const Vec3<T>& p) {
  return (s.center - p).squaredNorm() - s.radius * s.radius <= 0;
}
template <class T>
bool inClosed(const AabbT<T>& b, const Vec3<T>& p) {
  return (b.min.array() <= p.array()).all() && (p.array() <= b.max.array()).all();
}
template <class T>
bool inClosed(const ObbT<T>& b, const Vec3<T>& p) {
  const Vec3<T> local = b.axes.transpose() * (p - b.center);
  return (local.array().abs() <= b.halfExtents.array()).all();
}
template <class T, class Shape>
bool linetestSolid(const Shape& shape, const SegmentT<T>& s) {
  return inClosed(shape, s.start) || linecast(shape, s).has_value();
}
}  // namespace detail::rays

template <class T>
bool linetest(const SphereT<T>& sphere, const SegmentT<T>& s) {
  return detail::rays::linetestSolid(sphere, s);
}

template <class T>
bool linetest(const AabbT<T>& box, const SegmentT<T>& s) {
  return detail::rays::linetestSolid(box, s);
}

template <class T>
bool linetest(const ObbT<T>& box, const SegmentT<T>& s) {
  return detail::rays::linetestSolid(box, s);
}

// The ends' signed distances have opposite signs or one is zero; a segment in the plane touches it.
template <class T>
bool linetest(const PlaneT<T>& plane, const SegmentT<T>& s) {
  const T s0 = detail::rays::planeDistance(plane, s.start),
          s1 = detail::rays::planeDistance(plane, s.end);
  return (s0 <= 0 && s1 >= 0) || (s0 >= 0 && s1 <= 0);
}

template <class T>
bool linetest(const TriangleT<T>& tri, const SegmentT<T>& s) {
  return linecast(tri, s).has_value() ||
         detail::rays::touchesTriangleInItsPlane(tri, s.start, s.end);
}

}  // namespace simdphys

#if defined(__clang__)
#pragma clang fp contract(on)
#elif defined(__GNUC__)
#pragma GCC pop_options
#endif

// The definitions of simdphys/geometry3d/raycast.hpp (raycasts, linecasts and linetests): included
// by raycast.cpp, which instantiates them for float and double, and by any file of src/ that wants
// them inlined.
#pragma once

#include "simdphys/geometry3d/raycast.hpp"
#include "src/reference/math-inl.hpp"

namespace simdphys {

namespace detail::rays {

// v / |v| without overflow or underflow of |v|^2 (math.hpp's unitOr); `fallback` when v is zero
// or not finite.
template <class T>
Vec3<T> unitOr(const Vec3<T>& v, const Vec3<T>& fallback) {
  return detail::unitOr(v, fallback);
}

// The slab test of the line o + t d against the closed box [lo, hi], t in units of d. Near and far
// planes are chosen by the sign bit of d (that of 1/d; -0 counts as negative, as 1/-0 = -inf), so
// tNear <= tFar whenever both are numbers. A direction component of +-0 with the origin exactly
// on that slab's plane gives 0/0 = NaN: the comparisons below are false for NaN, so that plane
// puts no bound on t and the closed slab contains the whole line (no NaN reaches the result).
// Ties keep the lowest axis. This is core/ray_slab-inl.hpp's clipSlab (its comparison form, as
// batch3d.cpp's rayClosestBox runs it) written out, because the hit also needs the axis of the face
// entered or left, for its normal, which the shared lane form does not track.
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

template <class T>
std::optional<RayHitT<T>> hitTriangle(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                      T tMax);

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

namespace detail::rays {

// The line o + t d, t in [0, tMax], against a solid: the hit test of its kind.
template <class S, class T>
std::optional<RayHitT<T>> hitSolid(const S& solid, const Vec3<T>& o, const Vec3<T>& d, T tMax) {
  if constexpr (std::is_same_v<S, SphereT<T>>)
    return hitSphere(solid, o, d, tMax);
  else if constexpr (std::is_same_v<S, AabbT<T>>)
    return hitAabb(solid.min, solid.max, o, d, tMax);
  else
    return hitObb(solid, o, d, tMax);
}

}  // namespace detail::rays

template <class S, class T>
requires detail::rays::Solid<S, T> std::optional<RayHitT<T>> raycast(const S& solid,
                                                                     const RayT<T>& ray,
                                                                     detail::NoDeduce<T> tMax) {
  return detail::rays::hitSolid(solid, ray.origin, ray.direction, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const PlaneT<T>& plane, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax) {
  return detail::rays::hitPlane(plane, ray.origin, ray.direction,
                                detail::rays::planeDistance(plane, ray.origin),
                                plane.normal.dot(ray.direction), tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const WatertightRayT<T>& ray,
                                  detail::NoDeduce<T> tMax) {
  return detail::rays::hitTriangle(tri, ray, tMax);
}

template <class T>
std::optional<RayHitT<T>> raycast(const TriangleT<T>& tri, const RayT<T>& ray,
                                  detail::NoDeduce<T> tMax) {
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

template <class S, class T>
requires detail::rays::Solid<S, T> std::optional<RayHitT<T>> linecast(const S& solid,
                                                                      const SegmentT<T>& s) {
  return detail::rays::alongSegment(s, [&](const Vec3<T>& o, const Vec3<T>& d) {
    return detail::rays::hitSolid(solid, o, d, T(1));
  });
}

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

}  // namespace detail::rays

template <class S, class T>
requires detail::rays::Solid<S, T>
bool linetest(const S& solid, const SegmentT<T>& s) {
  return detail::rays::inClosed(solid, s.start) || linecast(solid, s).has_value();
}

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

// The definitions of simdphys/geometry3d/point_tests.hpp (3D containment, closest points,
// barycentric coordinates): included by point_tests.cpp, which instantiates them for float and
// double, and by any file of src/ that wants them inlined.
#pragma once

#include "simdphys/geometry3d/point_tests.hpp"
#include "src/reference/math-inl.hpp"
#include "src/reference/point_tests-inl.hpp"

namespace simdphys {

namespace detail {

// num / den clamped to [0, 1], and 0 when den is not positive (num >= 0 is known by the caller).
template <class T>
T unitRatio(T num, T den) {
  return den > 0 ? std::clamp(num / den, T(0), T(1)) : T(0);
}

// The tolerance of "p is on the shape" (see the header comment): the computation's rounding,
// relative to the local scale, and the rounding of p's coordinates.
template <class T>
T onShapeTolerance(T localScale, const Vec3<T>& p) {
  return kGeometryTolerance<T> * localScale +
         std::numeric_limits<T>::epsilon() * p.cwiseAbs().maxCoeff();
}

template <class T>
T longestEdgeSquared(const Vec3<T>& ab, const Vec3<T>& ac, const Vec3<T>& bc) {
  return std::max({ab.squaredNorm(), ac.squaredNorm(), bc.squaredNorm()});
}

// A triangle is degenerate when its height over the longest edge L is at most the tolerance times
// L, |ab x ac| <= tol L^2: it is then a segment (or a point) to within the tolerance. The cross
// product is accurate to about 2 eps L^2, so an exactly collinear triangle is always degenerate.
// |n|^2 ~ L^4 overflows in float for L above about 1e9 and underflows below 1e-9: callers scale
// the edges first (TriangleFrame; intersect.hpp's triangle tests).
template <class T>
bool degenerateTriangle(const Vec3<T>& normal, T longestSquared) {
  return normal.norm() <= kGeometryTolerance<T> * longestSquared;
}

// A triangle and a query point as offsets from the vertices, scaled by a power of two so that the
// longest edge is about 1 (exact: the scaled computation rounds exactly as the unscaled one would
// if it had an unbounded exponent). Products of up to four lengths (|n|^2, n.(e x ap)) then stay
// finite for triangles of any size in the supported range (with edges of 1e10, L^4 = 1e40 would
// overflow float) and do not underflow for small ones (edges of 1e-10). The offset of p counts
// when it is over 2^100 times the triangle's size, so that scaled values stay below about 2^105
// (finite) even for a query 1e18 away from a triangle of 1e-18; the triangle is then a point to
// far within eps |ap|, and its tiny scaled edges may underflow harmlessly.
//
// The normal is computed as e x w from the longest edge e and the height w of the third vertex
// over e's line (its offset r from the nearer end of e, minus r's part along e), not as
// (b - a) x (c - a). Both are (b - a) x (c - a) in exact arithmetic (edges taken in the cyclic
// order ab, bc, ca), but the cross product of two nearly parallel edges rounds each component by
// about eps L^2, in any direction, and on a thin triangle (|n| = L h, h << L) that tilts n by
// eps L / h also along the triangle, where offsets are long: n.ap was off by eps L |ap| / h (4e-5
// for the second reproducer). e and w are perpendicular, so e x w is accurate to a few eps
// relative to |n| but for the rounding of w, eps |r|: it tilts n about e, across the triangle,
// where its offsets are at most h long, so n.(offset) is off by a few eps |r| <= eps L only, and
// it changes |n| by eps |r| / h relative. |r| is the triangle's second-longest edge at most: on
// a needle (one short edge) r is that short edge and n is accurate to a few eps; on a flat cap
// (one angle near pi) |r| / h is large, as intrinsically (the cap's area moves by that much
// when its middle vertex moves by eps |r|).
template <class T>
struct TriangleFrame {
  Vec3<T> ab, ac, bc, ap, bp, cp;  // scaled offsets
  Vec3<T> n;                       // scaled normal, (b - a) x (c - a) (see above)
  T lab, lac, lbc;                 // scaled squared edge lengths
  T scale;                         // a power of two: true offset = scale * scaled offset

  TriangleFrame(const TriangleT<T>& t, const Vec3<T>& p) {
    ab = t.b - t.a, ac = t.c - t.a, bc = t.c - t.b, ap = p - t.a, bp = p - t.b, cp = p - t.c;
    const T size = std::max({ab.cwiseAbs().maxCoeff(), ac.cwiseAbs().maxCoeff(),
                             bc.cwiseAbs().maxCoeff(), std::ldexp(ap.cwiseAbs().maxCoeff(), -100)});
    const T inverse = inversePowerOfTwo(size);
    scale = T(1) / inverse;
    for (Vec3<T>* v : {&ab, &ac, &bc, &ap, &bp, &cp}) *v *= inverse;
    lab = ab.squaredNorm(), lac = ac.squaredNorm(), lbc = bc.squaredNorm();
    // The longest edge e, from P to Q, and the offset r of the third vertex from the nearer of P
    // and Q (equivalent: e x (R - P) = e x (R - Q)).
    const auto nearer = [](const Vec3<T>& x, T lx, const Vec3<T>& y, T ly) {
      return lx <= ly ? x : y;
    };
    Vec3<T> e, r;
    if (lab >= lac && lab >= lbc)
      e = ab, r = nearer(ac, lac, bc, lbc);  // P = a, Q = b, R = c
    else if (lbc >= lac)
      e = bc, r = -nearer(ab, lab, ac, lac);  // P = b, Q = c, R = a
    else
      e = -ac, r = nearer(Vec3<T>(-bc), lbc, ab, lab);  // P = c, Q = a, R = b
    const T ee = e.squaredNorm();
    n = ee > 0 ? e.cross(r - e * (r.dot(e) / ee)) : Vec3<T>::Zero();
  }

  T longestSquared() const { return std::max({lab, lac, lbc}); }

  bool degenerate() const { return degenerateTriangle(n, longestSquared()); }
};

// Degenerate triangle: the segment of its longest edge (within the tolerance it holds the third
// vertex). The longest edge is chosen by squared lengths, exact up to rounding: two edges whose
// squared lengths round alike differ in length by about eps L, and so do their segments. (Taking
// the closest of the three edges' closest points instead compares distances that differ by less
// than their rounding and can pick a wrong edge up to L sqrt(eps) away.) Returns the scaled
// offset of the closest point from a.
template <class T>
Vec3<T> closestOnDegenerateTriangle(const TriangleFrame<T>& f) {
  if (f.lab >= f.lac && f.lab >= f.lbc) return segmentParameter(f.ab, f.ap) * f.ab;
  if (f.lac >= f.lbc) return segmentParameter(f.ac, f.ap) * f.ac;
  return f.ab + segmentParameter(f.bc, f.bp) * f.bc;
}

// Ericson, Real-Time Collision Detection 5.1.5: find the Voronoi region of p (three vertex
// regions, three edge regions, the face) from the signs of dot products, then project onto that
// feature. The region tests va, vb, vc are written as n.(edge x offset) (equal to Ericson's
// d1 d4 - d3 d2 etc. by the Binet-Cauchy identity) because products of dot products lose digits
// to cancellation on thin triangles.
//
// In the face region the point is p projected onto the plane, ap - n (n.ap) / |n|^2, not
// Ericson's v ab + w ac: the barycentric weights of a thin triangle are uncertain by about
// eps L^2 / |n| each, which moved v ab + w ac along the triangle by that times L (1e-5 for a unit
// triangle with |n| / L^2 = 1e-2 in float). The projection's error is bounded without the angles:
// n (TriangleFrame) is off in direction only across the triangle, where offsets over it are at
// most |n| / L long, so n.ap is off by a few eps L for p over the triangle. The face test uses
// the same n, so the projected point lies in the (computed) face. Altogether the returned point
// is within about 8 eps (L + |ap|) of the true closest point for p on or near the triangle,
// whatever its angles; for p at a distance D off the plane add about 8 eps D L^2 / |n| along the
// plane (its tilt, as uncertain as the rounding of the vertices' offsets makes it). Measured
// against a double oracle: geometry3d_triangle_test.cpp, docs/geometry.md.
// Returns the closest point's offset from a.
template <class T>
Vec3<T> closestOnTriangle(const TriangleT<T>& tri, const Vec3<T>& p) {
  const TriangleFrame<T> f(tri, p);
  const Vec3<T>&ab = f.ab, &ac = f.ac, &bc = f.bc, &ap = f.ap, &bp = f.bp, &cp = f.cp, &n = f.n;
  if (f.degenerate()) return f.scale * closestOnDegenerateTriangle(f);

  const T d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return Vec3<T>::Zero();  // vertex a
  const T d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return tri.b - tri.a;  // vertex b
  const T d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return tri.c - tri.a;  // vertex c

  const T vc = n.dot(ab.cross(ap));  // <= 0: p is beyond edge ab
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return f.scale * (unitRatio(d1, d1 - d3) * ab);
  const T vb = n.dot(ap.cross(ac));  // <= 0: beyond edge ca
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return f.scale * (unitRatio(d2, d2 - d6) * ac);
  const T va = n.dot(bc.cross(bp));  // <= 0: beyond edge bc
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return f.scale * (ab + unitRatio(d4 - d3, (d4 - d3) + (d5 - d6)) * bc);
  // Face region: the projection onto the plane (|n|^2 is well above zero: not degenerate).
  return f.scale * (ap - n * (n.dot(ap) / n.squaredNorm()));
}

}  // namespace detail

template <class T>
bool contains(const SphereT<T>& sphere, const detail::NoDeduce<Vec3<T>>& point) {
  const T distance = (point - sphere.center).norm();
  return distance <=
         sphere.radius + detail::onShapeTolerance(std::max(distance, sphere.radius), point);
}

template <class T>
bool contains(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> offset = point - box.center;
  const Vec3<T> local = box.axes.transpose() * offset;
  const T excess = (local.cwiseAbs() - box.halfExtents).maxCoeff();
  return excess <= detail::onShapeTolerance(offset.norm() + box.halfExtents.maxCoeff(), point);
}

template <class T>
bool contains(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point) {
  return std::abs(plane.signedDistance(point)) <=
         detail::onShapeTolerance(point.norm() + std::abs(plane.d), point);
}

template <class T>
bool contains(const SegmentT<T>& segment, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> d = segment.end - segment.start;
  const Vec3<T> r = point - segment.start;
  const T t = detail::segmentParameter(d, r);
  return (r - t * d).norm() <= detail::onShapeTolerance(std::max(r.norm(), d.norm()), point);
}

template <class T>
bool contains(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> r = point - ray.origin;
  const T t = std::max(T(0), r.dot(ray.direction));
  return (r - t * ray.direction).norm() <= detail::onShapeTolerance(r.norm(), point);
}

template <class T>
bool contains(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> ap = point - triangle.a;
  const T longest = std::sqrt(detail::longestEdgeSquared<T>(
      triangle.b - triangle.a, triangle.c - triangle.a, triangle.c - triangle.b));
  return (ap - detail::closestOnTriangle(triangle, point)).norm() <=
         detail::onShapeTolerance(std::max(ap.norm(), longest), point);
}

template <class T>
Vec3<T> closestPoint(const ObbT<T>& box, const detail::NoDeduce<Vec3<T>>& point) {
  const Vec3<T> local = box.axes.transpose() * (point - box.center);
  const Vec3<T> clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
  if (clamped == local) return point;
  return box.center + box.axes * clamped;
}

template <class T>
Vec3<T> closestPoint(const PlaneT<T>& plane, const detail::NoDeduce<Vec3<T>>& point) {
  return point - plane.normal * plane.signedDistance(point);
}

template <class T>
Vec3<T> closestPoint(const RayT<T>& ray, const detail::NoDeduce<Vec3<T>>& point) {
  const T t = std::max(T(0), (point - ray.origin).dot(ray.direction));
  return ray.origin + t * ray.direction;
}

template <class T>
Vec3<T> closestPoint(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  return triangle.a + detail::closestOnTriangle(triangle, point);
}

template <class T>
Vec3<T> barycentric(const TriangleT<T>& triangle, const detail::NoDeduce<Vec3<T>>& point) {
  const detail::TriangleFrame<T> f(triangle, point);  // scaled: no overflow (see there)
  const Vec3<T>&ab = f.ab, &ac = f.ac, &bc = f.bc, &ap = f.ap, &bp = f.bp, &n = f.n;
  const T lab = f.lab, lac = f.lac, lbc = f.lbc, longest = f.longestSquared();
  if (f.degenerate()) {
    if (!(longest > 0)) return Vec3<T>(1, 0, 0);
    if (lab == longest) {
      const T t = ap.dot(ab) / lab;
      return Vec3<T>(1 - t, t, 0);
    }
    if (lac == longest) {
      const T t = ap.dot(ac) / lac;
      return Vec3<T>(1 - t, 0, t);
    }
    const T t = bp.dot(bc) / lbc;
    return Vec3<T>(0, 1 - t, t);
  }
  const T nn = n.squaredNorm();
  return Vec3<T>(n.dot(bc.cross(bp)) / nn, n.dot(ap.cross(ac)) / nn, n.dot(ab.cross(ap)) / nn);
}

template <class T>
SegmentClosestPointsT<T> closestPoints(const SegmentT<T>& first, const SegmentT<T>& second) {
  const Vec3<T> d1 = first.end - first.start, d2 = second.end - second.start;
  const Vec3<T> r = second.start - first.start;
  T bestS = 0, bestT = 0;
  T best = std::numeric_limits<T>::infinity();
  // The offset first(s) - second(t), taken from the starts so that it has no cancellation.
  const auto consider = [&](T s, T t) {
    const T distance = (s * d1 - t * d2 - r).norm();
    if (distance < best) {
      best = distance;
      bestS = s;
      bestT = t;
    }
  };
  // s and t are ratios of degree-4 products (|n|^2 ~ L^4 overflows float from L ~ 4e9): they are
  // computed on the offsets scaled exactly by a power of two that brings the longer segment to
  // about 1 (same bits where nothing overflows). Where r scaled overflows (|r| > 1e38 L), the
  // stationary point is skipped: the side candidates are then within L of it, far below the
  // rounding of r's coordinates.
  const T scale =
      detail::inversePowerOfTwo(std::max(d1.cwiseAbs().maxCoeff(), d2.cwiseAbs().maxCoeff()));
  const Vec3<T> u1 = d1 * scale, u2 = d2 * scale, ur = r * scale;
  const Vec3<T> n = u1.cross(u2);
  const T nn = n.squaredNorm();
  if (n.norm() > kGeometryTolerance<T> * u1.norm() * u2.norm()) {
    const T s = ur.cross(u2).dot(n) / nn, t = ur.cross(u1).dot(n) / nn;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) consider(s, t);
  }
  consider(T(0), detail::segmentParameter<T>(d2, first.start - second.start));
  consider(T(1), detail::segmentParameter<T>(d2, first.end - second.start));
  consider(detail::segmentParameter<T>(d1, r), T(0));
  consider(detail::segmentParameter<T>(d1, second.end - first.start), T(1));
  return {first.start + bestS * d1, second.start + bestT * d2, bestS, bestT, best};
}

}  // namespace simdphys

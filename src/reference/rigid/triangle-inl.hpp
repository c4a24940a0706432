// Manifolds of spheres and boxes against one triangle of a mesh (rigid/manifold.hpp): the
// separating axis test of box-box with the triangle as a flat, two-sided box, and the same
// clipping (box_box-inl.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "simdphys/geometry3d/point_tests.hpp"
#include "src/reference/rigid/box_box-inl.hpp"

namespace simdphys {

template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const TriangleT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  const Vec3<T> d = closestPoint(b, a.center) - a.center;
  const T dist = d.norm();
  // A centre on the triangle has no direction of its own: out along the face normal.
  if (dist > std::numeric_limits<T>::epsilon() * (1 + a.radius))
    m.normal = d / dist;
  else
    m.normal = (b.b - b.a).cross(b.c - b.a).normalized();
  detail::addContact(m, Vec3<T>(a.center + a.radius * m.normal), dist - a.radius, 0, maxSeparation);
  return m;
}

template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const TriangleT<T>& b, T maxSeparation,
                     unsigned activeEdges) {
  using namespace detail;
  // Everything is relative to the box's centre (float keeps its precision far from the origin).
  const std::array<Vec3<T>, 3> v{Vec3<T>(b.a - a.center), Vec3<T>(b.b - a.center),
                                 Vec3<T>(b.c - a.center)};
  const Vec3<T> face = (v[1] - v[0]).cross(v[2] - v[0]).normalized();
  const T size = a.halfExtents.maxCoeff();

  // The separating axis test. An axis l is oriented from the box towards the triangle, on the
  // side where they overlap least. Every axis bounds the separation; only the usable ones (the
  // face, the box's faces and active edges' crosses when the triangle has an active edge) are
  // candidates for the contact.
  struct Axis {
    T separation = -std::numeric_limits<T>::infinity();
    Vec3<T> l = Vec3<T>::UnitY();
    int i = 0, j = 0;  // the box's axis and the triangle's edge it comes from
  };
  std::array<Axis, 3> best;
  T separated = -std::numeric_limits<T>::infinity();
  const auto consider = [&](int kind, const Vec3<T>& l, int i, int j, bool usable) {
    const T p0 = l.dot(v[0]), p1 = l.dot(v[1]), p2 = l.dot(v[2]);
    const T r = projectedRadius(ObbT<T>{Vec3<T>::Zero(), a.halfExtents, a.axes}, l);
    const T above = std::min({p0, p1, p2}) - r, below = -r - std::max({p0, p1, p2});
    const T s = std::max(above, below);
    separated = std::max(separated, s);
    if (usable && s > best[std::size_t(kind)].separation)
      best[std::size_t(kind)] = {s, above >= below ? l : Vec3<T>(-l), i, j};
  };
  consider(0, face, 0, 0, true);
  for (int i = 0; i < 3; ++i) consider(1, a.axes.col(i), i, 0, true);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3<T> c = a.axes.col(i).cross(v[std::size_t((j + 1) % 3)] - v[std::size_t(j)]);
      const T norm = c.norm();
      if (norm > parallelSine<T>() * (v[std::size_t((j + 1) % 3)] - v[std::size_t(j)]).norm())
        consider(2, c / norm, i, j, (activeEdges >> j) & 1);
    }
  if (separated > maxSeparation) return {};
  const auto clearlyAbove = [&](const Axis& x, const Axis& than) {
    return x.separation > than.separation +
                              kBoxAxisRelativeTolerance<T> * std::abs(than.separation) +
                              kBoxAxisAbsoluteTolerance<T> * size;
  };
  // A box face meets the triangle's vertices nearest it (within the absolute tolerance): an
  // edge, or a vertex, which an active edge must bound; otherwise the face axis takes over.
  const auto activeFeature = [&](const Vec3<T>& l) {
    const std::array<T, 3> p{l.dot(v[0]), l.dot(v[1]), l.dot(v[2])};
    const T least = std::min({p[0], p[1], p[2]}) + kBoxAxisAbsoluteTolerance<T> * size;
    const unsigned near =
        unsigned(p[0] <= least) | unsigned(p[1] <= least) << 1 | unsigned(p[2] <= least) << 2;
    // Vertex k bounds edges k and k - 1; vertices k and k + 1 bound edge k.
    constexpr std::array<unsigned, 8> edges{0, 1 | 4, 1 | 2, 1, 2 | 4, 4, 2, 7};
    return near == 7 || (activeEdges & edges[near]) != 0;
  };
  const int kind = clearlyAbove(best[1], best[0]) && activeFeature(best[1].l) ? 1 : 0;
  ManifoldT<T> m;
  if (clearlyAbove(best[2], best[std::size_t(kind)])) {
    // Edge-edge: the box's edge along axis i farthest along the normal against triangle edge j.
    const Axis& axis = best[2];
    m.normal = axis.l;
    Vec3<T> mid = Vec3<T>::Zero();
    std::uint32_t index = std::uint32_t(4 * axis.i);
    for (int e = 0, bit = 0; e < 3; ++e) {
      if (e == axis.i) continue;
      const bool negative = a.axes.col(e).dot(m.normal) < 0;
      mid += (negative ? -a.halfExtents[e] : a.halfExtents[e]) * a.axes.col(e);
      index |= std::uint32_t(negative) << bit++;
    }
    const Vec3<T> half = a.halfExtents[axis.i] * a.axes.col(axis.i);
    const SegmentClosestPointsT<T> cp =
        closestPoints(SegmentT<T>{mid - half, mid + half},
                      SegmentT<T>{v[std::size_t(axis.j)], v[std::size_t((axis.j + 1) % 3)]});
    // Between both edges' ends only; otherwise a vertex is nearer and a face contact says more.
    if (cp.s > 0 && cp.s < 1 && cp.t > 0 && cp.t < 1) {
      // Ids past the face contacts' 12 * 64.
      m.points[0] = {Vec3<T>(a.center + T(0.5) * (cp.first + cp.second)), axis.separation,
                     768 + index * 3 + std::uint32_t(axis.j)};
      m.count = 1;
      return m;
    }
  }
  const Axis& axis = best[std::size_t(kind)];
  m.normal = axis.l;
  const T snap = kBoxClipSnap<T> * size;
  std::array<ContactPointT<T>, 8> found;
  int count = 0;
  if (kind == 0) {
    // The triangle's face is the reference: the box's face most along l (towards the triangle)
    // is clipped against the triangle's three side planes.
    std::uint32_t incFace = 0;
    ClipPolygon<T> poly = supportFace(a, Vec3<T>(Vec3<T>::Zero()), axis.l, incFace);
    for (std::uint32_t e = 0; e < 3; ++e) {
      const Vec3<T>& p = v[e];
      const Vec3<T> side = (v[(e + 1) % 3] - p).cross(face).normalized();  // outward
      poly = clip(poly, side, p, T(0), snap, 4 + e);
    }
    for (int c = 0; c < poly.n; ++c) {
      const ClipVertex<T>& x = poly.v[std::size_t(c)];
      const T s = axis.l.dot(v[0] - x.p);  // the box's point above (-) or below the triangle
      if (s <= maxSeparation)
        found[std::size_t(count++)] = {Vec3<T>(a.center + x.p + T(0.5) * s * axis.l), s,
                                       incFace * 64 + x.in * 8 + x.out};
    }
  } else {
    // The box's face is the reference: the triangle is clipped against its four side planes.
    const int k = axis.i;
    ClipPolygon<T> poly;
    poly.push({v[0], 2, 0});
    poly.push({v[1], 0, 1});
    poly.push({v[2], 1, 2});
    for (std::uint32_t s = 0; s < 4; ++s) {
      const int e = (k + 1 + int(s / 2)) % 3;
      const Vec3<T> side = (s % 2 ? T(-1) : T(1)) * a.axes.col(e);
      poly = clip(poly, side, Vec3<T>(Vec3<T>::Zero()), a.halfExtents[e], snap, 3 + s);
    }
    const std::uint32_t refFace = 6 + std::uint32_t(2 * k + (a.axes.col(k).dot(axis.l) < 0));
    for (int c = 0; c < poly.n; ++c) {
      const ClipVertex<T>& x = poly.v[std::size_t(c)];
      const T s = axis.l.dot(x.p) - a.halfExtents[k];
      if (s <= maxSeparation)
        found[std::size_t(count++)] = {Vec3<T>(a.center + x.p - T(0.5) * s * axis.l), s,
                                       refFace * 64 + x.in * 8 + x.out};
    }
  }
  keepFourOf(m, found, count);
  return m;
}

}  // namespace simdphys

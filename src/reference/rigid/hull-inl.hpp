// Manifolds of convex hulls (rigid/hull.hpp) against every shape of the rigid bodies: GJK (apart,
// within the speculative distance) or EPA (overlapping) finds the nearest features, the separating
// axis test over both shapes' faces chooses a face as box-box chooses its axis, and the other
// shape's face is clipped against it as box-box clips (Jolt's ManifoldBetweenTwoFaces); an edge or
// vertex contact is GJK's or EPA's single point.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "simdphys/geometry3d/epa.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "src/reference/rigid/clip-inl.hpp"
#include "src/reference/rigid/manifold-inl.hpp"

namespace simdphys::detail {

// A face as the clipping needs it: its polygon in the world, outward normal and index.
template <class T>
struct Face {
  std::array<Vec3<T>, HullShape::kMaxFaceVertices> v;
  int n = 0;
  Vec3<T> normal;
  std::uint32_t index = 0;
};

// The world's copy of a hull's vertices, for GJK and EPA's support function.
template <class T>
struct WorldHull {
  std::array<Vec3<T>, HullShape::kMaxVertices> v;
  int n = 0;
  explicit WorldHull(const PlacedHullT<T>& h) : n(int(h.shape->vertices().size())) {
    for (int i = 0; i < n; ++i)
      v[std::size_t(i)] =
          h.center + h.axes * h.shape->vertices()[std::size_t(i)].template cast<T>();
  }
  ConvexHullT<T> view() const { return {std::span<const Vec3<T>>(v.data(), std::size_t(n))}; }
};

// The face of each shape whose outward normal is nearest `d` (a triangle's side facing it).
template <class T>
Face<T> faceToward(const PlacedHullT<T>& h, const Vec3<T>& d) {
  const HullShape& s = *h.shape;
  const Vec3f local = (h.axes.transpose() * d).template cast<float>();
  int best = 0;
  for (int f = 1; f < s.faceCount(); ++f)
    if (s.faceNormal(f).dot(local) > s.faceNormal(best).dot(local)) best = f;
  Face<T> face;
  face.index = std::uint32_t(best);
  face.normal = h.axes * s.faceNormal(best).template cast<T>();
  for (const std::uint8_t i : s.face(best))
    face.v[std::size_t(face.n++)] = h.center + h.axes * s.vertices()[i].template cast<T>();
  return face;
}

template <class T>
Face<T> faceToward(const ObbT<T>& b, const Vec3<T>& d) {
  const Vec3<T> local = b.axes.transpose() * d;
  int k = 0;
  local.cwiseAbs().maxCoeff(&k);
  const T sign = local[k] < 0 ? T(-1) : T(1);
  const Vec3<T> c = b.center + sign * b.halfExtents[k] * b.axes.col(k);
  const Vec3<T> u = b.halfExtents[(k + 1) % 3] * b.axes.col((k + 1) % 3);
  const Vec3<T> v = sign * b.halfExtents[(k + 2) % 3] * b.axes.col((k + 2) % 3);
  Face<T> face;
  face.index = std::uint32_t(2 * k + (sign < 0));
  face.normal = sign * b.axes.col(k);
  face.v = {c + u + v, c - u + v, c - u - v, c + u - v};  // counter-clockwise about the normal
  face.n = 4;
  return face;
}

template <class T>
Face<T> faceToward(const TriangleT<T>& t, const Vec3<T>& d) {
  Face<T> face;
  face.normal = t.normal().normalized();
  face.n = 3;
  if (face.normal.dot(d) >= 0)
    face.v[0] = t.a, face.v[1] = t.b, face.v[2] = t.c;
  else
    face.normal = -face.normal, face.v[0] = t.a, face.v[1] = t.c, face.v[2] = t.b;
  return face;
}

// The outward normals of a shape's faces, for the separating axis test over them.
template <class T, class F>
void forEachFaceNormal(const PlacedHullT<T>& h, F f) {
  for (int k = 0; k < h.shape->faceCount(); ++k)
    f(Vec3<T>(h.axes * h.shape->faceNormal(k).template cast<T>()));
}
template <class T, class F>
void forEachFaceNormal(const ObbT<T>& b, F f) {
  for (int k = 0; k < 3; ++k) f(Vec3<T>(b.axes.col(k))), f(Vec3<T>(-b.axes.col(k)));
}
template <class T, class F>
void forEachFaceNormal(const TriangleT<T>& t, F f) {
  const Vec3<T> n = t.normal().normalized();
  f(n), f(Vec3<T>(-n));
}

// The face of `faces` whose separating axis separates its shape (`self`, as GJK sees it) most
// from `other` (the first of equals, as box-box takes its axes), and that separation.
template <class T, class F, class S, class O>
std::pair<Vec3<T>, T> bestFaceAxis(const F& faces, const S& self, const O& other) {
  std::pair<Vec3<T>, T> best{Vec3<T>::UnitY(), -std::numeric_limits<T>::infinity()};
  forEachFaceNormal(faces, [&](const Vec3<T>& n) {
    const T s = n.dot(support(other, Vec3<T>(-n)) - support(self, n));
    if (s > best.second) best = {n, s};
  });
  return best;
}

// The points of a face contact: the incident face clipped against the reference face's sides,
// each point left measured along the reference face's normal to its plane, those within
// maxSeparation kept. Ids: the faces and the clipped polygon's edge labels (clip-inl.hpp), or, for
// a mesh (`small`), below 1024.
template <class T, std::size_t N>
int clipFaces(const Face<T>& ref, const Face<T>& inc, bool refIsB, T maxSeparation, T snap,
              bool small, std::array<ContactPointT<T>, N>& out) {
  ClipPolygon<T, 2 * HullShape::kMaxFaceVertices> poly;
  for (int k = 0; k < inc.n; ++k)
    poly.push({inc.v[std::size_t(k)], std::uint32_t((k + inc.n - 1) % inc.n), std::uint32_t(k)});
  Vec3<T> mid = Vec3<T>::Zero();
  for (int k = 0; k < ref.n; ++k) mid += ref.v[std::size_t(k)];
  mid /= T(ref.n);
  for (int k = 0; k < ref.n && poly.n > 0; ++k) {
    const Vec3<T>& p = ref.v[std::size_t(k)];
    Vec3<T> side = (ref.v[std::size_t((k + 1) % ref.n)] - p).cross(ref.normal).normalized();
    if (side.dot(mid - p) > 0) side = -side;  // outward, whichever way the face winds
    poly = clip(poly, side, p, T(0), snap, std::uint32_t(HullShape::kMaxFaceVertices + k));
  }
  const Vec3<T> n = refIsB ? Vec3<T>(-ref.normal) : ref.normal;  // from A to B
  const T offset = ref.normal.dot(ref.v[0]);
  const std::uint32_t faces = (ref.index * 2654435761u ^ inc.index * 40503u ^ std::uint32_t(refIsB))
                              << 16;
  int count = 0;
  for (int k = 0; k < poly.n && count < int(N); ++k) {
    const ClipVertex<T>& c = poly.v[std::size_t(k)];
    const T t = ref.normal.dot(c.p) - offset;
    if (t > maxSeparation) continue;
    const Vec3<T> onA = refIsB ? c.p : Vec3<T>(c.p - t * n);
    const Vec3<T> point = onA + T(0.5) * t * n;
    // A point within 10 snaps of one kept is the same contact (an edge-on clip doubles corners
    // by rounding): kept once, as the solver would otherwise push there twice.
    const bool known = std::any_of(out.begin(), out.begin() + count, [&](const auto& q) {
      return (q.point - point).squaredNorm() <= T(100) * snap * snap;
    });
    if (known) continue;
    const std::uint32_t id = small ? (c.out & 0x7F) | ((c.in & 7) << 7) : faces | c.in << 8 | c.out;
    out[std::size_t(count++)] = {point, t, id};
  }
  return count;
}

// Where two shapes are nearest: the normal (A to B), their separation along it and the points
// of A and B, by GJK, or by EPA where they overlap. Empty if apart by more than maxSeparation.
template <class T>
struct Nearest {
  Vec3<T> n, onA, onB;
  T separation;
};
template <class T, class A, class B>
std::optional<Nearest<T>> nearest(const A& a, const B& b, T maxSeparation) {
  const GjkResultT<T> g = gjkDistance(a, b);
  if (!g.intersecting) {
    if (g.distance > maxSeparation) return std::nullopt;
    return Nearest<T>{(g.pointB - g.pointA) / g.distance, g.pointA, g.pointB, g.distance};
  }
  const auto p = epa(a, b);
  if (!p) return std::nullopt;
  return Nearest<T>{p->normal, p->pointA, p->pointB, -p->depth};
}

// The manifold of a hull A (its world vertices `worldA`) against a polytope B (a hull, its world
// vertices `shapeB`; a box; a triangle) nearest as `near` says. `forceB`: B's face facing A along
// near.n is the reference, whatever the faces' separations (a mesh's inactive edge).
template <class T, class B, class SB>
ManifoldT<T> faceContact(const PlacedHullT<T>& a, const ConvexHullT<T>& worldA, const B& b,
                         const SB& shapeB, const Nearest<T>& near, T maxSeparation, T size,
                         bool small, bool forceB) {
  ManifoldT<T> m;
  m.normal = near.n;
  // The separating axis test over both shapes' faces, each face's separation how far the other
  // shape's deepest point lies outside its plane; B's face taken over A's, and either over the
  // edge contact `near` is, only when clearly better (box-box's rule and tolerances).
  const auto [normalA, sepA] = bestFaceAxis<T>(a, worldA, shapeB);
  const auto [normalB, sepB] = bestFaceAxis<T>(b, shapeB, worldA);
  const auto clearlyAbove = [&](T x, T than) {
    return x > than + kBoxAxisRelativeTolerance<T> * std::abs(than) +
                   kBoxAxisAbsoluteTolerance<T> * size;
  };
  const bool faceOfB = forceB || clearlyAbove(sepB, sepA);
  const bool edge = !forceB && clearlyAbove(near.separation, faceOfB ? sepB : sepA);
  std::array<ContactPointT<T>, 2 * HullShape::kMaxFaceVertices> points;
  const T snap = kBoxClipSnap<T> * size;
  int n = 0;
  if (!edge) {
    // The reference face, and the other shape's face most against it, clipped.
    const Face<T> ref =
        faceOfB ? faceToward(b, forceB ? Vec3<T>(-near.n) : normalB) : faceToward(a, normalA);
    const Face<T> inc =
        faceOfB ? faceToward(a, Vec3<T>(-ref.normal)) : faceToward(b, Vec3<T>(-ref.normal));
    m.normal = faceOfB ? Vec3<T>(-ref.normal) : ref.normal;
    n = clipFaces(ref, inc, faceOfB, maxSeparation, snap, small, points);
    // Apart, with a face as the contact's axis but no point of the other face over it: no
    // speculative contact, as box-box finds none there. GJK's single point would do, but its
    // normal is then ill-defined (edges barely apart: any of a range of directions), and a
    // normal that turns from step to step carries warm-started friction sideways: a W5 pyramid
    // of hull cubes crept 0.5 m in 10 s with it, and holds to 5 mm without.
    if (n == 0 && near.separation > 0) return {};
  }
  if (n == 0) {  // an edge or vertex contact: GJK's or EPA's point, along its own normal
    m.normal = near.n;
    addContact(m, near.onA, near.separation, small ? 1023u : 0xFFFFu, maxSeparation);
    return m;
  }
  keepFourOf(m, points, n);
  return m;
}

}  // namespace simdphys::detail

namespace simdphys {

template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const SphereT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  const detail::WorldHull<T> world(a);
  if (const auto near = detail::nearest(world.view(), b, maxSeparation)) {
    m.normal = near->n;
    detail::addContact(m, near->onA, near->separation, 0, maxSeparation);
  }
  return m;
}

template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const ObbT<T>& b, T maxSeparation) {
  const detail::WorldHull<T> world(a);
  const auto near = detail::nearest(world.view(), b, maxSeparation);
  if (!near) return {};
  const T size = std::min(T(a.shape->halfExtents().maxCoeff()), b.halfExtents.maxCoeff());
  return detail::faceContact(a, world.view(), b, b, *near, maxSeparation, size, false, false);
}

template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const PlacedHullT<T>& b, T maxSeparation) {
  const detail::WorldHull<T> worldA(a), worldB(b);
  const auto near = detail::nearest(worldA.view(), worldB.view(), maxSeparation);
  if (!near) return {};
  const T size = T(std::min(a.shape->halfExtents().maxCoeff(), b.shape->halfExtents().maxCoeff()));
  return detail::faceContact(a, worldA.view(), b, worldB.view(), *near, maxSeparation, size, false,
                             false);
}

template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const PlaneT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  m.normal = -b.normal;  // the plane's solid is behind it
  std::array<ContactPointT<T>, HullShape::kMaxVertices> points;
  int n = 0;
  const T centre = b.signedDistance(a.center);
  for (std::size_t v = 0; v < a.shape->vertices().size(); ++v) {
    const Vec3<T> offset = a.axes * a.shape->vertices()[v].template cast<T>();
    const T s = centre + b.normal.dot(offset);  // from the centre's distance, as box-plane
    if (s <= maxSeparation)
      points[std::size_t(n++)] = {Vec3<T>(a.center + offset - T(0.5) * s * b.normal), s,
                                  std::uint32_t(v)};
  }
  detail::keepFourOf(m, points, n);
  return m;
}

template <class T>
ManifoldT<T> collide(const PlacedHullT<T>& a, const TriangleT<T>& b, T maxSeparation,
                     unsigned activeEdges) {
  const detail::WorldHull<T> world(a);
  auto near = detail::nearest(world.view(), b, maxSeparation);
  if (!near) return {};
  // The triangle's feature nearest A: the edges B's point lies on. Only an active one may give
  // its own normal (Jolt's active edges); else the face's, with A's deepest point along it.
  const std::array<Vec3<T>, 3> v{b.a, b.b, b.c};
  const Vec3<T> face = b.normal().normalized();
  const T size = T(a.shape->halfExtents().maxCoeff());
  bool forced = false;
  if (std::abs(face.dot(near->n)) <= T(1 - 1e-4)) {
    bool active = false;
    for (int e = 0; e < 3; ++e) {
      const Vec3<T>& p = v[std::size_t(e)];
      const Vec3<T>& q = v[std::size_t((e + 1) % 3)];
      const T along = (near->onB - p).dot(q - p) / (q - p).squaredNorm();
      const T off = (near->onB - p - along * (q - p)).norm();
      if (off <= T(1e-3) * size && (activeEdges >> e) & 1) active = true;
    }
    if (!active) {
      forced = true;
      // From the hull to the triangle: towards the side of the plane the hull's centre is not.
      near->n = face.dot(a.center - b.a) > 0 ? Vec3<T>(-face) : face;
      near->onA = support(world.view(), near->n);
      near->separation = -near->n.dot(near->onA - b.a);
      if (near->separation > maxSeparation) return {};
    }
  }
  return detail::faceContact(a, world.view(), b, b, *near, maxSeparation, size, true, forced);
}

}  // namespace simdphys

// Box-box manifolds (rigid/manifold.hpp): the separating axis test over the 15 axes, then a face
// contact (the incident face clipped against the reference face's side planes, at most four
// points kept) or an edge contact (one point between the two edges' closest points). As in
// box2d-lite's Collide.cpp, qu3e's q3BoxtoBox and Jolt's ManifoldBetweenTwoFaces.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "simdphys/geometry3d/point_tests.hpp"
#include "src/reference/rigid/clip-inl.hpp"
#include "src/reference/rigid/manifold-inl.hpp"

namespace simdphys::detail {

// Edge pairs whose sine of angle is below this give no axis: their cross product's direction is
// rounding noise there (its error is about eps / sine), and the face axes bound the separation
// on it to within sine times the boxes' size. sqrt(eps) balances the two.
template <class T>
T parallelSine() {
  return std::sqrt(std::numeric_limits<T>::epsilon());
}

// Half the extent of a box along the unit axis l.
template <class T>
T projectedRadius(const ObbT<T>& box, const Vec3<T>& l) {
  return (box.axes.transpose() * l).cwiseAbs().dot(box.halfExtents);
}

// The face of `box` (centred at `centre`) whose outward normal is most along `dir`, as a clip
// polygon of its four corners (corner c lies between the edges c - 1 and c); `face` receives its
// index, 2 k for the face along +axis k and 2 k + 1 for -axis k.
template <class T>
ClipPolygon<T> supportFace(const ObbT<T>& box, const Vec3<T>& centre, const Vec3<T>& dir,
                           std::uint32_t& face) {
  const Vec3<T> inBox = box.axes.transpose() * dir;
  int k = 0;
  inBox.cwiseAbs().maxCoeff(&k);
  const bool negative = inBox[k] < 0;
  face = std::uint32_t(2 * k + negative);
  const Vec3<T> c =
      centre + (negative ? -box.halfExtents[k] : box.halfExtents[k]) * box.axes.col(k);
  const Vec3<T> u = box.halfExtents[(k + 1) % 3] * box.axes.col((k + 1) % 3);
  const Vec3<T> v = box.halfExtents[(k + 2) % 3] * box.axes.col((k + 2) % 3);
  ClipPolygon<T> poly;
  poly.push({c + u + v, 3, 0});
  poly.push({c - u + v, 0, 1});
  poly.push({c - u - v, 1, 2});
  poly.push({c + u - v, 2, 3});
  return poly;
}

}  // namespace simdphys::detail

namespace simdphys {

template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const ObbT<T>& b, T maxSeparation) {
  using namespace detail;
  // Everything is relative to A's centre (float keeps its precision far from the origin).
  const Vec3<T> d = b.center - a.center;
  const T size = std::min(a.halfExtents.maxCoeff(), b.halfExtents.maxCoeff());

  // The separating axis test: the best axis of each kind (A's faces, B's faces, edge pairs), in
  // A's frame (Gottschalk's OBBTree test, Ericson 4.4.1): R holds B's axes, t B's centre, so each
  // axis's separation is a few products of their entries rather than projections of both boxes.
  // R's rows and columns are orthonormal to the boxes' validation (64 eps), which the edge
  // axes' closed forms rely on.
  struct Axis {
    T separation = -std::numeric_limits<T>::infinity();
    Vec3<T> l = Vec3<T>::UnitX();
    int i = 0, j = 0;  // the axes of A and of B it comes from
  };
  std::array<Axis, 3> best;
  const auto consider = [&](int kind, T s, int i, int j) {
    if (s > best[std::size_t(kind)].separation)
      best[std::size_t(kind)] = {s, Vec3<T>::UnitX(), i, j};
  };
  const Mat3<T> R = a.axes.transpose() * b.axes, absR = R.cwiseAbs();
  const Vec3<T> t = a.axes.transpose() * d;
  const Vec3<T>&ha = a.halfExtents, &hb = b.halfExtents;
  for (int i = 0; i < 3; ++i) consider(0, std::abs(t[i]) - ha[i] - absR.row(i).dot(hb), i, 0);
  for (int j = 0; j < 3; ++j)
    consider(1, std::abs(t.dot(R.col(j))) - absR.col(j).dot(ha) - hb[j], 0, j);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // The axis A_i x B_j is (0, -R(i2, j), R(i1, j)) in A's frame, up to the order of its
      // entries; its length is the sine of the edges' angle.
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const T sine = std::sqrt(R(i1, j) * R(i1, j) + R(i2, j) * R(i2, j));
      if (!(sine > parallelSine<T>())) continue;
      const T ra = ha[i1] * absR(i2, j) + ha[i2] * absR(i1, j);
      const T rb = hb[j1] * absR(i, j2) + hb[j2] * absR(i, j1);
      consider(2, (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) - ra - rb) / sine, i, j);
    }
  best[0].l = a.axes.col(best[0].i);
  best[1].l = b.axes.col(best[1].j);
  if (best[2].separation > -std::numeric_limits<T>::infinity())  // some edge pair not parallel
    best[2].l = a.axes.col(best[2].i).cross(b.axes.col(best[2].j)).normalized();
  if (std::max({best[0].separation, best[1].separation, best[2].separation}) > maxSeparation)
    return {};
  const auto clearlyAbove = [&](const Axis& x, const Axis& than) {
    return x.separation > than.separation +
                              kBoxAxisRelativeTolerance<T> * std::abs(than.separation) +
                              kBoxAxisAbsoluteTolerance<T> * size;
  };
  const int face = clearlyAbove(best[1], best[0]) ? 1 : 0;
  ManifoldT<T> m;
  if (clearlyAbove(best[2], best[std::size_t(face)])) {
    // Edge-edge: A's edge along axis i farthest along the normal, B's along j farthest against
    // it; an edge's index is its axis and the sides it lies on along the other two.
    const Axis& axis = best[2];
    m.normal = axis.l.dot(d) < 0 ? Vec3<T>(-axis.l) : axis.l;
    const auto supportEdge = [](const ObbT<T>& box, const Vec3<T>& centre, const Vec3<T>& dir,
                                int k, std::uint32_t& index) {
      Vec3<T> mid = centre;
      index = std::uint32_t(4 * k);
      for (int e = 0, bit = 0; e < 3; ++e) {
        if (e == k) continue;
        const bool negative = box.axes.col(e).dot(dir) < 0;
        mid += (negative ? -box.halfExtents[e] : box.halfExtents[e]) * box.axes.col(e);
        index |= std::uint32_t(negative) << bit++;
      }
      const Vec3<T> half = box.halfExtents[k] * box.axes.col(k);
      return SegmentT<T>{mid - half, mid + half};
    };
    std::uint32_t ea = 0, eb = 0;
    const SegmentT<T> edgeA = supportEdge(a, Vec3<T>::Zero(), m.normal, axis.i, ea);
    const SegmentT<T> edgeB = supportEdge(b, d, Vec3<T>(-m.normal), axis.j, eb);
    const SegmentClosestPointsT<T> cp = closestPoints(edgeA, edgeB);
    // Only when the closest points lie between the edges' ends (they then differ by the
    // separation along the normal); otherwise a vertex is nearer than the edges (apart boxes,
    // whose SAT separation only bounds their distance) and a face contact describes it.
    if (cp.s > 0 && cp.s < 1 && cp.t > 0 && cp.t < 1) {
      // Ids past the face contacts' 2 * 6 * 6 * 64.
      m.points[0] = {Vec3<T>(a.center + T(0.5) * (cp.first + cp.second)), axis.separation,
                     4608 + ea * 12 + eb};
      m.count = 1;
      return m;
    }
  }
  const Axis& axis = best[std::size_t(face)];
  m.normal = axis.l.dot(d) < 0 ? Vec3<T>(-axis.l) : axis.l;

  // Face contact: the reference face is the chosen axis's, n its outward normal (towards the
  // other box); the incident face is the other box's face most anti-parallel to n.
  const bool refIsA = face == 0;
  const ObbT<T>& ref = refIsA ? a : b;
  const ObbT<T>& inc = refIsA ? b : a;
  const Vec3<T> refCentre = refIsA ? Vec3<T>::Zero() : d, incCentre = refIsA ? d : Vec3<T>::Zero();
  const int k = refIsA ? axis.i : axis.j;
  const Vec3<T> n = refIsA ? m.normal : Vec3<T>(-m.normal);
  const std::uint32_t refFace = std::uint32_t(2 * k + (ref.axes.col(k).dot(n) < 0));
  std::uint32_t incFace = 0;  // the incident face: its outward normal most against n
  ClipPolygon<T> poly = supportFace(inc, incCentre, Vec3<T>(-n), incFace);
  for (std::uint32_t s = 0; s < 4; ++s) {
    const int e = (k + 1 + int(s / 2)) % 3;
    const Vec3<T> side = (s % 2 ? T(-1) : T(1)) * ref.axes.col(e);
    poly = clip(poly, side, refCentre, ref.halfExtents[e], kBoxClipSnap<T> * size, 4 + s);
  }

  // The clipped points within reach, on the incident face; the manifold's point is midway
  // between one and its projection on the reference face.
  std::array<ContactPointT<T>, 8> found;
  int count = 0;
  const std::uint32_t faces = ((refIsA ? 0 : 6) + refFace) * 6 + incFace;
  for (int c = 0; c < poly.n; ++c) {
    const ClipVertex<T>& x = poly.v[std::size_t(c)];
    const T s = n.dot(x.p - refCentre) - ref.halfExtents[k];
    if (s <= maxSeparation)
      found[std::size_t(count++)] = {Vec3<T>(a.center + x.p - T(0.5) * s * n), s,
                                     faces * 64 + x.in * 8 + x.out};
  }
  keepFourOf(m, found, count);
  return m;
}

}  // namespace simdphys

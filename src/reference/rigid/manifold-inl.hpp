// Manifolds of spheres and of shapes against planes (rigid/manifold.hpp); box-box is
// box_box-inl.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "simdphys/rigid/manifold.hpp"

namespace simdphys::detail {

// Adds a point of A's surface `onA` with its separation along the manifold's normal, if within
// maxSeparation.
template <class T>
void addContact(ManifoldT<T>& m, const Vec3<T>& onA, T separation, std::uint32_t id,
                T maxSeparation) {
  if (separation > maxSeparation || m.count == ManifoldT<T>::kMaxPoints) return;
  m.points[std::size_t(m.count++)] = {onA + T(0.5) * separation * m.normal, separation, id};
}

}  // namespace simdphys::detail

namespace simdphys {

template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const SphereT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  const Vec3<T> d = b.center - a.center;
  const T dist = d.norm();
  // Concentric spheres have no direction of their own: push along +y, as any would do.
  m.normal = dist > std::numeric_limits<T>::min() ? Vec3<T>(d / dist) : Vec3<T>::UnitY();
  detail::addContact(m, Vec3<T>(a.center + a.radius * m.normal), dist - a.radius - b.radius, 0,
                     maxSeparation);
  return m;
}

template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const ObbT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  const Vec3<T> p = b.axes.transpose() * (a.center - b.center);
  const Vec3<T> q = p.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents);
  // The region of the box the centre lies in names the feature: 3 states an axis.
  std::uint32_t id = 0;
  for (int k = 0; k < 3; ++k)
    id = id * 3 + (p[k] < -b.halfExtents[k] ? 1u : p[k] > b.halfExtents[k] ? 2u : 0u);
  T separation;
  if (id == 0) {
    // The centre is inside: out through the nearest face.
    int k = 0;
    T least = b.halfExtents[0] - std::abs(p[0]);
    for (int j = 1; j < 3; ++j)
      if (b.halfExtents[j] - std::abs(p[j]) < least)
        least = b.halfExtents[j] - std::abs(p[j]), k = j;
    m.normal = -(p[k] < 0 ? T(-1) : T(1)) * Vec3<T>(b.axes.col(k));
    separation = -least - a.radius;
    id = 27 + 2 * std::uint32_t(k) + (p[k] < 0 ? 1u : 0u);  // which face, not only which axis
  } else {
    const Vec3<T> d = p - q;  // from the box's surface to the centre, in the box's frame
    const T dist = d.norm();
    m.normal = -(b.axes * d) / dist;
    separation = dist - a.radius;
  }
  detail::addContact(m, Vec3<T>(a.center + a.radius * m.normal), separation, id, maxSeparation);
  return m;
}

template <class T>
ManifoldT<T> collide(const SphereT<T>& a, const PlaneT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  m.normal = -b.normal;  // the plane's solid is behind it
  detail::addContact(m, Vec3<T>(a.center - a.radius * b.normal),
                     b.signedDistance(a.center) - a.radius, 0, maxSeparation);
  return m;
}

template <class T>
ManifoldT<T> collide(const ObbT<T>& a, const PlaneT<T>& b, T maxSeparation) {
  ManifoldT<T> m;
  m.normal = -b.normal;
  // The deepest four vertices within reach, deepest first: a box meets a plane with at most four
  // at once (a face), more only when all of it is within maxSeparation, and then its lowest face
  // counts. (Chosen by selection: std::sort on the 8 made GCC 12 warn of bounds it never reaches.)
  std::array<Vec3<T>, 8> corner;
  std::array<T, 8> s;
  const T centre = b.signedDistance(a.center);
  for (std::size_t v = 0; v < 8; ++v) {
    const Vec3<T> offset = a.axes * Vec3<T>((v & 1) ? a.halfExtents.x() : -a.halfExtents.x(),
                                            (v & 2) ? a.halfExtents.y() : -a.halfExtents.y(),
                                            (v & 4) ? a.halfExtents.z() : -a.halfExtents.z());
    corner[v] = a.center + offset;
    s[v] = centre + b.normal.dot(offset);  // from the centre's distance: no cancellation far out
  }
  std::array<bool, 8> taken{};
  for (int i = 0; i < ManifoldT<T>::kMaxPoints; ++i) {
    std::size_t v = 0;
    while (taken[v]) ++v;
    for (std::size_t w = v + 1; w < 8; ++w)
      if (!taken[w] && s[w] < s[v]) v = w;
    taken[v] = true;
    detail::addContact(m, corner[v], s[v], std::uint32_t(v), maxSeparation);
  }
  return m;
}

}  // namespace simdphys

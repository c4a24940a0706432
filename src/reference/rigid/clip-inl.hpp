// Polygon clipping and point reduction for face contacts (box_box-inl.hpp, triangle-inl.hpp) and
// for merging a mesh's manifolds (narrowphase-inl.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "simdphys/rigid/manifold.hpp"

namespace simdphys::detail {

// A vertex of the clipped incident face, with the labels of the polygon's edges into and out of
// it: 0-3 the incident face's edges, 4-7 the reference face's side planes. The pair names what
// the point is (an incident corner, an incident edge through a side plane, a reference corner),
// the same from frame to frame; the out label alone differs between the vertices of a convex
// polygon, so the pair is unique within it.
template <class T>
struct ClipVertex {
  Vec3<T> p;
  std::uint32_t in, out;
};
// Capacity N: a box's face has 4 corners and each of its 4 clips adds at most one; a hull's
// faces have at most 64 (rigid/hull.hpp).
template <class T, std::size_t N = 8>
struct ClipPolygon {
  std::array<ClipVertex<T>, N> v;
  int n = 0;
  void push(const ClipVertex<T>& x) {
    if (n < int(v.size())) v[std::size_t(n++)] = x;
  }
};

// Sutherland-Hodgman: the part of `poly` where side.(p - origin) <= h; the new vertices, where an
// edge crosses the plane, take `label` for the part of the polygon that now runs along it. A
// vertex within `snap` of the plane counts as on it: kept as itself, never doubled by a crossing
// point next to it (flush faces of a stack then keep their corners' ids through rounding).
template <class T, std::size_t N>
ClipPolygon<T, N> clip(const ClipPolygon<T, N>& poly, const Vec3<T>& side, const Vec3<T>& origin,
                       T h, T snap, std::uint32_t label) {
  ClipPolygon<T, N> out;
  for (int k = 0; k < poly.n; ++k) {
    const ClipVertex<T>& p = poly.v[std::size_t(k)];
    const ClipVertex<T>& q = poly.v[std::size_t((k + 1) % poly.n)];
    const T dp = side.dot(p.p - origin) - h, dq = side.dot(q.p - origin) - h;
    if (dp <= snap) out.push(p);
    if ((dp < -snap && dq > snap) || (dp > snap && dq < -snap)) {
      const Vec3<T> x = p.p + (dp / (dp - dq)) * (q.p - p.p);
      out.push(dp < 0 ? ClipVertex<T>{x, p.out, label} : ClipVertex<T>{x, label, p.out});
    }
  }
  return out;
}

// The indices of at most four of the n points to keep, in the order picked (Jolt's
// PruneContactPoints, Box2D): the deepest, the farthest from it, the one spanning the largest
// triangle with those two, and the one adding the most area outside that triangle.
template <class T, std::size_t N>
int keepFour(const std::array<ContactPointT<T>, N>& c, int n, const Vec3<T>& normal,
             std::array<int, 4>& keep) {
  if (n <= 4) {
    for (int i = 0; i < n; ++i) keep[std::size_t(i)] = i;
    return n;
  }
  std::array<bool, N> taken{};
  const auto pick = [&](auto score) {
    int best = -1;
    T bestScore = -std::numeric_limits<T>::infinity();
    for (int i = 0; i < n; ++i)
      if (!taken[std::size_t(i)] && (best < 0 || score(c[std::size_t(i)].point) > bestScore))
        best = i, bestScore = score(c[std::size_t(i)].point);
    taken[std::size_t(best)] = true;
    return best;
  };
  const auto at = [&](int k) { return c[std::size_t(keep[std::size_t(k)])].point; };
  keep[0] = 0;
  for (int i = 1; i < n; ++i)
    if (c[std::size_t(i)].separation < c[std::size_t(keep[0])].separation) keep[0] = i;
  taken[std::size_t(keep[0])] = true;
  keep[1] = pick([&](const Vec3<T>& p) { return (p - at(0)).squaredNorm(); });
  const auto area = [&](const Vec3<T>& p, const Vec3<T>& q, const Vec3<T>& r) {
    return normal.dot((q - p).cross(r - p));  // twice the signed area, seen along the normal
  };
  keep[2] = pick([&](const Vec3<T>& p) { return std::abs(area(at(0), at(1), p)); });
  const T orient = area(at(0), at(1), at(2)) < 0 ? T(-1) : T(1);
  keep[3] = pick([&](const Vec3<T>& p) {
    const T outside0 = -orient * area(at(0), at(1), p), outside1 = -orient * area(at(1), at(2), p);
    return std::max({outside0, outside1, -orient * area(at(2), at(0), p)});
  });
  return 4;
}

// The manifold's points: at most four of the n in c (keepFour's), along its normal.
template <class T, std::size_t N>
void keepFourOf(ManifoldT<T>& m, const std::array<ContactPointT<T>, N>& c, int n) {
  std::array<int, 4> keep{};
  m.count = keepFour(c, n, m.normal, keep);
  for (int j = 0; j < m.count; ++j) m.points[std::size_t(j)] = c[std::size_t(keep[std::size_t(j)])];
}

}  // namespace simdphys::detail

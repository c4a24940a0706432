// The definitions of simdphys/geometry2d/collisions.hpp (2D shape-versus-shape tests and contact
// manifolds): included by collisions.cpp, which instantiates them for float and double, and by any
// file of src/ that wants them inlined.
#pragma once

#include "simdphys/geometry2d/collisions.hpp"
#include "src/reference/geometry2d/point_tests-inl.hpp"

namespace simdphys {

template <class T>
Manifold2T<T> flipped(Manifold2T<T> m) {
  m.normal = -m.normal;
  return m;
}

namespace detail::g2 {

// Lexicographic order on a shape's fields, so that same-type pairs compute in one order.
template <class T>
bool before(const CircleT<T>& a, const CircleT<T>& b) {
  return std::array<T, 3>{a.center.x(), a.center.y(), a.radius} <
         std::array<T, 3>{b.center.x(), b.center.y(), b.radius};
}

template <class T>
bool before(const RectT<T>& a, const RectT<T>& b) {
  return std::array<T, 4>{a.min.x(), a.min.y(), a.max.x(), a.max.y()} <
         std::array<T, 4>{b.min.x(), b.min.y(), b.max.x(), b.max.y()};
}

template <class T>
bool before(const OrientedRectT<T>& a, const OrientedRectT<T>& b) {
  return std::array<T, 5>{a.center.x(), a.center.y(), a.halfExtents.x(), a.halfExtents.y(),
                          a.rotation} < std::array<T, 5>{b.center.x(), b.center.y(),
                                                         b.halfExtents.x(), b.halfExtents.y(),
                                                         b.rotation};
}

// A rectangle in a frame whose origin is some point of the scene (its center is relative to it):
// center, axes (columns, unit), half extents.
template <class T>
struct Box {
  Vec2<T> center;
  Mat2<T> axes;
  Vec2<T> half;
};

template <class T>
Box<T> boxOf(const OrientedRectT<T>& b, const Vec2<T>& origin) {
  return {b.center - origin, b.axes(), b.halfExtents};
}

template <class T>
Box<T> boxOf(const RectT<T>& r, const Vec2<T>& origin) {
  return {((r.min - origin) + (r.max - origin)) / T(2), Mat2<T>::Identity(),
          (r.max - r.min) / T(2)};
}

// Half the length of the box's projection on the unit axis u.
template <class T>
T projectedRadius(const Box<T>& b, const Vec2<T>& u) {
  return b.half.x() * std::abs(b.axes.col(0).dot(u)) + b.half.y() * std::abs(b.axes.col(1).dot(u));
}

// The SAT's scale: the rounding of every separation below is a few eps of the offset between the
// centers plus the half extents.
template <class T>
T boxScale(const Box<T>& a, const Box<T>& b) {
  return (b.center - a.center).norm() + (a.half.sum() + b.half.sum());
}

// The face of `ref` that separates `other` the most: for each axis u of ref, the face facing
// other (sign of d.u, + on a tie) and its separation |d.u| - (ref half extent + other's projected
// radius), d = other.center - ref.center. Positive: a separating axis. Ties keep axis 0.
template <class T>
struct FaceSeparation {
  T separation;
  int axis;
  T sign;
};

template <class T>
FaceSeparation<T> maxSeparation(const Box<T>& ref, const Box<T>& other) {
  const Vec2<T> d = other.center - ref.center;
  FaceSeparation<T> best{-std::numeric_limits<T>::infinity(), 0, T(1)};
  for (int i = 0; i < 2; ++i) {
    const Vec2<T> u = ref.axes.col(i);
    const T along = d.dot(u);
    const T separation = std::abs(along) - (ref.half[i] + projectedRadius(other, u));
    if (separation > best.separation) best = {separation, i, along >= 0 ? T(1) : T(-1)};
  }
  return best;
}

// SAT on the four face normals, closed within kGeometry2dTolerance * boxScale.
template <class T>
bool boxesIntersect(const Box<T>& a, const Box<T>& b) {
  const T slack = kGeometry2dTolerance<T> * boxScale(a, b);
  return maxSeparation(a, b).separation <= slack && maxSeparation(b, a).separation <= slack;
}

// Keeps the part of the polyline `in` (0 to 2 points) where side.w <= offset (Sutherland-Hodgman
// on one line, as Box2D's b2ClipSegmentToLine).
template <class T>
int clipToSide(const std::array<Vec2<T>, 2>& in, int count, std::array<Vec2<T>, 2>& out,
               const Vec2<T>& side, T offset) {
  int n = 0;
  if (count == 0) return 0;
  const T d0 = side.dot(in[0]) - offset;
  if (d0 <= 0) out[n++] = in[0];
  if (count == 1) return n;
  const T d1 = side.dot(in[1]) - offset;
  if (d1 <= 0) out[n++] = in[1];
  if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0))
    out[n++] = in[0] + (d0 / (d0 - d1)) * (in[1] - in[0]);
  return n;
}

// Manifold of two boxes in a frame with the given origin (contacts are returned in world
// coordinates, origin + frame point). Reference face: the face of a with the largest separation,
// unless b's separates more by over the tolerance (Box2D prefers the first shape in the same way,
// for coherence). Incident face: the face of the other box most anti-parallel to the reference
// normal (ties: its axis 0). The incident edge is clipped to the reference face's side planes;
// clipped points at most the tolerance in front of the reference face are contacts, moved halfway
// towards it.
template <class T>
Manifold2T<T> collideBoxes(const Box<T>& a, const Box<T>& b, const Vec2<T>& origin) {
  const T slack = kGeometry2dTolerance<T> * boxScale(a, b);
  const FaceSeparation<T> fa = maxSeparation(a, b), fb = maxSeparation(b, a);
  Manifold2T<T> m;
  if (fa.separation > slack || fb.separation > slack) return m;
  const bool flip = fb.separation > fa.separation + slack;
  const Box<T>& ref = flip ? b : a;
  const Box<T>& inc = flip ? a : b;
  const FaceSeparation<T>& f = flip ? fb : fa;

  const Vec2<T> n = f.sign * ref.axes.col(f.axis);  // reference face normal, towards inc
  const int j = 1 - f.axis;
  const Vec2<T> tangent = ref.axes.col(j);
  const T sideHalf = ref.half[j];
  const Vec2<T> faceCenter = ref.center + n * ref.half[f.axis];

  const Vec2<T> nk0 = inc.axes.col(0), nk1 = inc.axes.col(1);
  const int k = std::abs(n.dot(nk0)) >= std::abs(n.dot(nk1)) ? 0 : 1;
  const Vec2<T> uk = inc.axes.col(k);
  const T incSign = n.dot(uk) > 0 ? T(-1) : T(1);
  const Vec2<T> incCenter = inc.center + (incSign * inc.half[k]) * uk - faceCenter;
  const Vec2<T> e = inc.axes.col(1 - k) * inc.half[1 - k];
  const std::array<Vec2<T>, 2> edge{incCenter - e, incCenter + e};

  std::array<Vec2<T>, 2> once{}, clipped{};
  int count = clipToSide(edge, 2, once, tangent, sideHalf);
  count = clipToSide(once, count, clipped, Vec2<T>(-tangent), sideHalf);

  m.colliding = true;
  m.normal = flip ? Vec2<T>(-n) : n;
  m.depth = std::max(T(0), -f.separation);
  for (int i = 0; i < count; ++i) {
    const T s = n.dot(clipped[i]);
    if (s > slack) continue;
    m.contacts[m.count++] = origin + faceCenter + clipped[i] - (s / 2) * n;
  }
  if (m.count == 0) {
    // Not reached in exact arithmetic (the deepest vertex of the incident box lies on the
    // incident edge within the side planes); kept so rounding can never leave a collision without
    // a contact: the deepest incident vertex, clamped into the reference face's span.
    const Vec2<T> w = edge[0].dot(n) <= edge[1].dot(n) ? edge[0] : edge[1];
    const T along = std::clamp(tangent.dot(w), -sideHalf, sideHalf);
    const T s = n.dot(w);
    m.contacts[0] = origin + faceCenter + along * tangent + (s / 2) * n;
    m.count = 1;
  }
  if (m.count == 2 && (m.contacts[0] - m.contacts[1]).norm() <= slack) m.count = 1;
  return m;
}

// A circle of radius r centered at the origin against the axis-aligned box [lo, hi] given
// relative to the circle's center (the caller knows they intersect). Normal from the circle to
// the box, contact relative to the circle's center.
template <class T>
Manifold2T<T> circleBoxAtOrigin(T r, const Vec2<T>& lo, const Vec2<T>& hi) {
  Manifold2T<T> m;
  m.colliding = true;
  m.count = 1;
  const Vec2<T> q = Vec2<T>::Zero().cwiseMax(lo).cwiseMin(hi);  // closest box point
  const T distance = q.norm();
  if (distance > 0) {
    m.normal = q / distance;
    m.depth = std::max(T(0), r - distance);
    m.contacts[0] = (r * m.normal + q) / T(2);
    return m;
  }
  // The center is in the box: leave through the nearest face (ties in the order listed).
  const std::array<T, 4> toFace{-lo.x(), hi.x(), -lo.y(), hi.y()};
  const std::array<Vec2<T>, 4> push{Vec2<T>(1, 0), Vec2<T>(-1, 0), Vec2<T>(0, 1), Vec2<T>(0, -1)};
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (toFace[i] < toFace[best]) best = i;
  m.normal = push[best];
  m.depth = r + toFace[best];
  m.contacts[0] = ((r - toFace[best]) / T(2)) * m.normal;
  return m;
}

// Circle against an oriented rectangle, in the rectangle's local frame: the circle's center
// relative to the rectangle's, rotated into its axes.
template <class T>
struct CircleInBox {
  Mat2<T> axes;
  Vec2<T> offset;  // circle center - box center, world axes
  Vec2<T> local;   // the same in the box's axes
};

template <class T>
CircleInBox<T> circleInBox(const CircleT<T>& c, const OrientedRectT<T>& b) {
  const Mat2<T> axes = b.axes();
  const Vec2<T> offset = c.center - b.center;
  return {axes, offset, axes.transpose() * offset};
}

}  // namespace detail::g2

template <class T>
bool intersects(const CircleT<T>& a, const CircleT<T>& b) {
  const T distance = (b.center - a.center).norm();
  const T reach = a.radius + b.radius;
  return distance <= reach + kGeometry2dTolerance<T> * std::max(distance, reach);
}

template <class T>
bool intersects(const CircleT<T>& c, const RectT<T>& r) {
  const Vec2<T> q = Vec2<T>::Zero().cwiseMax(r.min - c.center).cwiseMin(r.max - c.center);
  const T distance = q.norm();
  return distance <= c.radius + kGeometry2dTolerance<T> * std::max(distance, c.radius);
}

template <class T>
bool intersects(const CircleT<T>& c, const OrientedRectT<T>& b) {
  const detail::g2::CircleInBox<T> f = detail::g2::circleInBox(c, b);
  const Vec2<T> q = f.local.cwiseMax(-b.halfExtents).cwiseMin(b.halfExtents);
  const T distance = (f.local - q).norm();
  return distance <= c.radius + kGeometry2dTolerance<T> *
                                    (c.radius + f.offset.norm() + b.halfExtents.maxCoeff());
}

template <class T>
bool intersects(const RectT<T>& r, const OrientedRectT<T>& b) {
  return detail::g2::boxesIntersect(detail::g2::boxOf(r, b.center), detail::g2::boxOf(b, b.center));
}

template <class T>
bool intersects(const OrientedRectT<T>& a, const OrientedRectT<T>& b) {
  if (detail::g2::before(b, a)) return intersects(b, a);
  return detail::g2::boxesIntersect(detail::g2::boxOf(a, a.center), detail::g2::boxOf(b, a.center));
}

template <class T>
Manifold2T<T> collide(const CircleT<T>& a, const CircleT<T>& b) {
  if (detail::g2::before(b, a)) return flipped(collide(b, a));
  Manifold2T<T> m;
  if (!intersects(a, b)) return m;
  const Vec2<T> d = b.center - a.center;
  const T distance = d.norm();
  m.colliding = true;
  m.normal = distance > 0 ? Vec2<T>(d / distance) : Vec2<T>(1, 0);
  m.depth = std::max(T(0), a.radius + b.radius - distance);
  const Vec2<T> onA = a.radius * m.normal, onB = d - b.radius * m.normal;
  m.contacts[0] = a.center + (onA + onB) / T(2);
  m.count = 1;
  return m;
}

template <class T>
Manifold2T<T> collide(const CircleT<T>& c, const RectT<T>& r) {
  if (!intersects(c, r)) return {};
  Manifold2T<T> m =
      detail::g2::circleBoxAtOrigin(c.radius, Vec2<T>(r.min - c.center), Vec2<T>(r.max - c.center));
  m.contacts[0] += c.center;
  return m;
}

template <class T>
Manifold2T<T> collide(const CircleT<T>& c, const OrientedRectT<T>& b) {
  if (!intersects(c, b)) return {};
  const detail::g2::CircleInBox<T> f = detail::g2::circleInBox(c, b);
  Manifold2T<T> m = detail::g2::circleBoxAtOrigin(c.radius, Vec2<T>(-b.halfExtents - f.local),
                                                  Vec2<T>(b.halfExtents - f.local));
  m.normal = f.axes * m.normal;
  m.contacts[0] = c.center + f.axes * m.contacts[0];
  return m;
}

template <class T>
Manifold2T<T> collide(const RectT<T>& a, const RectT<T>& b) {
  if (detail::g2::before(b, a)) return flipped(collide(b, a));
  Manifold2T<T> m;
  if (!intersects(a, b)) return m;
  // push[i]: how far b must move along direction[i] to touch a.
  const std::array<T, 4> push{a.max.x() - b.min.x(), b.max.x() - a.min.x(), a.max.y() - b.min.y(),
                              b.max.y() - a.min.y()};
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (push[i] < push[best]) best = i;
  const int axis = best / 2, other = 1 - axis;
  const bool positive = best % 2 == 0;
  m.colliding = true;
  m.normal = Vec2<T>::Zero();
  m.normal[axis] = positive ? T(1) : T(-1);
  m.depth = push[best];
  // The face of a the normal leaves through, and the facing face of b.
  const T faceA = positive ? a.max[axis] : a.min[axis];
  const T faceB = positive ? b.min[axis] : b.max[axis];
  const T mid = (faceA + faceB) / T(2);
  const T lo = std::max(a.min[other], b.min[other]), hi = std::min(a.max[other], b.max[other]);
  m.contacts[0][axis] = mid;
  m.contacts[0][other] = lo;
  m.contacts[1][axis] = mid;
  m.contacts[1][other] = hi;
  m.count = lo == hi ? 1 : 2;
  return m;
}

template <class T>
Manifold2T<T> collide(const RectT<T>& r, const OrientedRectT<T>& b) {
  return detail::g2::collideBoxes(detail::g2::boxOf(r, b.center), detail::g2::boxOf(b, b.center),
                                  b.center);
}

template <class T>
Manifold2T<T> collide(const OrientedRectT<T>& a, const OrientedRectT<T>& b) {
  if (detail::g2::before(b, a)) return flipped(collide(b, a));
  return detail::g2::collideBoxes(detail::g2::boxOf(a, a.center), detail::g2::boxOf(b, a.center),
                                  a.center);
}

}  // namespace simdphys

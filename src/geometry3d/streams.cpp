#include "simdphys/geometry3d/streams.hpp"

#include "simdphys/geometry3d/raycast.hpp"

namespace simdphys {
using detail::at;
using detail::requireIndex;

void BoxStream::push(const Aabb& b) {
  validate(b, at("BoxStream::push", size()));
  append({b.min.x(), b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z()});
}

void BoxStream::set(std::size_t i, const Aabb& b) {
  requireIndex(i, size(), "BoxStream::set");
  validate(b, at("BoxStream::set", i));
  store(i, {b.min.x(), b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z()});
}

Aabb BoxStream::operator[](std::size_t i) const {
  return {{value(0, i), value(1, i), value(2, i)}, {value(3, i), value(4, i), value(5, i)}};
}

void SphereStream::push(const Sphere& s) {
  validate(s, at("SphereStream::push", size()));
  append({s.center.x(), s.center.y(), s.center.z(), s.radius});
}

void SphereStream::set(std::size_t i, const Sphere& s) {
  requireIndex(i, size(), "SphereStream::set");
  validate(s, at("SphereStream::set", i));
  store(i, {s.center.x(), s.center.y(), s.center.z(), s.radius});
}

Sphere SphereStream::operator[](std::size_t i) const {
  return {{value(0, i), value(1, i), value(2, i)}, value(3, i)};
}

void BoundsStream::push(const Vec3f& center, const Vec3f& halfExtents) {
  const std::string where = at("BoundsStream::push", size());
  detail::requireFiniteField(center, where, "center");
  detail::requireFiniteField(halfExtents, where, "halfExtents");
  constexpr char kAxis[] = {'x', 'y', 'z'};
  for (int a = 0; a < 3; ++a)
    if (!(halfExtents[a] >= 0)) throw Error(where + ": halfExtents." + kAxis[a] + " is negative");
  detail::requireReachInRange(center, halfExtents, where, "center +- halfExtents");
  append({center.x(), center.y(), center.z(), halfExtents.x(), halfExtents.y(), halfExtents.z()});
}

Aabb BoundsStream::operator[](std::size_t i) const {
  const Vec3f c(value(0, i), value(1, i), value(2, i)), e(value(3, i), value(4, i), value(5, i));
  return {c - e, c + e};
}

void TriangleStream::push(const Triangle& t) {
  const std::string where = at("TriangleStream::push", size());
  validate(t, where);
  // The same test as raycast's, which never hits such a triangle.
  if ((detail::rays::triangleNormalWide(t).array() == 0).all())
    throw Error(where + ": the triangle is degenerate (its vertices are collinear)");
  append({t.a.x(), t.a.y(), t.a.z(), t.b.x(), t.b.y(), t.b.z(), t.c.x(), t.c.y(), t.c.z()});
}

namespace {
std::array<float, 15> fieldsOf(const Obb& b) {
  std::array<float, 15> x{};
  for (int k = 0; k < 3; ++k) x[k] = b.center[k], x[3 + k] = b.halfExtents[k];
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) x[6 + 3 * c + k] = b.axes(k, c);
  return x;
}
}  // namespace

void ObbStream::push(const Obb& b) {
  validate(b, at("ObbStream::push", size()));
  append(fieldsOf(b));
}

void ObbStream::set(std::size_t i, const Obb& b) {
  requireIndex(i, size(), "ObbStream::set");
  validate(b, at("ObbStream::set", i));
  store(i, fieldsOf(b));
}

Obb ObbStream::operator[](std::size_t i) const {
  Obb b;
  for (int k = 0; k < 3; ++k) b.center[k] = value(k, i), b.halfExtents[k] = value(3 + k, i);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) b.axes(k, c) = value(6 + 3 * c + k, i);
  return b;
}

void PointStream::push(const Vec3f& p) {
  detail::requireFiniteField(p, at("PointStream::push", size()), "point");
  append({p.x(), p.y(), p.z()});
}

}  // namespace simdphys

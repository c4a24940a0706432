#include "simdphys/geometry3d/streams.hpp"

#include "simdphys/geometry3d/raycast.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {
using detail::at;

namespace {
std::array<float, 6> fieldsOf(const Aabb& b) {
  return {b.min.x(), b.min.y(), b.min.z(), b.max.x(), b.max.y(), b.max.z()};
}
std::array<float, 4> fieldsOf(const Sphere& s) {
  return {s.center.x(), s.center.y(), s.center.z(), s.radius};
}
std::array<float, 15> fieldsOf(const Obb& b) {
  std::array<float, 15> x{};
  for (int k = 0; k < 3; ++k) x[k] = b.center[k], x[3 + k] = b.halfExtents[k];
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) x[6 + 3 * c + k] = b.axes(k, c);
  return x;
}
}  // namespace

void BoxStream::push(const Aabb& b) { pushValid("BoxStream::push", b, fieldsOf(b)); }

void BoxStream::set(std::size_t i, const Aabb& b) { setValid("BoxStream::set", i, b, fieldsOf(b)); }

Aabb BoxStream::operator[](std::size_t i) const {
  return {{value(0, i), value(1, i), value(2, i)}, {value(3, i), value(4, i), value(5, i)}};
}

void SphereStream::push(const Sphere& s) { pushValid("SphereStream::push", s, fieldsOf(s)); }

void SphereStream::set(std::size_t i, const Sphere& s) {
  setValid("SphereStream::set", i, s, fieldsOf(s));
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

void ObbStream::push(const Obb& b) { pushValid("ObbStream::push", b, fieldsOf(b)); }

void ObbStream::set(std::size_t i, const Obb& b) { setValid("ObbStream::set", i, b, fieldsOf(b)); }

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

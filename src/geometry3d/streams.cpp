#include <cmath>
#include <sstream>

#include "simdphys/geometry3d.hpp"

namespace simdphys {
namespace {
constexpr char kAxis[] = {'x', 'y', 'z'};

std::string at(std::string_view where, std::size_t i) {
  return std::string(where) + ": element " + std::to_string(i);
}
}  // namespace

// ---- BoxStream ---------------------------------------------------------------------------------

void BoxStream::resize(std::size_t n) {
  for (Stream<float>* s : fields()) s->resize(n);
}

void BoxStream::reserve(std::size_t n) {
  for (Stream<float>* s : fields()) s->reserve(n);
}

void BoxStream::push(const Aabb& box) {
  validate(box, at("BoxStream::push", size()));
  std::size_t i = size();
  resize(i + 1);
  set(i, box);
}

void BoxStream::set(std::size_t i, const Aabb& box) {
  if (i >= size()) throw Error(at("BoxStream::set", i) + " is out of range");
  validate(box, at("BoxStream::set", i));
  minX_[i] = box.min.x(), minY_[i] = box.min.y(), minZ_[i] = box.min.z();
  maxX_[i] = box.max.x(), maxY_[i] = box.max.y(), maxZ_[i] = box.max.z();
}

Aabb BoxStream::operator[](std::size_t i) const {
  return {{minX_[i], minY_[i], minZ_[i]}, {maxX_[i], maxY_[i], maxZ_[i]}};
}

// ---- SphereStream ------------------------------------------------------------------------------

void SphereStream::resize(std::size_t n) {
  for (Stream<float>* s : fields()) s->resize(n);
}

void SphereStream::reserve(std::size_t n) {
  for (Stream<float>* s : fields()) s->reserve(n);
}

void SphereStream::push(const Sphere& sphere) {
  validate(sphere, at("SphereStream::push", size()));
  std::size_t i = size();
  resize(i + 1);
  set(i, sphere);
}

void SphereStream::set(std::size_t i, const Sphere& sphere) {
  if (i >= size()) throw Error(at("SphereStream::set", i) + " is out of range");
  validate(sphere, at("SphereStream::set", i));
  x_[i] = sphere.center.x(), y_[i] = sphere.center.y(), z_[i] = sphere.center.z();
  r_[i] = sphere.radius;
}

Sphere SphereStream::operator[](std::size_t i) const { return {{x_[i], y_[i], z_[i]}, r_[i]}; }

// ---- BoundsStream ------------------------------------------------------------------------------

void BoundsStream::resize(std::size_t n) {
  for (Stream<float>* s : fields()) s->resize(n);
}

void BoundsStream::reserve(std::size_t n) {
  for (Stream<float>* s : fields()) s->reserve(n);
}

void BoundsStream::push(const Vec3f& center, const Vec3f& halfExtents) {
  std::string where = at("BoundsStream::push", size());
  detail::requireFiniteField(center, where, "center");
  detail::requireFiniteField(halfExtents, where, "halfExtents");
  for (int a = 0; a < 3; ++a)
    if (!(halfExtents[a] >= 0)) throw Error(where + ": halfExtents." + kAxis[a] + " is negative");
  std::size_t i = size();
  resize(i + 1);
  cx_[i] = center.x(), cy_[i] = center.y(), cz_[i] = center.z();
  ex_[i] = halfExtents.x(), ey_[i] = halfExtents.y(), ez_[i] = halfExtents.z();
}

Aabb BoundsStream::operator[](std::size_t i) const {
  Vec3f c(cx_[i], cy_[i], cz_[i]), e(ex_[i], ey_[i], ez_[i]);
  return {c - e, c + e};
}

}  // namespace simdphys

// Operations on one model: bounds, transform validation, raycasts in model space.
#include "simdphys/scene/model.hpp"

#include <cmath>
#include <sstream>

#include "simdphys/geometry3d/raycast.hpp"

namespace simdphys {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

Aabb obbBounds(const Obb& o) {
  const Vec3f reach = o.axes.cwiseAbs() * o.halfExtents;
  return {o.center - reach, o.center + reach};
}

}  // namespace

Aabb localBounds(const ModelShape& shape) {
  return std::visit(
      Overloaded{[](const std::shared_ptr<const MeshBvh>& m) { return m->mesh().bounds(); },
                 [](const Sphere& s) {
                   return Aabb{s.center.array() - s.radius, s.center.array() + s.radius};
                 },
                 [](const Aabb& b) { return b; }, [](const Obb& o) { return obbBounds(o); }},
      shape);
}

Aabb transformBounds(const Aabb& local, const Mat4f& m) {
  const Vec3f c = transformPoint(m, local.center());
  const Vec3f h = m.topLeftCorner<3, 3>().cwiseAbs() * local.halfExtents();
  // The centre and the |M| h products each carry a few roundings of their magnitude; 16 eps of
  // |c| + h (and of the local box's own scale, through |M|) is several times that.
  const Vec3f slack =
      16 * std::numeric_limits<float>::epsilon() *
      (c.cwiseAbs() + h + m.topLeftCorner<3, 3>().cwiseAbs() * local.center().cwiseAbs());
  return {c - h - slack, c + h + slack};
}

void validateTransform(const Mat4f& m, std::string_view where) {
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(m(row, col))) {
        std::ostringstream msg;
        msg << where << ": transform(" << row << ", " << col << ") is " << m(row, col)
            << ", not finite";
        throw Error(msg.str());
      }
  if (!(m(3, 0) == 0 && m(3, 1) == 0 && m(3, 2) == 0 && m(3, 3) == 1))
    throw Error(std::string(where) + ": transform is not affine (last row must be 0 0 0 1)");
  if (m.topLeftCorner<3, 3>().cast<double>().determinant() == 0)
    throw Error(std::string(where) + ": transform is singular (a zero scale?)");
  // The supported range (math.hpp): each axis's scale factor (its column's length, in double)
  // in [kMinScale, kMaxCoordinate], so the inverse's stays in range too, and the translation
  // in range. A model scaled by 1e-39 would otherwise be accepted but never hit.
  for (int col = 0; col < 3; ++col) {
    const double scale = m.col(col).head<3>().cast<double>().norm();
    if (!(scale >= kMinScale && scale <= kMaxCoordinate)) {
      std::ostringstream msg;
      msg << where << ": transform's scale along axis " << col << " is " << scale
          << ", outside the supported range [" << kMinScale << ", " << kMaxCoordinate << "]";
      throw Error(msg.str());
    }
    if (!(std::abs(m(col, 3)) <= kMaxCoordinate)) {
      std::ostringstream msg;
      msg << where << ": transform's translation "
          << "xyz"[col] << " is " << m(col, 3)
          << ", outside the supported range (|t| <= " << kMaxCoordinate << ")";
      throw Error(msg.str());
    }
  }
}

ModelHit worldHit(const PlacedShape& placed, const Ray& ray, float t, const Vec3f& localNormal,
                  std::uint32_t triangle) {
  // Normals transform by the inverse transpose; the sign survives (n'.d = n.(M^-1 d)), so a
  // normal facing the model-space ray still faces the world ray, up to rounding, fixed below.
  Vec3f n = placed.worldInverse->topLeftCorner<3, 3>().transpose() * localNormal;
  n.normalize();
  if (n.dot(ray.direction) > 0) n = -n;
  ModelHit hit;
  hit.t = t;
  hit.point = ray.at(t);
  hit.normal = n;
  hit.triangle = triangle;
  return hit;
}

std::optional<ModelHit> raycast(const PlacedShape& placed, const Ray& ray, float tMax) {
  const Mat4f& inv = *placed.worldInverse;
  const Ray local{transformPoint(inv, ray.origin), transformDirection(inv, ray.direction)};
  return std::visit(
      Overloaded{[&](const std::shared_ptr<const MeshBvh>& m) -> std::optional<ModelHit> {
                   const ElementHit h = m->raycast(local, tMax);
                   if (!h.hit()) return std::nullopt;
                   const Vec3f n = m->mesh().triangle(h.index).normal();
                   return worldHit(placed, ray, h.t, n, h.index);
                 },
                 [&](const auto& primitive) -> std::optional<ModelHit> {
                   const auto h = simdphys::raycast(primitive, local, tMax);
                   if (!h) return std::nullopt;
                   return worldHit(placed, ray, h->t, h->normal, kNoHit);
                 }},
      *placed.shape);
}

}  // namespace simdphys

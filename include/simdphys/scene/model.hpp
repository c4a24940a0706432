// Models (book chapter 12): a shape (a triangle mesh with its BVH, or a primitive) placed in the
// world by a transform, optionally relative to a parent model. Operations on one model run in
// model space: a world ray is moved into the model's frame, cast there, and its hit brought back.
//
// Transforms follow docs/conventions.md: column vectors, world = parent world * local, a local
// transform is any invertible affine Mat4f (typically transform(scale, rotation, translation)).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <variant>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/mesh_bvh.hpp"

namespace simdphys {

// What a model is made of, in model space. Meshes are shared: many models may instance one.
using ModelShape = std::variant<std::shared_ptr<const MeshBvh>, Sphere, Aabb, Obb>;

// No parent: the default handle, which names no model.
inline constexpr Handle kNoParent{};
inline constexpr std::uint32_t kNoModel = ~0u;

struct Model {
  ModelShape shape;
  // Model space to the parent's space (to world space without a parent).
  Mat4f transform = Mat4f::Identity();
  Handle parent = kNoParent;  // the parent model in its scene (Scene::add's handle)
};

// Where a ray meets a model, in world space.
struct ModelHit {
  std::uint32_t model = kNoModel;
  // Along the ray, in units of its direction: the world distance for a unit direction.
  float t = std::numeric_limits<float>::infinity();
  Vec3f point = Vec3f::Zero();
  Vec3f normal = Vec3f::Zero();     // unit, facing the ray
  std::uint32_t triangle = kNoHit;  // the mesh triangle hit; kNoHit for primitives
  bool hit() const { return model != kNoModel; }
};

// The model-space bounding box of a shape (a mesh's: its vertices').
Aabb localBounds(const ModelShape& shape);

// The world box of a model-space box under an affine matrix (centre moved, half extents through
// |M|, Arvo 1990), widened by a few ulp of its coordinates so that it contains the transformed
// box despite rounding: structures prune with it and must never lose a model by an ulp.
Aabb transformBounds(const Aabb& local, const Mat4f& world);

// Throws Error naming `where` unless m is finite, affine (last row exactly 0 0 0 1), invertible
// (its 3x3 determinant, in double, is not zero) and in the supported range (math.hpp): each
// column's length (the axis's scale factor) in [kMinScale, kMaxCoordinate], the translation's
// components at most kMaxCoordinate in magnitude.
void validateTransform(const Mat4f& m, std::string_view where);

// A model placed in the world: its shape and the matrices both ways. What a scene keeps.
struct PlacedShape {
  const ModelShape* shape;
  const Mat4f* world;         // model to world
  const Mat4f* worldInverse;  // world to model
};

// The hit of a world ray (unit direction) on the shape, t in world units in [0, tMax]. The ray is
// moved into model space without normalising its direction, so t needs no conversion: a point at
// world distance t maps to model origin + t * model direction. Normals go back through the
// inverse transpose. `model` of the result is left for the caller to fill.
std::optional<ModelHit> raycast(const PlacedShape& placed, const Ray& ray,
                                float tMax = std::numeric_limits<float>::infinity());

// The world hit record of a model-space hit (t, model-space normal) of the ray.
ModelHit worldHit(const PlacedShape& placed, const Ray& ray, float t, const Vec3f& localNormal,
                  std::uint32_t triangle);

}  // namespace simdphys

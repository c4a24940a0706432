// Scenes (book chapter 12): models with transforms and parents, their world bounds as streams,
// an octree and a top-level BVH over those bounds, and the queries through them: raycasts (one
// ray or a stream), sphere and box queries, frustum culling, picking.
//
// A model's world box is the box of its model-space bounds under its world matrix
// (transformBounds), stored as a BoundsStream entry (centre, half extents): `bounds()[i]` as
// min/max is what sphere and box queries test and what the BVH is built on, the centre and
// extents are what culling tests. Queries test world boxes, as the book's scene does with its
// models' bounds; raycasts test the shapes themselves.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "simdphys/bvh.hpp"
#include "simdphys/scene/camera.hpp"
#include "simdphys/scene/model.hpp"
#include "simdphys/scene/octree.hpp"

namespace simdphys {

// Which structure answers a query; all give the same answer.
enum class SceneIndex { kFlat, kOctree, kBvh };

class Scene {
 public:
  explicit Scene(const OctreeOptions& octree = {}) : octreeOptions_(octree) {}

  // Adds a model and returns its index. Throws Error naming the model if its transform is not
  // finite, affine and invertible, its shape is invalid (a null mesh, a negative radius, ...),
  // or its parent is not an existing model.
  std::uint32_t add(const Model& model);
  // Sets a model's local transform (validated as for add).
  void setTransform(std::uint32_t model, const Mat4f& local);
  // Makes `parent` (kNoParent for none) the model's parent. Throws Error if either index is out
  // of range or the link would close a cycle (the message lists it).
  void setParent(std::uint32_t model, std::uint32_t parent);

  // Brings world matrices, world bounds, the octree and the BVH up to date: after models were
  // added both are rebuilt; after moves the BVH is refitted and the moved models are taken out
  // of the octree's leaves and put into their new ones. Throws Error naming the model if a world
  // matrix (parent world * local) is not finite or singular. Queries need it after any change.
  void update();

  std::size_t size() const { return models_.size(); }
  const Model& model(std::uint32_t i) const { return models_.at(i); }
  const Mat4f& world(std::uint32_t i) const { return world_.at(i); }
  const BoundsStream& bounds() const { return bounds_; }
  const Octree& octree() const { return octree_; }
  // Model i in the world, for the single-model operations of model.hpp.
  PlacedShape placed(std::uint32_t i) const {
    return {&models_[i].shape, &world_[i], &inverse_[i]};
  }
  const Bvh& bvh() const { return bvh_; }

  // The closest model the ray (unit direction) hits with t in [0, tMax]; ties in t go to the
  // smaller model index. Through the BVH, nearest subtree first.
  ModelHit raycast(const Ray& ray, float tMax = std::numeric_limits<float>::infinity()) const;
  // The same for every ray of a stream (each ray's tMax), whose directions may have any non-zero
  // length as in MeshBvh: t is in units of the ray's direction. Model by model, the
  // rays that meet the model's world box are moved into its space as one RayStream, and a mesh
  // casts them all through MeshBvh's stream raycast. Suits many rays and few models (a frame).
  void raycast(const RayStream& rays, std::span<ModelHit> out) const;

  // Indices, ascending, of the models whose world box meets the shape (closed tests).
  std::vector<std::uint32_t> query(const Sphere& sphere, SceneIndex via = SceneIndex::kBvh) const;
  std::vector<std::uint32_t> query(const Aabb& box, SceneIndex via = SceneIndex::kBvh) const;
  // Indices, ascending, of the models whose world box passes Frustum::intersectsBox; returns
  // their number.
  std::size_t cull(const Frustum& frustum, std::vector<std::uint32_t>& visible,
                   SceneIndex via = SceneIndex::kOctree) const;
  // The model under the window point (px, py) of the camera: the closest hit of its picking ray.
  ModelHit pick(const Camera& camera, float px, float py) const;

 private:
  void requireIndex(std::uint32_t i, const char* where) const;
  void requireUpToDate(const char* where) const;

  OctreeOptions octreeOptions_;
  std::vector<Model> models_;
  std::vector<Mat4f> world_, inverse_;
  BoundsStream bounds_;
  BoxStream boxes_;  // bounds_ as min/max, the BVH's input
  Octree octree_;
  Bvh bvh_;
  std::size_t indexed_ = 0;  // models in the octree and BVH
  bool dirty_ = false;
};

}  // namespace simdphys

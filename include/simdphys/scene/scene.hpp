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

  // Models are kept dense, at indices 0 .. size() - 1 of the streams (bounds(), the results of
  // queries, ModelHit::model); a model is named for as long as it lives by the handle add()
  // returns (handle.hpp). A removal moves the last model into the hole, so indices change and
  // handles do not. Every call that takes a handle throws Error, naming the call and the handle,
  // if the handle's model was removed (even if its slot holds a newer model) or never existed.

  // Adds a model at index size() and returns its handle. Throws Error naming the model if its
  // transform is not finite, affine and invertible, its shape is invalid (a null mesh, a negative
  // radius, ...), or its parent is not a model of the scene.
  Handle add(const Model& model);
  // Removes a model; the last model takes its index. Throws Error if the model is still a parent
  // (remove or re-parent its children first). Queries need update() after it.
  void remove(Handle model);
  // Sets a model's local transform (validated as for add).
  void setTransform(Handle model, const Mat4f& local);
  // Makes `parent` (kNoParent for none) the model's parent. Throws Error if the link would close
  // a cycle (the message lists it, by index).
  void setParent(Handle model, Handle parent);

  // Brings world matrices, world bounds, the octree and the BVH up to date: after models were
  // added or removed both are rebuilt; after moves the BVH is refitted and the moved models are
  // taken out of the octree's leaves and put into their new ones. Throws Error naming the model
  // if a world matrix (parent world * local) is not finite or singular. Queries need it after any
  // change.
  void update();

  std::size_t size() const { return models_.size(); }
  // True while the handle's model is in the scene.
  bool contains(Handle model) const;
  // The index of a model in the streams, until the next removal.
  std::uint32_t index(Handle model) const;
  // The handle of the model at an index (Error if out of range).
  Handle handle(std::uint32_t index) const;

  // A model by handle, or by index (an element of a query's result, ModelHit::model).
  const Model& model(Handle m) const { return models_[require(m, "Scene::model")]; }
  const Model& model(std::uint32_t i) const { return models_.at(i); }
  const Mat4f& world(Handle m) const { return world_.at(require(m, "Scene::world")); }
  const Mat4f& world(std::uint32_t i) const { return world_.at(i); }
  const BoundsStream& bounds() const { return bounds_; }
  const Octree& octree() const { return octree_; }
  // A model in the world, for the single-model operations of model.hpp.
  PlacedShape placed(Handle m) const { return placed(require(m, "Scene::placed")); }
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
  // The index of a handle's model; Error naming `where` if the handle names none.
  std::uint32_t require(Handle model, const char* where) const;
  void requireUpToDate(const char* where) const;
  // The index of model i's parent, or kNoModel.
  std::uint32_t parentIndex(std::uint32_t i) const;
  // query()'s one body, for a sphere or a box (scene.cpp).
  template <class Shape>
  std::vector<std::uint32_t> select(const Shape& shape, SceneIndex via) const;

  // A handle's slot: the index of its model and the generation of the handle that names it.
  HandleTable handles_;

  OctreeOptions octreeOptions_;
  std::vector<Model> models_;
  std::vector<Mat4f> world_, inverse_;
  BoundsStream bounds_;
  BoxStream boxes_;  // bounds_ as min/max, the BVH's input
  Octree octree_;
  Bvh bvh_;
  std::size_t indexed_ = 0;  // models in the octree and BVH; kRebuild after a removal
  static constexpr std::size_t kRebuild = ~std::size_t(0);
  bool dirty_ = false;
};

}  // namespace simdphys

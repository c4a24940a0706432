// The scene: models, world transforms and bounds, and the queries by box, sphere and frustum.
#include "simdphys/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "simdphys/geometry3d/intersect.hpp"

namespace simdphys {
namespace {

std::string modelName(std::uint32_t i) { return "model " + std::to_string(i); }

void validateShape(const ModelShape& shape, const std::string& where) {
  if (const auto* mesh = std::get_if<std::shared_ptr<const MeshBvh>>(&shape)) {
    if (!*mesh) throw Error(where + ": the mesh is null");
  } else {
    std::visit(
        [&](const auto& s) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, std::shared_ptr<const MeshBvh>>)
            validate(s, where);
        },
        shape);
  }
}

// The inverse of an affine matrix: [A t]^-1 = [A^-1  -A^-1 t].
Mat4f affineInverse(const Mat4f& m) {
  const Mat3f a = m.topLeftCorner<3, 3>().cast<double>().inverse().cast<float>();
  Mat4f inv = Mat4f::Identity();
  inv.topLeftCorner<3, 3>() = a;
  inv.topRightCorner<3, 1>() = -(a * m.topRightCorner<3, 1>());
  return inv;
}

// Whether a query's shape meets a model's world box (closed), and the box that holds every box
// that passes: the BVH's candidates.
bool meets(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}
bool meets(const Sphere& sphere, const Aabb& box) { return intersects(sphere, box); }

Aabb reach(const Aabb& box) { return box; }
// The sphere test passes boxes up to its tolerance (16 eps of the distance and radius) beyond the
// radius, and its float distance may round below the true one by an ulp of the centre: the reach
// is wider than both.
Aabb reach(const Sphere& sphere) {
  const float pad = sphere.radius * 1e-5f +
                    4 * std::numeric_limits<float>::epsilon() * sphere.center.cwiseAbs().maxCoeff();
  return {sphere.center.array() - (sphere.radius + pad),
          sphere.center.array() + (sphere.radius + pad)};
}

}  // namespace

std::uint32_t Scene::require(Handle h, const char* where) const {
  return handles_.index(h, where, "model");
}

void Scene::requireUpToDate(const char* where) const {
  if (dirty_) throw Error(std::string(where) + ": the scene changed; call update() first");
}

std::uint32_t Scene::parentIndex(std::uint32_t i) const {
  const Handle p = models_[i].parent;
  return p == kNoParent ? kNoModel : handles_.index(p, "Scene", "model");
}

bool Scene::contains(Handle h) const { return handles_.contains(h); }

std::uint32_t Scene::index(Handle h) const { return require(h, "Scene::index"); }

Handle Scene::handle(std::uint32_t i) const {
  if (i >= models_.size())
    throw Error("Scene::handle: " + modelName(i) + " is out of range (" +
                std::to_string(models_.size()) + " models)");
  return handles_.handle(i);
}

Handle Scene::add(const Model& model) {
  const auto i = std::uint32_t(models_.size());
  const std::string where = "Scene::add: " + modelName(i);
  validateTransform(model.transform, where);
  validateShape(model.shape, where);
  if (model.parent != kNoParent) {
    if (model.parent.slot >= handles_.slots())
      throw Error(where + ": parent " + std::to_string(model.parent.slot) + " is out of range (" +
                  std::to_string(i) + " models before it)");
    require(model.parent, (where + " (parent)").c_str());
  }
  models_.push_back(model);
  dirty_ = true;
  return handles_.add();
}

void Scene::remove(Handle h) {
  const std::uint32_t i = require(h, "Scene::remove");
  for (std::uint32_t m = 0; m < models_.size(); ++m)
    if (models_[m].parent == h)
      throw Error("Scene::remove: " + modelName(i) + " is the parent of " + modelName(m) +
                  "; remove or re-parent its children first");
  handles_.remove(h, "Scene::remove", "model");
  models_[i] = std::move(models_.back());
  models_.pop_back();
  indexed_ = kRebuild;
  dirty_ = true;
}

void Scene::setTransform(Handle h, const Mat4f& local) {
  const std::uint32_t i = require(h, "Scene::setTransform");
  validateTransform(local, "Scene::setTransform: " + modelName(i));
  models_[i].transform = local;
  dirty_ = true;
}

void Scene::setParent(Handle h, Handle parent) {
  const std::uint32_t i = require(h, "Scene::setParent");
  if (parent != kNoParent) {
    // Walk up from the new parent: meeting the model means the link would close a cycle.
    std::uint32_t p = require(parent, "Scene::setParent (parent)");
    std::string chain = std::to_string(i);
    for (; p != kNoModel; p = parentIndex(p)) {
      chain += " -> " + std::to_string(p);
      if (p == i)
        throw Error("Scene::setParent: " + modelName(i) + " would be its own ancestor (" + chain +
                    ")");
    }
  }
  models_[i].parent = parent;
  dirty_ = true;
}

void Scene::update() {
  const std::size_t n = models_.size();
  world_.resize(n);
  inverse_.resize(n);
  // Parents before children: walk up to the nearest model already done, then back down.
  std::vector<std::uint8_t> done(n, 0);
  std::vector<std::uint32_t> chain;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t m = i; m != kNoModel && !done[m]; m = parentIndex(m)) chain.push_back(m);
    for (; !chain.empty(); chain.pop_back()) {
      const std::uint32_t m = chain.back();
      const std::uint32_t p = parentIndex(m);
      world_[m] = p == kNoModel ? models_[m].transform : Mat4f(world_[p] * models_[m].transform);
      validateTransform(world_[m], "Scene::update: " + modelName(m) + " (world)");
      inverse_[m] = affineInverse(world_[m]);
      done[m] = 1;
    }
  }
  BoundsStream fresh;
  fresh.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    // Cut to the supported range: at its edge the bounds' rounding slack reaches past it, and
    // every query is inside it, so the cut changes no answer.
    const Vec3f edge = Vec3f::Constant(kMaxCoordinate);
    const Aabb b = transformBounds(localBounds(models_[i].shape), world_[i]);
    const Aabb cut{b.min.cwiseMax(-edge), b.max.cwiseMin(edge)};
    const Vec3f c = cut.min * 0.5f + cut.max * 0.5f;
    Vec3f h = cut.max * 0.5f - cut.min * 0.5f;
    // c + h can round one ulp past the edge; an ulp of h is far inside the bounds' slack.
    for (int a = 0; a < 3; ++a)
      while (std::abs(c[a]) + h[a] > kMaxCoordinate) h[a] = std::nextafter(h[a], 0.0f);
    fresh.push(c, h);
  }
  std::vector<std::uint32_t> moved;
  if (indexed_ == n)
    for (std::uint32_t i = 0; i < n; ++i)
      if (fresh[i].min != bounds_[i].min || fresh[i].max != bounds_[i].max) moved.push_back(i);
  bounds_ = std::move(fresh);
  boxes_.clear();
  boxes_.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) boxes_.push(bounds_[i]);
  if (indexed_ != n) {
    octree_.build(bounds_, octreeOptions_);
    bvh_.build(boxes_);
  } else if (!moved.empty()) {
    octree_.update(moved, bounds_);
    bvh_.refit(boxes_);
  }
  indexed_ = n;
  dirty_ = false;
}

// ---- queries ---------------------------------------------------------------------------------

template <class Shape>
std::vector<std::uint32_t> Scene::select(const Shape& shape, SceneIndex via) const {
  requireUpToDate("Scene::query");
  validate(shape, "Scene::query");
  if (via == SceneIndex::kOctree) return octree_.query(shape);
  std::vector<std::uint32_t> out;
  if (via == SceneIndex::kFlat) {
    for (std::uint32_t i = 0; i < size(); ++i)
      if (meets(shape, bounds_[i])) out.push_back(i);
    return out;
  }
  std::vector<std::uint32_t> candidates;
  bvh_.query(reach(shape), candidates);
  for (std::uint32_t i : candidates)
    if (meets(shape, bounds_[i])) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> Scene::query(const Sphere& sphere, SceneIndex via) const {
  return select(sphere, via);
}

std::vector<std::uint32_t> Scene::query(const Aabb& box, SceneIndex via) const {
  return select(box, via);
}

std::size_t Scene::cull(const Frustum& frustum, std::vector<std::uint32_t>& visible,
                        SceneIndex via) const {
  requireUpToDate("Scene::cull");
  switch (via) {
    case SceneIndex::kFlat:
      return simdphys::cull(frustum, bounds_, visible);
    case SceneIndex::kOctree:
      return octree_.cull(frustum, visible);
    case SceneIndex::kBvh:
      return simdphys::cull(frustum, bvh_, bounds_, visible);
  }
  return 0;
}

ModelHit Scene::pick(const Camera& camera, float px, float py) const {
  return raycast(camera.ray(px, py));
}

}  // namespace simdphys

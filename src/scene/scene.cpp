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

bool overlaps(const Aabb& a, const Aabb& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

}  // namespace

void Scene::requireIndex(std::uint32_t i, const char* where) const {
  if (i >= models_.size())
    throw Error(std::string(where) + ": " + modelName(i) + " is out of range (" +
                std::to_string(models_.size()) + " models)");
}

void Scene::requireUpToDate(const char* where) const {
  if (dirty_) throw Error(std::string(where) + ": the scene changed; call update() first");
}

std::uint32_t Scene::add(const Model& model) {
  const auto i = std::uint32_t(models_.size());
  const std::string where = "Scene::add: " + modelName(i);
  validateTransform(model.transform, where);
  validateShape(model.shape, where);
  if (model.parent != kNoParent && model.parent >= i)
    throw Error(where + ": parent " + std::to_string(model.parent) + " is out of range (" +
                std::to_string(i) + " models before it)");
  models_.push_back(model);
  dirty_ = true;
  return i;
}

void Scene::setTransform(std::uint32_t i, const Mat4f& local) {
  requireIndex(i, "Scene::setTransform");
  validateTransform(local, "Scene::setTransform: " + modelName(i));
  models_[i].transform = local;
  dirty_ = true;
}

void Scene::setParent(std::uint32_t i, std::uint32_t parent) {
  requireIndex(i, "Scene::setParent");
  if (parent != kNoParent) {
    requireIndex(parent, "Scene::setParent (parent)");
    // Walk up from the new parent: meeting the model means the link would close a cycle.
    std::string chain = std::to_string(i);
    for (std::uint32_t p = parent; p != kNoParent; p = models_[p].parent) {
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
    for (std::uint32_t m = i; m != kNoParent && !done[m]; m = models_[m].parent) chain.push_back(m);
    for (; !chain.empty(); chain.pop_back()) {
      const std::uint32_t m = chain.back();
      const std::uint32_t p = models_[m].parent;
      world_[m] = p == kNoParent ? models_[m].transform : Mat4f(world_[p] * models_[m].transform);
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

std::vector<std::uint32_t> Scene::query(const Sphere& sphere, SceneIndex via) const {
  requireUpToDate("Scene::query");
  validate(sphere, "Scene::query");
  std::vector<std::uint32_t> out;
  if (via == SceneIndex::kOctree) return octree_.query(sphere);
  if (via == SceneIndex::kFlat) {
    for (std::uint32_t i = 0; i < size(); ++i)
      if (intersects(sphere, bounds_[i])) out.push_back(i);
    return out;
  }
  // The sphere test passes boxes up to its tolerance (16 eps of the distance and radius) beyond
  // the radius, and its float distance may round below the true one by an ulp of the centre: the
  // candidate box is widened by more than both.
  const float pad = sphere.radius * 1e-5f +
                    4 * std::numeric_limits<float>::epsilon() * sphere.center.cwiseAbs().maxCoeff();
  const Aabb reach{sphere.center.array() - (sphere.radius + pad),
                   sphere.center.array() + (sphere.radius + pad)};
  std::vector<std::uint32_t> candidates;
  bvh_.query(reach, candidates);
  for (std::uint32_t i : candidates)
    if (intersects(sphere, bounds_[i])) out.push_back(i);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> Scene::query(const Aabb& box, SceneIndex via) const {
  requireUpToDate("Scene::query");
  validate(box, "Scene::query");
  std::vector<std::uint32_t> out;
  if (via == SceneIndex::kOctree) return octree_.query(box);
  if (via == SceneIndex::kFlat) {
    for (std::uint32_t i = 0; i < size(); ++i)
      if (overlaps(box, bounds_[i])) out.push_back(i);
    return out;
  }
  bvh_.query(box, out);
  std::sort(out.begin(), out.end());
  return out;
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

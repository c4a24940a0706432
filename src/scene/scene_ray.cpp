// Scene raycasts: one ray through the top-level BVH, or a stream of rays model by model.
#include <algorithm>
#include <array>
#include <string>

#include "simdphys/scene/scene.hpp"

namespace simdphys {
namespace {

// Where the ray enters the box [lo, hi], if it does before `limit` (t >= 0). An axis the ray is
// parallel to is tested directly (its division would give 0 / 0 on a face).
bool enters(const Vec3f& lo, const Vec3f& hi, const Ray& ray, float limit, float& enter) {
  float t0 = 0, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    const float o = ray.origin[a], d = ray.direction[a];
    if (d == 0) {
      if (o < lo[a] || o > hi[a]) return false;
      continue;
    }
    float tn = (lo[a] - o) / d, tf = (hi[a] - o) / d;
    if (tn > tf) std::swap(tn, tf);
    t0 = std::max(t0, tn);
    t1 = std::min(t1, tf);
  }
  enter = t0;
  return t0 <= t1;
}

// The order of hits: the smaller t, then the smaller model index. A miss (model kNoModel) at the
// caller's tMax loses to a hit at the same t.
bool closer(const ModelHit& a, const ModelHit& b) {
  return a.t < b.t || (a.t == b.t && a.model < b.model);
}

Aabb boxOf(const BvhNode& n, int k) {
  return {{n.minX[k], n.minY[k], n.minZ[k]}, {n.maxX[k], n.maxY[k], n.maxZ[k]}};
}

}  // namespace

ModelHit Scene::raycast(const Ray& ray, float tMax) const {
  requireUpToDate("Scene::raycast");
  validate(ray, "Scene::raycast");
  if (!(tMax >= 0)) throw Error("Scene::raycast: tMax must be >= 0");
  ModelHit best;
  best.t = tMax;
  const auto nodes = bvh_.nodes();
  if (nodes.empty()) return best;
  // A node enters the stack with the t where the ray enters its box; popped, it is skipped if a
  // hit closer than that was found meanwhile. The world boxes are widened beyond rounding
  // (transformBounds), so a model's hit is never before its box's entry.
  std::vector<std::pair<float, std::uint32_t>> stack{{0.0f, 0u}};
  std::array<std::pair<float, std::uint32_t>, BvhNode::kWidth> near;
  while (!stack.empty()) {
    const auto [enter, index] = stack.back();
    stack.pop_back();
    if (enter > best.t) continue;
    const BvhNode& node = nodes[index];
    int count = 0;
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t c = node.child[k];
      float t;
      if (c == BvhNode::kEmpty) continue;
      const Aabb box = boxOf(node, k);
      if (!enters(box.min, box.max, ray, best.t, t)) continue;
      if (!BvhNode::isLeaf(c)) {
        near[count++] = {t, c};
        continue;
      }
      const std::uint32_t m = BvhNode::leafFirst(c);
      if (auto hit = simdphys::raycast(placed(m), ray)) {
        hit->model = m;
        if (closer(*hit, best)) best = *hit;
      }
    }
    // Farthest first onto the stack, so the nearest box is searched next (insertion sort: <= 8).
    for (int k = 1; k < count; ++k)
      for (int j = k; j > 0 && near[j - 1].first < near[j].first; --j)
        std::swap(near[j - 1], near[j]);
    for (int k = 0; k < count; ++k) stack.push_back(near[k]);
  }
  return best;
}

void Scene::raycast(const RayStream& rays, std::span<ModelHit> out) const {
  requireUpToDate("Scene::raycast");
  if (out.size() != rays.size())
    throw Error("Scene::raycast: " + std::to_string(rays.size()) + " rays but room for " +
                std::to_string(out.size()) + " hits");
  for (std::size_t i = 0; i < rays.size(); ++i) {
    out[i] = ModelHit{};
    out[i].t = rays.tMax()[i];
  }
  std::vector<std::uint32_t> candidates;
  std::vector<MeshHit> meshHits;
  RayStream local;
  for (std::uint32_t m = 0; m < size(); ++m) {
    const Aabb box = bounds_[m];
    const PlacedShape shape = placed(m);
    candidates.clear();
    for (std::uint32_t i = 0; i < rays.size(); ++i) {
      float t;
      if (enters(box.min, box.max, rays[i], out[i].t, t)) candidates.push_back(i);
    }
    auto offer = [&](std::uint32_t i, std::optional<ModelHit> hit) {
      if (!hit) return;
      hit->model = m;
      if (closer(*hit, out[i])) out[i] = *hit;
    };
    const auto* mesh = std::get_if<std::shared_ptr<const MeshBvh>>(&models_[m].shape);
    if (!mesh) {
      for (std::uint32_t i : candidates) offer(i, simdphys::raycast(shape, rays[i]));
      continue;
    }
    // One stream in model space: t along the moved (not normalised) direction is world t.
    local.clear();
    local.reserve(candidates.size());
    for (std::uint32_t i : candidates) {
      const Ray r = rays[i];
      local.push(
          {transformPoint(inverse_[m], r.origin), transformDirection(inverse_[m], r.direction)});
    }
    meshHits.assign(candidates.size(), MeshHit{});
    (*mesh)->raycast(local, meshHits);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (!meshHits[k].hit()) continue;
      const Vec3f n = (*mesh)->mesh().triangle(meshHits[k].id).normal();
      offer(candidates[k], worldHit(shape, rays[candidates[k]], meshHits[k].t, n, meshHits[k].id));
    }
  }
}

}  // namespace simdphys

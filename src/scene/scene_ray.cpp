// Scene raycasts: one ray through the top-level BVH, or a stream of rays model by model.
#include <algorithm>
#include <array>
#include <cmath>
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

namespace {

// The rays of a stream as the box filter reads them: origins and inverse directions, SoA. A zero
// direction component becomes +-1e-30 before inverting, so the products below never meet
// 0 * inf: a ray parallel to a slab gets a huge t of the right sign (or 0 on the slab's plane),
// which keeps every box the ray can touch (the filter may keep a few it cannot; never loses one).
struct RaySlabs {
  std::array<std::vector<float>, 3> origin, inverse;
  explicit RaySlabs(const RayStream& rays) {
    for (int a = 0; a < 3; ++a) {
      const float* o = rays.origin(a).data();
      const float* d = rays.direction(a).data();
      origin[a].assign(o, o + rays.size());
      inverse[a].resize(rays.size());
      for (std::size_t i = 0; i < rays.size(); ++i)
        inverse[a][i] = 1.0f / (d[i] == 0 ? std::copysign(1e-30f, d[i]) : d[i]);
    }
  }
  // keep[i] = 1 where ray i enters the box before limit[i]: a plain loop the compiler
  // vectorises.
  void enters(const Aabb& box, const float* limit, std::uint8_t* keep) const {
    const std::size_t n = origin[0].size();
    for (std::size_t i = 0; i < n; ++i) {
      float t0 = 0, t1 = limit[i];
      for (int a = 0; a < 3; ++a) {
        const float tn = (box.min[a] - origin[a][i]) * inverse[a][i];
        const float tf = (box.max[a] - origin[a][i]) * inverse[a][i];
        t0 = std::max(t0, std::min(tn, tf));
        t1 = std::min(t1, std::max(tn, tf));
      }
      keep[i] = t0 <= t1;
    }
  }
};

// Rays moved into a model's space, written in place by their owner: RayStream::push would
// validate each one again (they were validated entering the scene and an invertible affine map
// keeps them finite and non-zero). writable() reaches only the live rays, so the padding stays
// inert.
class ModelRays : public RayStream {
 public:
  void fill(const RayStream& rays, std::span<const std::uint32_t> pick, const Mat4f& inverse) {
    using F = fields::Ray;
    resize(pick.size());
    std::span<float> origin[3], direction[3];
    for (int a = 0; a < 3; ++a)
      origin[a] = writable(F::origin + a), direction[a] = writable(F::direction + a);
    const std::span<float> tMax = writable(F::tMax);
    for (std::size_t k = 0; k < pick.size(); ++k) {
      const std::uint32_t i = pick[k];
      const Vec3f o(rays.origin(0)[i], rays.origin(1)[i], rays.origin(2)[i]);
      const Vec3f d(rays.direction(0)[i], rays.direction(1)[i], rays.direction(2)[i]);
      const Vec3f lo = transformPoint(inverse, o), ld = transformDirection(inverse, d);
      for (int a = 0; a < 3; ++a) origin[a][k] = lo[a], direction[a][k] = ld[a];
      tMax[k] = std::numeric_limits<float>::infinity();
    }
  }
};

}  // namespace

void Scene::raycast(const RayStream& rays, std::span<ModelHit> out) const {
  requireUpToDate("Scene::raycast");
  if (out.size() != rays.size())
    throw Error("Scene::raycast: " + std::to_string(rays.size()) + " rays but room for " +
                std::to_string(out.size()) + " hits");
  // The closest t so far, per ray, beside the hits: the box filter reads it as a stream.
  std::vector<float> bestT(rays.tMax().data(), rays.tMax().data() + rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    out[i] = ModelHit{};
    out[i].t = bestT[i];
  }
  const RaySlabs slabs(rays);
  std::vector<std::uint8_t> keep(rays.size());
  std::vector<std::uint32_t> candidates;
  std::vector<MeshHit> meshHits;
  ModelRays local;
  for (std::uint32_t m = 0; m < size(); ++m) {
    const PlacedShape shape = placed(m);
    slabs.enters(bounds_[m], bestT.data(), keep.data());
    candidates.clear();
    for (std::uint32_t i = 0; i < rays.size(); ++i)
      if (keep[i]) candidates.push_back(i);
    auto offer = [&](std::uint32_t i, std::optional<ModelHit> hit) {
      if (!hit) return;
      hit->model = m;
      if (closer(*hit, out[i])) out[i] = *hit, bestT[i] = hit->t;
    };
    const auto* mesh = std::get_if<std::shared_ptr<const MeshBvh>>(&models_[m].shape);
    if (!mesh) {
      for (std::uint32_t i : candidates) offer(i, simdphys::raycast(shape, rays[i]));
      continue;
    }
    // A model placed at the origin unscaled (a terrain, typically) that most rays reach takes
    // the caller's stream as it is, saving the copy; the mesh's own tree rejects the others.
    const bool whole = inverse_[m] == Mat4f::Identity() && 2 * candidates.size() > rays.size();
    if (!whole) {
      // One stream in model space: t along the moved (not normalised) direction is world t.
      local.fill(rays, candidates, inverse_[m]);
    } else {
      candidates.resize(rays.size());
      for (std::uint32_t i = 0; i < rays.size(); ++i) candidates[i] = i;
    }
    meshHits.assign(candidates.size(), MeshHit{});
    (*mesh)->raycast(whole ? rays : local, meshHits);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (!meshHits[k].hit()) continue;
      const Vec3f n = (*mesh)->mesh().triangle(meshHits[k].id).normal();
      offer(candidates[k], worldHit(shape, rays[candidates[k]], meshHits[k].t, n, meshHits[k].id));
    }
  }
}

}  // namespace simdphys

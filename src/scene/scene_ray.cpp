// Scene raycasts: one ray through the top-level BVH, or a stream of rays model by model.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "simdphys/scene/scene.hpp"
#include "src/bvh/scalar_walk.hpp"

namespace simdphys {
namespace {

// The order of hits: the smaller t, then the smaller model index. A miss (model kNoModel) at the
// caller's tMax loses to a hit at the same t.
bool closer(const ModelHit& a, const ModelHit& b) {
  return a.t < b.t || (a.t == b.t && a.model < b.model);
}

// The scene's walk of its top-level tree (a box tree: one model a leaf), as the mesh's: the same
// node test, nearest box first, a box farther than the closest hit found since skipped. The world
// boxes are widened beyond rounding (transformBounds), so a model's hit is never before its box's
// entry.
class ModelRayCore {
 public:
  ModelRayCore(const Scene& scene, const Ray& ray, float tMax) : scene_(scene), ray_(ray) {
    detail::setSlabs(slabs_, ray.origin.x(), ray.origin.y(), ray.origin.z(), ray.direction.x(),
                     ray.direction.y(), ray.direction.z(), tMax);
    best_.t = tMax;
  }
  float bound() const { return best_.t; }
  int expand(const BvhNode& n, float bound, std::uint32_t* refs, float* dists) const {
    return reference::expandRay(n, slabs_, bound, refs, dists);
  }
  bool leaf(std::uint32_t ref) {
    const std::uint32_t m = BvhNode::leafFirst(ref);
    if (auto hit = simdphys::raycast(scene_.placed(m), ray_)) {
      hit->model = m;
      if (closer(*hit, best_)) best_ = *hit;
    }
    return false;
  }
  const ModelHit& best() const { return best_; }

 private:
  const Scene& scene_;
  const Ray& ray_;
  detail::TraversalRay slabs_;
  ModelHit best_;
};

}  // namespace

ModelHit Scene::raycast(const Ray& ray, float tMax) const {
  requireUpToDate("Scene::raycast");
  validate(ray, "Scene::raycast");
  if (!(tMax >= 0)) throw Error("Scene::raycast: tMax must be >= 0");
  ModelRayCore core(*this, ray, tMax);
  reference::traverseRay(bvh_.nodes().data(), bvh_.nodes().size(), core);
  return core.best();
}

namespace {

// The rays of a stream as the box filter reads them: origins and inverse directions, SoA.
struct RaySlabs {
  std::array<std::vector<float>, 3> origin, inverse;
  bool finite = true;  // every inverse finite: raySlab's Max/Min form
  explicit RaySlabs(const RayStream& rays) {
    for (int a = 0; a < 3; ++a) {
      const float* o = rays.origin(a).data();
      const float* d = rays.direction(a).data();
      origin[a].assign(o, o + rays.size());
      inverse[a].resize(rays.size());
      for (std::size_t i = 0; i < rays.size(); ++i) {
        inverse[a][i] = 1.0f / d[i];
        finite = finite && std::isfinite(inverse[a][i]);
      }
    }
  }
  // keep[i] = 1 where ray i enters the box before limit[i] (the walk's slab test, so it keeps
  // every box the ray can touch): a plain loop the compiler vectorises.
  void enters(const Aabb& box, const float* limit, std::uint8_t* keep) const {
    if (finite)
      enters<true>(box, limit, keep);
    else
      enters<false>(box, limit, keep);
  }
  template <bool kFinite>
  void enters(const Aabb& box, const float* limit, std::uint8_t* keep) const {
    const std::size_t n = origin[0].size();
    for (std::size_t i = 0; i < n; ++i) {
      float o[3], inv[3], enter;
      for (int a = 0; a < 3; ++a) o[a] = origin[a][i], inv[a] = inverse[a][i];
      // The near face by the direction's sign bit, that of its inverse (-0 gives -inf).
      auto faces = [&](int a, float& nearFace, float& farFace) {
        nearFace = inv[a] < 0 ? box.max[a] : box.min[a];
        farFace = inv[a] < 0 ? box.min[a] : box.max[a];
      };
      keep[i] =
          reference::raySlab<kFinite>(reference::ScalarLane{}, faces, o, inv, limit[i], enter);
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
  std::vector<ElementHit> meshHits;
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
    meshHits.assign(candidates.size(), ElementHit{});
    (*mesh)->raycast(whole ? rays : local, meshHits);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (!meshHits[k].hit()) continue;
      const Vec3f n = (*mesh)->mesh().triangle(meshHits[k].index).normal();
      offer(candidates[k],
            worldHit(shape, rays[candidates[k]], meshHits[k].t, n, meshHits[k].index));
    }
  }
}

}  // namespace simdphys

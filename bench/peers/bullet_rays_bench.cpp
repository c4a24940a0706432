// Peer: Bullet's btBvhTriangleMeshShape (Debian's libbullet-dev, single precision) on W2, the same
// mesh and rays as rays_bench.cpp: performRaycast with a btTriangleRaycastCallback that keeps the
// closest hit. Bullet casts segments, so each ray runs from its origin to origin + 1000 direction
// (the mesh lies within 400 of every origin); t = hit fraction x 1000. Its callback reports every
// triangle crossed and the closest is kept here, ties to the smaller id, as W2 asks; back faces
// count (kF_FilterBackfaces is off by default).
#include <limits>
#include <memory>

#include "bench/rays_common.hpp"

#include "bench/peers/bullet.hpp"

namespace simdphys::bench {
namespace {

constexpr float kLength = 1000;

class ClosestTriangle : public btTriangleRaycastCallback {
 public:
  using btTriangleRaycastCallback::btTriangleRaycastCallback;
  btScalar reportHit(const btVector3&, btScalar fraction, int, int triangle) override {
    if (fraction < best_ || (fraction == best_ && std::uint32_t(triangle) < id_))
      best_ = fraction, id_ = std::uint32_t(triangle);
    return best_;  // later triangles need only be tested up to the closest so far
  }
  ElementHit hit() const { return id_ == kNoHit ? ElementHit{} : ElementHit{id_, best_ * kLength}; }

 private:
  btScalar best_ = 1;
  std::uint32_t id_ = kNoHit;
};

class BulletMesh {
 public:
  explicit BulletMesh(const Mesh& mesh) {
    vertices_.reserve(3 * mesh.vertices.size());
    for (const Vec3f& v : mesh.vertices) vertices_.insert(vertices_.end(), {v.x(), v.y(), v.z()});
    for (const auto& t : mesh.triangles)
      indices_.insert(indices_.end(), {int(t[0]), int(t[1]), int(t[2])});
    array_ = std::make_unique<btTriangleIndexVertexArray>(
        int(mesh.size()), indices_.data(), 3 * int(sizeof(int)), int(mesh.vertices.size()),
        vertices_.data(), 3 * int(sizeof(float)));
  }
  void build() { shape_ = std::make_unique<btBvhTriangleMeshShape>(array_.get(), true, true); }
  // performRaycast is not const in Bullet, though it changes nothing.
  btBvhTriangleMeshShape& shape() const { return *shape_; }

 private:
  std::vector<float> vertices_;
  std::vector<int> indices_;
  std::unique_ptr<btTriangleIndexVertexArray> array_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
};

const BulletMesh& builtMesh() {
  static const std::unique_ptr<BulletMesh> m = [] {
    auto p = std::make_unique<BulletMesh>(raysWorkload().mesh);
    p->build();
    return p;
  }();
  return *m;
}

void registerBulletRays() {
  for (RaysKind kind : kRaysKinds) {
    registerOnce(raysTask(kind), "bullet_bvh_triangle_mesh", "peer", raysCount(kind),
                 [kind](benchmark::State& state) {
                   const RaySet& set = raySet(kind);
                   btBvhTriangleMeshShape& shape = builtMesh().shape();
                   std::vector<ElementHit> hits(set.rays.size());
                   for (auto _ : state) {
#pragma omp parallel for schedule(dynamic, 256)
                     for (std::int64_t j = 0; j < std::int64_t(set.rays.size()); ++j) {
                       const Ray r = set.rays[std::size_t(j)];
                       const btVector3 from = toBullet(r.origin);
                       const btVector3 to = from + kLength * toBullet(r.direction);
                       ClosestTriangle callback(from, to);
                       shape.performRaycast(&callback, from, to);
                       hits[std::size_t(j)] = callback.hit();
                     }
                     benchmark::DoNotOptimize(hits.data());
                   }
                   reportRays(state, set, hits, /*peer=*/true);
                 });
  }
  registerOnce("rays/build", "bullet_bvh_triangle_mesh", "peer", kRaysTriangles,
               [](benchmark::State& state) {
                 BulletMesh mesh(raysWorkload().mesh);
                 for (auto _ : state) mesh.build();
                 state.SetItemsProcessed(std::int64_t(state.iterations() * kRaysTriangles));
               });
}

const bool kRegistered = (registerBulletRays(), true);

}  // namespace
}  // namespace simdphys::bench

// Models and scenes: transforms and parents (hand-worked), validation, and raycasts against the
// models (through the BVH, as a stream, against brute force and against world-space oracles).
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "paths.hpp"
#include "scene_cases.hpp"
#include "simdphys/geometry3d/raycast.hpp"

namespace simdphys {
namespace {

using test::expectError;
using test::OnEveryPath;

Mat4f translation(float x, float y, float z) {
  return transform(Vec3f::Ones(), Mat3f::Identity(), Vec3f(x, y, z));
}

// ---- transforms and parents ------------------------------------------------------------------

TEST(SceneModels, ParentsComposeTransforms) {
  const float half = std::numbers::pi_v<float> / 2;
  Scene scene;
  // Parent: scale 2, a quarter turn about z, then to (10, 0, 0). Child: 1 along its parent's x.
  // Grandchild: 2 along the child's y.
  const auto parent = scene.add(
      {Sphere{Vec3f::Zero(), 1}, transform(Vec3f::Constant(2), rotationZ(half), Vec3f(10, 0, 0))});
  const auto child = scene.add({Sphere{Vec3f::Zero(), 1}, translation(1, 0, 0), parent});
  const auto grandchild = scene.add({Sphere{Vec3f::Zero(), 0.5f}, translation(0, 2, 0), child});
  scene.update();
  // By hand: the child's origin (1,0,0) is scaled to (2,0,0), turned to (0,2,0), moved to
  // (10,2,0). The grandchild's (0,2,0) in the child's frame is scaled to (0,4,0), turned to
  // (-4,0,0), plus the child's origin: (6,2,0). Tolerance: the quarter turn's cosine is -4.4e-8,
  // not 0, so coordinates carry errors of 1e-6 at magnitude 10; 1e-5 covers it.
  auto origin = [&](Handle m) { return transformPoint(scene.world(m), Vec3f::Zero()); };
  EXPECT_LT((origin(child) - Vec3f(10, 2, 0)).norm(), 1e-5f);
  EXPECT_LT((origin(grandchild) - Vec3f(6, 2, 0)).norm(), 1e-5f);
  // Scale reaches the grandchild: its radius 0.5 is 1 in the world, so a ray down -y from
  // (6, 10, 0) meets its top at y = 3: t = 7 (same tolerance). The parent and the child (world
  // radius 2 at x = 10) span x in [8, 12] and are missed.
  const ModelHit hit = scene.raycast({{6, 10, 0}, {0, -1, 0}});
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(hit.model, scene.index(grandchild));
  EXPECT_NEAR(hit.t, 7.0f, 1e-5f);
  EXPECT_LT((hit.normal - Vec3f(0, 1, 0)).norm(), 1e-5f);
}

TEST(SceneModels, ReparentingMovesTheSubtree) {
  Scene scene;
  const auto a = scene.add({Aabb{Vec3f::Constant(-1), Vec3f::Constant(1)}, translation(5, 0, 0)});
  const auto b = scene.add({Aabb{Vec3f::Constant(-1), Vec3f::Constant(1)}, translation(0, 0, 7)});
  const auto c = scene.add({Sphere{Vec3f::Zero(), 1}, translation(0, 3, 0), b});
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(0, 3, 7));  // exact sums
  scene.setParent(c, a);
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(5, 3, 0));
  scene.setParent(c, kNoParent);
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(0, 3, 0));
}

TEST(SceneModels, BadInputNamesWhatAndWhere) {
  Scene scene;
  Mat4f nan = Mat4f::Identity();
  nan(1, 3) = std::numeric_limits<float>::quiet_NaN();
  expectError([&] { scene.add({Sphere{Vec3f::Zero(), 1}, nan}); }, "model 0: transform(1, 3)");
  Mat4f flat = Mat4f::Identity();
  flat(2, 2) = 0;
  expectError([&] { scene.add({Sphere{Vec3f::Zero(), 1}, flat}); }, "singular");
  Mat4f projective = Mat4f::Identity();
  projective(3, 2) = -1;
  expectError([&] { scene.add({Sphere{Vec3f::Zero(), 1}, projective}); }, "not affine");
  expectError([&] { scene.add({Sphere{Vec3f::Zero(), -1}}); }, "model 0: radius");
  expectError([&] { scene.add({std::shared_ptr<const MeshBvh>()}); }, "mesh is null");
  expectError(
      [&] {
        scene.add({Sphere{Vec3f::Zero(), 1}, Mat4f::Identity(), Handle{3, 1}});
      },
      "parent 3 is out of range");
  const auto a = scene.add({Sphere{Vec3f::Zero(), 1}});
  const auto b = scene.add({Sphere{Vec3f::Zero(), 1}, Mat4f::Identity(), a});
  const auto c = scene.add({Sphere{Vec3f::Zero(), 1}, Mat4f::Identity(), b});
  expectError([&] { scene.setParent(a, c); },
              "model 0 would be its own ancestor (0 -> 2 -> 1 -> 0)");
  expectError([&] { scene.setParent(a, a); }, "own ancestor");
  expectError([&] { scene.setParent(a, Handle{9, 1}); }, "model 9 is out of range");
  expectError(
      [&] {
        scene.setTransform(Handle{7, 1}, Mat4f::Identity());
      },
      "model 7 is out of range");
  expectError([&] { scene.raycast({Vec3f::Zero(), Vec3f::UnitX()}); }, "call update() first");
  // A world matrix can leave the supported range though every local one is in it: named at
  // update (scale 1e10 twice gives 1e20 > kMaxCoordinate).
  Scene deep;
  const Mat4f huge = transform(Vec3f::Constant(1e10f), Mat3f::Identity(), Vec3f::Zero());
  const auto p = deep.add({Sphere{Vec3f::Zero(), 1}, huge});
  deep.add({Sphere{Vec3f::Zero(), 1}, huge, p});
  expectError([&] { deep.update(); }, "model 1 (world)");
}

// ---- handles and removal ---------------------------------------------------------------------

Model sphereAt(float x, Handle parent = kNoParent) {
  return {Sphere{Vec3f::Zero(), 1}, translation(x, 0, 0), parent};
}

TEST(SceneHandles, RemovalKeepsModelsDenseAndHandlesStable) {
  Scene scene;
  const Handle a = scene.add(sphereAt(0)), b = scene.add(sphereAt(10)), c = scene.add(sphereAt(20));
  EXPECT_EQ(scene.index(a), 0u);
  EXPECT_EQ(scene.index(c), 2u);
  scene.remove(a);  // the last model, c, takes index 0
  EXPECT_EQ(scene.size(), 2u);
  EXPECT_FALSE(scene.contains(a));
  EXPECT_TRUE(scene.contains(c));
  EXPECT_EQ(scene.index(c), 0u);
  EXPECT_EQ(scene.index(b), 1u);
  EXPECT_EQ(scene.handle(0), c);
  EXPECT_EQ(scene.handle(1), b);
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(20, 0, 0));
  EXPECT_EQ(transformPoint(scene.world(0u), Vec3f::Zero()), Vec3f(20, 0, 0));
  // A new model reuses the freed slot with the next generation: the old handle stays stale.
  const Handle d = scene.add(sphereAt(30));
  EXPECT_EQ(d.slot, a.slot);
  EXPECT_EQ(d.generation, a.generation + 1);
  EXPECT_EQ(scene.index(d), 2u);
  EXPECT_FALSE(scene.contains(a));
  expectError([&] { scene.setTransform(a, Mat4f::Identity()); },
              "Scene::setTransform: the handle (slot 0, generation 1) is stale");
  expectError([&] { scene.remove(a); },
              "Scene::remove: the handle (slot 0, generation 1) is stale");
  expectError([&] { scene.world(a); }, "Scene::world: the handle");
  expectError([&] { scene.setParent(d, a); }, "Scene::setParent (parent): the handle");
  expectError([&] { scene.add(sphereAt(0, a)); }, "Scene::add: model 3 (parent): the handle");
  expectError([&] { scene.index(Handle{}); }, "Scene::index: model 4294967295 is out of range");
  expectError([&] { scene.handle(3); }, "Scene::handle: model 3 is out of range (3 models)");
  EXPECT_EQ(scene.size(), 3u);  // the rejected calls changed nothing
  EXPECT_EQ(transformPoint(scene.model(d).transform, Vec3f::Zero()), Vec3f(30, 0, 0));
}

// After removals the structures are rebuilt: every query answers for the models left, by their
// new indices, whichever index answers it.
TEST(SceneHandles, QueriesAfterRemoval) {
  Scene scene;
  std::vector<Handle> handles;
  for (int i = 0; i < 12; ++i) handles.push_back(scene.add(sphereAt(10.0f * float(i))));
  scene.update();
  scene.remove(handles[3]);  // the model at x = 30; the one at x = 110 takes index 3
  scene.remove(handles[0]);  // x = 0; x = 100 takes index 0
  expectError([&] { scene.raycast({Vec3f::Zero(), Vec3f::UnitX()}); }, "call update() first");
  scene.update();
  ASSERT_EQ(scene.size(), 10u);
  EXPECT_EQ(scene.bounds().size(), 10u);
  for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh}) {
    SCOPED_TRACE("index " + std::to_string(int(via)));
    EXPECT_TRUE(scene.query(Aabb{{29, -1, -1}, {31, 1, 1}}, via).empty());  // removed
    EXPECT_TRUE(scene.query(Sphere{{0, 0, 0}, 0.5f}, via).empty());         // removed
    EXPECT_EQ(scene.query(Aabb{{109, -1, -1}, {111, 1, 1}}, via),
              std::vector<std::uint32_t>{scene.index(handles[11])});
    EXPECT_EQ(scene.query(Aabb{{-1, -1, -1}, {121, 1, 1}}, via).size(), 10u);
  }
  // A ray along x from x = -5 hits the nearest model left, at x = 10.
  const ModelHit hit = scene.raycast({{-5, 0, 0}, Vec3f::UnitX()});
  ASSERT_TRUE(hit.hit());
  EXPECT_EQ(scene.handle(hit.model), handles[1]);
  EXPECT_NEAR(hit.t, 14.0f, 1e-5f);  // the sphere's surface at x = 9
  // Removing every model leaves an empty scene that answers nothing.
  for (const Handle h : handles)
    if (scene.contains(h)) scene.remove(h);
  scene.update();
  EXPECT_EQ(scene.size(), 0u);
  EXPECT_FALSE(scene.raycast({{-5, 0, 0}, Vec3f::UnitX()}).hit());
}

TEST(SceneHandles, ParentsFollowTheirModelsAndCannotBeRemovedFirst) {
  Scene scene;
  const Handle a = scene.add(sphereAt(0)), p = scene.add(sphereAt(100));
  const Handle c = scene.add({Sphere{Vec3f::Zero(), 1}, translation(0, 5, 0), p});
  expectError([&] { scene.remove(p); },
              "Scene::remove: model 1 is the parent of model 2; remove or re-parent its children");
  EXPECT_EQ(scene.size(), 3u);
  scene.remove(a);  // c moves to index 0; its parent p stays at 1
  EXPECT_EQ(scene.index(c), 0u);
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(100, 5, 0));
  scene.setParent(c, kNoParent);
  scene.remove(p);
  scene.update();
  EXPECT_EQ(transformPoint(scene.world(c), Vec3f::Zero()), Vec3f(0, 5, 0));
}

// ---- raycasts --------------------------------------------------------------------------------

class SceneRays : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(SceneRays);

// Rays from random points towards random models: the BVH's answer is the brute-force loop over
// every model (same t to the bit, same model), and the stream's is the same.
TEST_P(SceneRays, BvhAndStreamEqualBruteForce) {
  test::RandomScene rs(60, 20, 41);
  const Scene& scene = rs.scene;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> pos(-30, 30);
  std::uniform_int_distribution<int> pickModel(0, int(scene.size()) - 1);
  RayStream stream;
  std::vector<Ray> rays;
  for (int i = 0; i < 400; ++i) {
    const Vec3f o(pos(rng), pos(rng), pos(rng));
    const Vec3f aim = transformPoint(scene.world(pickModel(rng)), Vec3f::Zero());
    // Most rays aim at a model; every fourth goes anywhere.
    const Vec3f d = i % 4 == 3 ? test::randomDirection(rng) : Vec3f((aim - o).normalized());
    rays.push_back({o, d});
    stream.push(rays.back());
  }
  std::vector<ModelHit> streamed(rays.size());
  scene.raycast(stream, streamed);
  int hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ModelHit brute;
    for (std::uint32_t m = 0; m < scene.size(); ++m) {
      auto h = raycast(scene.placed(m), rays[i]);
      if (h && (h->t < brute.t || (h->t == brute.t && m < brute.model))) {
        brute = *h;
        brute.model = m;
      }
    }
    const ModelHit viaBvh = scene.raycast(rays[i]);
    EXPECT_EQ(viaBvh.model, brute.model) << "ray " << i;
    EXPECT_EQ(viaBvh.t, brute.t) << "ray " << i;
    EXPECT_EQ(viaBvh.model, streamed[i].model) << "ray " << i;
    EXPECT_EQ(viaBvh.t, streamed[i].t) << "ray " << i;
    EXPECT_EQ(viaBvh.triangle, streamed[i].triangle) << "ray " << i;
    hits += viaBvh.hit();
  }
  EXPECT_GT(hits, 200);  // the aimed rays mostly hit: the comparison is not vacuous
}

// The same rays against each model rebuilt in world space from its placement, in double, by
// raycast.hpp alone (meshes: every triangle): an oracle that shares no code with the scene.
std::optional<RayHitd> worldOracle(const test::RandomScene& rs, std::uint32_t m, const Rayd& ray) {
  const test::Placement& p = rs.placements[m];
  const Mat3d r = axisAngle(p.axis.cast<double>(), double(p.angle));
  const double s = p.scale;
  const Vec3d t = p.translation.cast<double>();
  auto toWorld = [&](const Vec3f& v) -> Vec3d { return t + s * (r * v.cast<double>()); };
  auto first = [](auto h) { return h; };
  const ModelShape& shape = rs.scene.model(m).shape;
  if (const auto* mesh = std::get_if<std::shared_ptr<const MeshBvh>>(&shape)) {
    std::optional<RayHitd> best;
    for (std::size_t k = 0; k < (*mesh)->mesh().size(); ++k) {
      const Triangle tri = (*mesh)->mesh().triangle(k);
      const auto h = raycast(Triangled{toWorld(tri.a), toWorld(tri.b), toWorld(tri.c)}, ray);
      if (h && (!best || h->t < best->t)) best = h;
    }
    return best;
  }
  if (const auto* sphere = std::get_if<Sphere>(&shape))
    return first(raycast(Sphered{toWorld(sphere->center), s * sphere->radius}, ray));
  if (const auto* box = std::get_if<Aabb>(&shape))
    return first(
        raycast(Obbd{toWorld(box->center()), s * box->halfExtents().cast<double>(), r}, ray));
  const Obb& obb = std::get<Obb>(shape);
  return first(raycast(
      Obbd{toWorld(obb.center), s * obb.halfExtents.cast<double>(), r * obb.axes.cast<double>()},
      ray));
}

TEST_P(SceneRays, HitsMatchWorldSpaceOracles) {
  test::RandomScene rs(60, 20, 43);
  std::mt19937 rng(44);
  std::uniform_real_distribution<float> pos(-30, 30);
  std::uniform_int_distribution<int> pickModel(0, int(rs.scene.size()) - 1);
  int compared = 0, disagreements = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3f o(pos(rng), pos(rng), pos(rng));
    const Vec3f aim = rs.placements[pickModel(rng)].translation;
    const Ray ray{o, (aim - o).normalized()};
    const Rayd rayd = cast<double>(ray);
    double best = std::numeric_limits<double>::infinity(), second = best, slope = 1;
    std::uint32_t bestModel = kNoModel;
    for (std::uint32_t m = 0; m < rs.scene.size(); ++m) {
      const auto h = worldOracle(rs, m, rayd);
      if (!h) continue;
      if (h->t < best) {
        second = best, best = h->t, bestModel = m;
        slope = std::abs(h->normal.dot(rayd.direction));
      } else {
        second = std::min(second, h->t);
      }
    }
    // Two models within 1e-3 of each other along the ray: the float rounding of the transforms
    // (a few ulp of coordinates up to ~40, 1e-5) could order them either way; skip.
    if (second - best < 1e-3) continue;
    const ModelHit hit = rs.scene.raycast(ray);
    ++compared;
    if (hit.model != bestModel) {
      // A ray grazing a silhouette within the rounding of the float transform (1e-5 of the
      // coordinates) may hit in one precision and miss in the other; counted, not failed.
      ++disagreements;
      continue;
    }
    // t: the float path rounds the world matrix, its inverse and the moved ray, each a few eps
    // at coordinates up to ~60 (8 eps * 60 = 6e-5 of position); along the ray that grows as
    // 1 / |cos| of the angle to the surface normal. 1e-4 / |cos| leaves a margin; hits within
    // 0.6 degrees of grazing (|cos| < 0.01) are not compared.
    if (hit.hit() && slope >= 0.01) {
      EXPECT_NEAR(hit.t, best, 1e-4 / slope) << "ray " << i << " model " << hit.model;
    }
  }
  EXPECT_GT(compared, 300);
  // Grazing rays: the band of width ~1e-5 around each silhouette is ~1e-5 of a model's size, so
  // among 400 rays more than two such would mean a real fault.
  EXPECT_LE(disagreements, 2);
}

}  // namespace
}  // namespace simdphys

// Queries through the scene's structures: sphere, box and frustum queries through the octree
// and the BVH equal brute force over the models' boxes, also after models move; the octree and
// the BVH cull equal the flat cull on W6 and on frustums from many camera poses.
#include <gtest/gtest.h>

#include "paths.hpp"
#include "scene_cases.hpp"
#include "testing/cull_reference.hpp"
#include "workloads.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

std::vector<std::uint32_t> bruteCull(const Frustum& f, const BoundsStream& b) {
  std::vector<std::uint32_t> v;
  reference::cullBoxes(f, b.field(fields::Bounds::cx).view(), b.field(fields::Bounds::cy).view(),
                       b.field(fields::Bounds::cz).view(), b.field(fields::Bounds::ex).view(),
                       b.field(fields::Bounds::ey).view(), b.field(fields::Bounds::ez).view(), v);
  return v;
}

template <class Shape>
std::vector<std::uint32_t> bruteQuery(const Shape& shape, const BoundsStream& b) {
  std::vector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < b.size(); ++i)
    if (intersects(shape, b[i])) v.push_back(i);
  return v;
}

// Boxes of very different sizes (0.01 to 40 across) in [-100, 100]^3: many straddle octree
// cells, some are larger than the deepest cells.
BoundsStream mixedBoxes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-100, 100), logSize(-2, 1.3f);
  BoundsStream b;
  for (std::size_t i = 0; i < n; ++i)
    b.push(
        {pos(rng), pos(rng), pos(rng)},
        {std::pow(10.f, logSize(rng)), std::pow(10.f, logSize(rng)), std::pow(10.f, logSize(rng))});
  return b;
}

// Frustums from cameras at random places looking at random points, perspective and
// orthographic, some seeing everything and some nothing.
std::vector<Frustum> frustums(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> pos(-150, 150);
  std::vector<Frustum> out;
  for (int i = 0; i < 12; ++i) {
    const Vec3f eye(pos(rng), pos(rng), pos(rng)), target(pos(rng) / 3, pos(rng) / 3, pos(rng) / 3);
    out.push_back(
        i % 3 == 2
            ? Camera::orthographic(eye, target, Vec3f::UnitY(), 40, 16, 9, -10, 300).frustum()
            : Camera::perspective(eye, target, Vec3f::UnitY(), 0.3f + 0.2f * i, 16, 9, 0.5f,
                                  50.0f + 40.0f * i)
                  .frustum());
  }
  return out;
}

class SceneOctree : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(SceneOctree);

// The exact figure of workload W6 (102,099 boxes) through the octree and the BVH, on every path.
// The workload and its two trees depend on no path: built once, every path run in this process.
TEST(SceneOctreeW6, BoxesThroughOctreeAndBvhOnEveryPath) {
  const workloads::CullWorkload w = workloads::makeCullWorkload(1'000'000);
  const Octree octree(w.boxes);
  BoxStream boxes;
  for (std::size_t i = 0; i < w.boxes.size(); ++i) boxes.push(w.boxes[i]);
  const Bvh bvh(boxes);
  test::forEveryPath([&] {
    std::vector<std::uint32_t> flat, viaOctree, viaBvh;
    cull(w.frustum, w.boxes, flat);
    octree.cull(w.frustum, viaOctree);
    cull(w.frustum, bvh, w.boxes, viaBvh);
    EXPECT_EQ(flat.size(), workloads::kCullBoxesVisible);
    EXPECT_EQ(viaOctree, flat);
    EXPECT_EQ(viaBvh, flat);
  });
}

// Brute force depends on no path: computed once, every path run in this process.
TEST(SceneOctreeBruteForce, CullAndQueriesEqualBruteForceOnEveryPath) {
  const BoundsStream boxes = mixedBoxes(20'000, 7);
  BoxStream minMax;
  for (std::size_t i = 0; i < boxes.size(); ++i) minMax.push(boxes[i]);
  const std::vector<Frustum> views = frustums(8);
  std::vector<std::vector<std::uint32_t>> culled;
  for (const Frustum& f : views) culled.push_back(bruteCull(f, boxes));
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> pos(-120, 120), size(0, 30);
  std::vector<Sphere> spheres;
  std::vector<Aabb> aabbs;
  std::vector<std::vector<std::uint32_t>> inSphere, inBox;
  for (int q = 0; q < 50; ++q) {
    const Sphere s{{pos(rng), pos(rng), pos(rng)}, size(rng)};
    const Vec3f c(pos(rng), pos(rng), pos(rng)), h(size(rng), size(rng), size(rng));
    const Aabb box{c - h, c + h};
    spheres.push_back(s), aabbs.push_back(box);
    inSphere.push_back(bruteQuery(s, boxes)), inBox.push_back(bruteQuery(box, boxes));
  }
  test::forEveryPath([&] {
    for (const OctreeOptions& options :
         {OctreeOptions{}, OctreeOptions{4, 10}, OctreeOptions{1000, 2}}) {
      const Octree octree(boxes, options);
      const Bvh bvh(minMax);
      std::vector<std::uint32_t> viaOctree, viaBvh;
      for (std::size_t v = 0; v < views.size(); ++v) {
        octree.cull(views[v], viaOctree);
        cull(views[v], bvh, boxes, viaBvh);
        EXPECT_EQ(viaOctree, culled[v]) << "leaf size " << options.maxLeafSize;
        EXPECT_EQ(viaBvh, culled[v]);
      }
      for (std::size_t q = 0; q < spheres.size(); ++q) {
        EXPECT_EQ(octree.query(spheres[q]), inSphere[q]);
        EXPECT_EQ(octree.query(aabbs[q]), inBox[q]);
      }
    }
  });
}

// The book's update: moved boxes leave their old leaves and enter new ones, some far outside the
// root cell; the answers stay those of brute force over the new boxes.
TEST_P(SceneOctree, MovedBoxesAreFoundAtTheirNewPlace) {
  BoundsStream boxes = mixedBoxes(5'000, 10);
  Octree octree(boxes, {16, 8});
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> pos(-300, 300);
  std::vector<std::uint32_t> moved;
  BoundsStream next;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    Vec3f c(boxes.field(fields::Bounds::cx)[i], boxes.field(fields::Bounds::cy)[i],
            boxes.field(fields::Bounds::cz)[i]);
    const Vec3f h(boxes.field(fields::Bounds::ex)[i], boxes.field(fields::Bounds::ey)[i],
                  boxes.field(fields::Bounds::ez)[i]);
    if (i % 7 == 0) c = {pos(rng), pos(rng), pos(rng)}, moved.push_back(i);
    next.push(c, h);
  }
  octree.update(moved, next);
  EXPECT_GT(octree.outsideCount(), 0u);  // the test covers the outside list
  std::vector<std::uint32_t> visible;
  for (const Frustum& f : frustums(12)) {
    octree.cull(f, visible);
    EXPECT_EQ(visible, bruteCull(f, next));
  }
  for (std::uint32_t i : {0u, 7u, 700u}) {  // moved boxes, queried where they are now
    const Aabb at = next[i];
    const auto found = octree.query(at);
    EXPECT_TRUE(std::binary_search(found.begin(), found.end(), i)) << "box " << i;
    EXPECT_EQ(found, bruteQuery(at, next));
  }
}

class SceneQueries : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(SceneQueries);

TEST_P(SceneQueries, EveryIndexEqualsBruteForceBeforeAndAfterMoves) {
  test::RandomScene rs(300, 40, 21);
  Scene& scene = rs.scene;
  std::mt19937 rng(22);
  auto check = [&] {
    std::uniform_real_distribution<float> pos(-50, 50), size(0, 15);
    for (int q = 0; q < 30; ++q) {
      const Sphere s{{pos(rng), pos(rng), pos(rng)}, size(rng)};
      const Vec3f c(pos(rng), pos(rng), pos(rng)), h(size(rng), size(rng), size(rng));
      const Aabb box{c - h, c + h};
      for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh}) {
        EXPECT_EQ(scene.query(s, via), bruteQuery(s, scene.bounds()));
        EXPECT_EQ(scene.query(box, via), bruteQuery(box, scene.bounds()));
      }
    }
    std::vector<std::uint32_t> visible;
    for (const Frustum& f : frustums(23))
      for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh}) {
        scene.cull(f, visible, via);
        EXPECT_EQ(visible, bruteCull(f, scene.bounds()));
      }
  };
  check();
  // Move a third of the models, some far away; chain a few under moving parents.
  for (std::uint32_t i = 0; i < scene.size(); i += 3)
    scene.setTransform(scene.handle(i),
                       test::randomPlacement(rng, i % 2 ? 40.0f : 200.0f).matrix());
  for (std::uint32_t i = 4; i < 40; i += 5) scene.setParent(scene.handle(i), scene.handle(i - 3));
  scene.update();
  check();
}

// A model moved by its transform is hit and found where it is now, not where it was.
TEST(SceneMoves, ModelsAreFoundAtTheirNewPlace) {
  test::Meshes meshes;
  Scene scene;
  const auto box =
      scene.add({meshes.box, transform(Vec3f::Ones(), Mat3f::Identity(), Vec3f(0, 0, 0))});
  scene.add(
      {Sphere{Vec3f::Zero(), 1}, transform(Vec3f::Ones(), Mat3f::Identity(), Vec3f(50, 0, 0))});
  scene.update();
  const Ray down{{20, 10, 0}, {0, -1, 0}};
  EXPECT_FALSE(scene.raycast(down).hit());
  scene.setTransform(box, transform(Vec3f::Ones(), Mat3f::Identity(), Vec3f(20, 0, 0)));
  scene.update();
  const ModelHit hit = scene.raycast(down);
  EXPECT_EQ(hit.model, scene.index(box));
  EXPECT_EQ(hit.t, 9.5f);  // the box's top face at y = 0.5: exact in float
  EXPECT_FALSE(scene.raycast({{0, 10, 0}, {0, -1, 0}}).hit());
  const Sphere around{{20, 0, 0}, 1};
  for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh})
    EXPECT_EQ(scene.query(around, via), std::vector<std::uint32_t>{scene.index(box)});
}

}  // namespace
}  // namespace simdphys

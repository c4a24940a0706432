// The supported range (math.hpp: |coordinate| <= kMaxCoordinate) in the BVH, meshes,
// broadphases, octree, scene, camera and frustum, on every path: inside it exact answers at its
// edges, outside it an Error where the values enter (issue 11, section 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <random>

#include "expect_error.hpp"
#include "paths.hpp"
#include "simdphys/broadphase.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "simdphys/scene/octree.hpp"
#include "simdphys/scene/scene.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

constexpr float kRange = kMaxCoordinate;

class RangeScene : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(RangeScene);

// A coordinate uniform over the range, and a size log-uniform from 1e-3 to the whole range, so
// boxes of every scale meet.
struct RangeRandom {
  std::mt19937 rng;
  explicit RangeRandom(unsigned seed) : rng(seed) {}
  float coordinate() { return std::uniform_real_distribution<float>(-kRange, kRange)(rng); }
  float size() { return std::pow(10.0f, std::uniform_real_distribution<float>(-3, 18)(rng)); }
  // An interval of that size around a random coordinate, cut to the range.
  std::pair<float, float> interval() {
    const float c = coordinate(), h = size();
    return {std::max(c - h, -kRange), std::min(c + h, kRange)};
  }
  Aabb box() {
    Aabb b;
    for (int a = 0; a < 3; ++a) std::tie(b.min[a], b.max[a]) = interval();
    return b;
  }
};

Mesh rangeHeightfield() {
  // y = 0.9e18 sin(x / 3e17) cos(z / 3e17) over the whole range in x and z (in double, so the
  // heights are inside the range too).
  return heightfieldMesh(16, 16, -kRange, kRange, -kRange, kRange, [](double x, double z) {
    return 0.9e18 * std::sin(x / 3e17) * std::cos(z / 3e17);
  });
}

// The ids of the triangles the shape intersects, by testing each one: what a query must return.
template <class Shape>
std::vector<std::uint32_t> bruteOverlaps(const Mesh& m, const Shape& s) {
  std::vector<std::uint32_t> ids;
  for (std::uint32_t i = 0; i < m.size(); ++i)
    if (intersects(m.triangle(i), s)) ids.push_back(i);
  return ids;
}

// ---- mesh BVH overlap queries -------------------------------------------------------------------

// Issue 11's crash: a query box of +-FLT_MAX, or a sphere of radius 3e38, widened to infinity,
// let empty slots pass and read them as leaves. Now such a query is out of range: an Error.
TEST_P(RangeScene, MeshOverlapRejectsQueriesOutsideTheRange) {
  const MeshBvh m(heightfieldMesh(16, 16, 0, 10, 0, 10, [](double, double) { return 0.0; }));
  const Vec3f big = Vec3f::Constant(FLT_MAX);
  test::expectError([&] { m.overlapping(Aabb{-big, big}); }, "MeshBvh::overlapping(Aabb)");
  test::expectError(
      [&] {
        m.overlapping(Sphere{{0, 0, 0}, 3e38f});
      },
      "MeshBvh::overlapping(Sphere)");
  test::expectError(
      [&] {
        m.overlapping(Obb{{0, 0, 0}, Vec3f::Constant(1e38f)});
      },
      "MeshBvh::overlapping(Obb)");
  test::expectError(
      [&] {
        m.overlapping(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 0, 2e38f}});
      },
      "MeshBvh::overlapping(Triangle)");
  test::expectError(
      [&] {
        m.linecast(Segment{{-1e20f, 1, 1}, {1e20f, 1, 1}});
      },
      "MeshBvh::linecast");
  test::expectError(
      [&] {
        m.linetest(Segment{{-1e20f, 1, 1}, {1e20f, 1, 1}});
      },
      "MeshBvh::linetest");
}

TEST(RangeMesh, VerticesOutsideTheRangeAreRejected) {
  Mesh m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2e38f, 0, 0}}, {{0, 1, 2}, {1, 3, 2}}};
  test::expectError([&] { MeshBvh b(m); }, "MeshBvh: vertex 3: position");
  m.vertices[3] = {0, 0, -1.01e18f};
  test::expectError([&] { MeshBvh b(m); }, "vertex 3");
  m.vertices[3] = {1e18f, -1e18f, 1e18f};  // the range's corner is inside
  EXPECT_NO_THROW(MeshBvh b(m));
  test::expectError(
      [] { heightfieldMesh(4, 4, 0, 1, 0, 1, [](double x, double) { return x * 1e19; }); },
      "heightfieldMesh: vertex 1");
  test::expectError([] { sphereMesh({0, 0, 0}, 1e20f, 4, 8); }, "sphereMesh: vertex 0");
  const MeshBvh ok(m);
  std::vector<Vec3f> moved = m.vertices;
  moved[2] = {0, 3e38f, 0};
  MeshBvh b = ok;
  test::expectError([&] { b.refit(moved); }, "MeshBvh::refit: vertex 2");
}

// A mesh over the whole range: queries of every size, up to the whole range, equal brute force.
TEST_P(RangeScene, MeshOverlapAtTheRangeEdgesEqualsBruteForce) {
  const Mesh mesh = rangeHeightfield();
  const MeshBvh bvh(mesh);
  const Aabb all{Vec3f::Constant(-kRange), Vec3f::Constant(kRange)};
  std::vector<std::uint32_t> every(mesh.size());
  for (std::uint32_t i = 0; i < mesh.size(); ++i) every[i] = i;
  EXPECT_EQ(bvh.overlapping(all), every);  // the range holds every triangle
  // The largest sphere in range, and the sphere tests through the tree against the test per
  // triangle.
  const Sphere largest{{0, 0, 0}, kRange};
  EXPECT_EQ(bvh.overlapping(largest), bruteOverlaps(mesh, largest));
  RangeRandom r(7);
  for (int q = 0; q < 200; ++q) {
    const Aabb b = r.box();
    ASSERT_EQ(bvh.overlapping(b), bruteOverlaps(mesh, b)) << q;
    // A sphere must lie in range as a whole: its radius at most the centre's distance to the edge.
    const Vec3f c = b.center();
    const Sphere s{c, std::min(r.size(), kRange - c.cwiseAbs().maxCoeff())};
    ASSERT_EQ(bvh.overlapping(s), bruteOverlaps(mesh, s)) << q;
  }
}

// ---- linecast across the range ------------------------------------------------------------------

// A square in the plane x = 5e17 spanning the range in y and z; a segment across the whole range
// in x meets it 1.5e18 from its start.
TEST_P(RangeScene, LinecastAcrossTheRange) {
  const Mesh wall{{{5e17f, -kRange, -kRange},
                   {5e17f, kRange, -kRange},
                   {5e17f, kRange, kRange},
                   {5e17f, -kRange, kRange}},
                  {{0, 1, 2}, {0, 2, 3}}};
  const MeshBvh bvh(wall);
  const ElementHit h = bvh.linecast(Segment{{-kRange, 3e17f, -2e17f}, {kRange, 3e17f, -2e17f}});
  ASSERT_TRUE(h.hit());
  // t = 0.75 of the segment (a few roundings of the watertight test, each 2^-24 relative) times
  // its length 2e18 (exact): 4 ulp of the answer.
  EXPECT_NEAR(h.t, 1.5e18f, 4 * 1.5e18f * FLT_EPSILON);
  EXPECT_TRUE(bvh.linetest(Segment{{-kRange, 3e17f, -2e17f}, {kRange, 3e17f, -2e17f}}));
  EXPECT_FALSE(bvh.linecast(Segment{{-kRange, 3e17f, -2e17f}, {4e17f, 3e17f, -2e17f}}).hit());
  // Along the diagonal of the range: it crosses x = 5e17 at 0.75 of its length, 0.75 * 2e18 sqrt 3.
  const ElementHit d = bvh.linecast(Segment{Vec3f::Constant(-kRange), Vec3f::Constant(kRange)});
  ASSERT_TRUE(d.hit());
  const float want = float(0.75 * 2e18 * std::sqrt(3.0));
  // The length sqrt(3) 2e18 adds a rounding of its own: 8 ulp.
  EXPECT_NEAR(d.t, want, 8 * want * FLT_EPSILON);
}

// ---- broadphases over the whole range -----------------------------------------------------------

TEST_P(RangeScene, PairsOverTheWholeRangeEqualBruteForce) {
  RangeRandom r(11);
  BoxStream boxes;
  std::vector<Aabb> list;
  for (int i = 0; i < 3000; ++i) list.push_back(r.box());
  // The whole range, and boxes at its corners.
  list.push_back({Vec3f::Constant(-kRange), Vec3f::Constant(kRange)});
  list.push_back({Vec3f::Constant(kRange), Vec3f::Constant(kRange)});
  list.push_back({Vec3f::Constant(-kRange), Vec3f::Constant(-kRange)});
  for (const Aabb& b : list) boxes.push(b);
  std::vector<Pair> want;
  for (std::uint32_t i = 0; i < list.size(); ++i)
    for (std::uint32_t j = i + 1; j < list.size(); ++j)
      if ((list[i].min.array() <= list[j].max.array()).all() &&
          (list[j].min.array() <= list[i].max.array()).all())
        want.push_back({i, j});
  ASSERT_GT(want.size(), list.size());  // the set is not trivially sparse
  for (PairMethod m : {PairMethod::kGridSweep, PairMethod::kSweep, PairMethod::kBvh}) {
    std::vector<Pair> pairs;
    findPairs(boxes, pairs, m);
    std::sort(pairs.begin(), pairs.end());
    EXPECT_EQ(pairs, want) << "method " << int(m);
  }
}

TEST_P(RangeScene, Pairs2dOverTheWholeRangeEqualBruteForce) {
  RangeRandom r(13);
  RectStream rects;
  std::vector<Rect> list;
  for (int i = 0; i < 3000; ++i) {
    Rect q;
    for (int a = 0; a < 2; ++a) std::tie(q.min[a], q.max[a]) = r.interval();
    list.push_back(q);
  }
  list.push_back({Vec2f::Constant(-kRange), Vec2f::Constant(kRange)});
  list.push_back({Vec2f::Constant(kRange), Vec2f::Constant(kRange)});
  for (const Rect& q : list) rects.push(q);
  std::vector<Pair> want;
  for (std::uint32_t i = 0; i < list.size(); ++i)
    for (std::uint32_t j = i + 1; j < list.size(); ++j)
      if ((list[i].min.array() <= list[j].max.array()).all() &&
          (list[j].min.array() <= list[i].max.array()).all())
        want.push_back({i, j});
  ASSERT_GT(want.size(), list.size());
  for (PairMethod2d m : {PairMethod2d::kBandedSweep, PairMethod2d::kSweep, PairMethod2d::kBrute}) {
    std::vector<Pair> pairs;
    findPairs(rects, pairs, m);
    EXPECT_EQ(pairs, want) << "method " << int(m);  // sorted by contract
  }
}

// ---- the octree at the range's edges ------------------------------------------------------------

TEST_P(RangeScene, OctreeAtTheRangeEdgesEqualsBruteForce) {
  RangeRandom r(17);
  BoundsStream bounds;
  std::vector<Aabb> list;
  for (int i = 0; i < 2000; ++i) list.push_back(r.box());
  list.push_back({Vec3f::Constant(kRange), Vec3f::Constant(kRange)});
  list.push_back({Vec3f::Constant(-kRange), Vec3f::Constant(-kRange)});
  // Centre and half extents of each box; where c + h rounds one ulp past the range's edge (a
  // BoundsStream holds only boxes in range), the half extent one ulp less.
  for (const Aabb& b : list) {
    const Vec3f c = b.min * 0.5f + b.max * 0.5f;
    Vec3f h = b.max * 0.5f - b.min * 0.5f;
    for (int a = 0; a < 3; ++a)
      while (std::abs(c[a]) + h[a] > kRange) h[a] = std::nextafter(h[a], 0.0f);
    bounds.push(c, h);
  }
  const Octree tree(bounds, {8, 8});
  for (int q = 0; q < 200; ++q) {
    const Aabb b = q == 0 ? Aabb{Vec3f::Constant(-kRange), Vec3f::Constant(kRange)} : r.box();
    std::vector<std::uint32_t> want;
    for (std::uint32_t i = 0; i < list.size(); ++i)
      if (overlaps(bounds[i], b)) want.push_back(i);
    if (q == 0) {
      ASSERT_EQ(want.size(), list.size());
    }
    ASSERT_EQ(tree.query(b), want) << q;
  }
}

Mat4f moved(const Vec3f& t) { return transform(Vec3f::Ones(), Mat3f::Identity(), t); }

// ---- bad arguments ------------------------------------------------------------------------------

// A stream's directions may have any non-zero length, as in MeshBvh: t is in units of the
// direction, on every kind of model, so a ray of direction 2u hits at half the t of u.
TEST_P(RangeScene, SceneStreamRaycastHonoursTheDirectionUnits) {
  Scene scene;
  scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(10, 0, 0))});
  scene.add({Aabb{{-1, -1, -1}, {1, 1, 1}}, moved(Vec3f(0, 10, 0))});
  scene.add({Obb{{0, 0, 0}, {1, 1, 1}}, moved(Vec3f(0, 0, 10))});
  scene.add({std::make_shared<const MeshBvh>(boxMesh({{-1, -1, -1}, {1, 1, 1}})),
             moved(Vec3f(-10, 0, 0))});
  scene.update();
  // A mesh at the origin, unscaled, that most rays reach: the stream is cast as it is.
  Scene terrain;
  terrain.add({std::make_shared<const MeshBvh>(boxMesh({{-1, -1, -1}, {1, 1, 1}}))});
  terrain.update();
  const Vec3f axes[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}};
  for (float length : {0.5f, 1.0f, 4.0f}) {
    RayStream rays;
    for (const Vec3f& a : axes) rays.push(Ray{a * 20, -a * length});  // towards the mesh
    std::vector<ModelHit> toMesh(rays.size());
    terrain.raycast(rays, toMesh);
    for (std::uint32_t m = 0; m < 4; ++m) {
      ASSERT_EQ(toMesh[m].model, 0u);
      EXPECT_EQ(toMesh[m].t, 19 / length) << "axis " << m << ", length " << length;
    }
    rays = RayStream();
    for (const Vec3f& a : axes) rays.push(Ray{{0, 0, 0}, a * length});
    std::vector<ModelHit> hits(rays.size());
    scene.raycast(rays, hits);
    for (std::uint32_t m = 0; m < 4; ++m) {
      ASSERT_EQ(hits[m].model, m) << length;
      // Each model's near face is 9 from the origin: t = 9 / length (exact: length is a power
      // of 2), the point on the face.
      EXPECT_EQ(hits[m].t, 9 / length) << "model " << m << ", length " << length;
      EXPECT_EQ(hits[m].point, axes[m] * 9) << "model " << m << ", length " << length;
    }
  }
}

// A camera's frustum at the origin looking down -z, and spheres around it, some in view.
Mat4f cameraMatrix() {
  return perspective(1.0f, 1.5f, 0.5f, 100.0f) *
         lookAt(Vec3f(0, 0, 0), Vec3f(0.1f, -0.2f, -1), Vec3f(0, 1, 0));
}
SphereStream spheresAround() {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> pos(-120, 120), radius(0.1f, 3);
  SphereStream s;
  for (int i = 0; i < 5000; ++i) s.push({{pos(rng), pos(rng), pos(rng)}, radius(rng)});
  return s;
}

TEST_P(RangeScene, CullRejectsAnInvalidFrustum) {
  const Frustum good = Frustum::fromMatrix(cameraMatrix());
  const SphereStream spheres = spheresAround();
  BoundsStream boxes;
  for (std::size_t i = 0; i < spheres.size(); ++i)
    boxes.push(spheres[i].center, Vec3f::Constant(spheres[i].radius));
  const Octree octree(boxes);
  const Bvh bvh([&] {
    BoxStream b;
    for (std::size_t i = 0; i < boxes.size(); ++i) b.push(boxes[i]);
    return b;
  }());
  Frustum nanNormal = good, infD = good, longNormal = good;
  nanNormal.planes[2].normal.x() = std::numeric_limits<float>::quiet_NaN();
  infD.planes[4].d = std::numeric_limits<float>::infinity();
  longNormal.planes[1].normal *= 2;  // the tests read n.p + d as a distance: n must be unit
  std::vector<std::uint32_t> visible{7};
  test::expectError([&] { cull(nanNormal, spheres, visible); },
                    "cull(SphereStream): frustum plane 2: normal.x");
  test::expectError([&] { cull(infD, boxes, visible); }, "cull(BoundsStream): frustum plane 4: d");
  test::expectError([&] { cull(longNormal, spheres, visible); }, "frustum plane 1: normal");
  test::expectError([&] { octree.cull(nanNormal, visible); }, "Octree::cull: frustum plane 2");
  test::expectError([&] { cull(infD, bvh, boxes, visible); }, "cull(Bvh): frustum plane 4");
  EXPECT_EQ(visible, std::vector<std::uint32_t>{7});  // untouched
  Scene scene;
  scene.add({Sphere{{0, 0, -5}, 1}});
  scene.update();
  for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh})
    test::expectError([&] { scene.cull(nanNormal, visible, via); }, "frustum plane 2");
}

// Issue 11: a valid matrix scaled by 1e20 or 1e-25 was rejected (a plane normal's length over-
// or underflowed). The planes are scale-free: the same objects are culled.
TEST_P(RangeScene, FrustumFromAScaledMatrixCullsTheSame) {
  const SphereStream spheres = spheresAround();
  std::vector<std::uint32_t> want, got;
  cull(Frustum::fromMatrix(cameraMatrix()), spheres, want);
  ASSERT_GT(want.size(), 10u);
  ASSERT_LT(want.size(), spheres.size() / 2);
  for (float scale : {1e20f, 1e-25f, 1e30f, 1e-30f}) {
    const Mat4f scaled = cameraMatrix() * scale;
    cull(Frustum::fromMatrix(scaled), spheres, got);
    EXPECT_EQ(got, want) << scale;
  }
}

TEST(RangeCamera, ProjectionsRejectParametersGivingANonFiniteMatrix) {
  test::expectError([] { perspective(1.0f, 1e-40f, 0.1f, 10.0f); }, "perspective: fovY 1");
  test::expectError([] { perspective(1e-39f, 1.0f, 0.1f, 10.0f); }, "non-finite or vanishing");
  test::expectError([] { orthographic(-FLT_MAX, FLT_MAX, -1.0f, 1.0f, 0.1f, 10.0f); },
                    "orthographic: left");
  test::expectError([] { orthographic(0.0f, 1e-40f, -1.0f, 1.0f, 0.1f, 10.0f); },
                    "non-finite or vanishing");
  const Vec3f far = Vec3f::Constant(0.9f * FLT_MAX);
  test::expectError([&] { lookAt(far, Vec3f::Zero(), Vec3f::UnitY()); }, "lookAt: eye");
  // In double the same parameters are fine.
  EXPECT_TRUE(perspective(1.0, 1e-40, 0.1, 10.0).allFinite());
  // And the range's edges in float.
  EXPECT_TRUE(orthographic(-kRange, kRange, -kRange, kRange, -kRange, kRange).allFinite());
  EXPECT_TRUE(
      lookAt(Vec3f::Constant(kRange), Vec3f::Constant(-kRange), Vec3f::UnitY()).allFinite());
}

TEST(RangeScene, ModelTransformsOutsideTheRangeAreRejected) {
  Scene scene;
  const auto scaled = [](float s) {
    return transform(Vec3f(1, s, 1), Mat3f::Identity(), Vec3f::Zero());
  };
  test::expectError(
      [&] {
        scene.add({Sphere{{0, 0, 0}, 1}, scaled(1e-39f)});
      },
      "model 0: transform's scale along axis 1 is");
  test::expectError([&] { scene.add({Sphere{{0, 0, 0}, 1}, scaled(1e-19f)}); }, "axis 1");
  test::expectError([&] { scene.add({Sphere{{0, 0, 0}, 1}, scaled(2e18f)}); }, "axis 1");
  test::expectError(
      [&] {
        scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(0, 0, -2e18f))});
      },
      "model 0: transform's translation z");
  EXPECT_EQ(scene.size(), 0u);
  // The edges of the range are accepted, and a model scaled by kMinScale is hit.
  scene.add({Sphere{{0, 0, 0}, 1e18f}, scaled(kMinScale)});
  scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(0, 0, -kRange))});
  scene.update();
  // The first model is a 2e18 x 2 x 2e18 ellipsoid: a ray down -y from y = 5 meets it at y = 1.
  const ModelHit h = scene.raycast(Ray{{0, 5, 0}, {0, -1, 0}});
  EXPECT_EQ(h.model, 0u);
  // Within a few roundings of the scaled hit (the radius 1e18 times 1e-18 is 1 to 1 ulp; the
  // ray's t through the inverse transform adds a few more): 8 ulp of 4.
  EXPECT_NEAR(h.t, 4.0f, 8 * 4 * FLT_EPSILON);
}

// ---- scene queries with far-apart shapes --------------------------------------------------------

TEST_P(RangeScene, SceneQueriesAcrossTheRange) {
  Scene scene;
  const float edge = kRange - 1e12f;  // unit spheres just inside the range, 2e18 apart
  scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(-edge, 0, 0))});
  scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(edge, 0, 0))});
  scene.add({Sphere{{0, 0, 0}, 1}, moved(Vec3f(0, -edge, edge))});
  scene.update();
  for (SceneIndex via : {SceneIndex::kFlat, SceneIndex::kOctree, SceneIndex::kBvh}) {
    SCOPED_TRACE(int(via));
    EXPECT_EQ(scene.query(Sphere{{-edge, 0, 0}, 2}, via), std::vector<std::uint32_t>{0});
    EXPECT_EQ(scene.query(Sphere{{edge, 0, 0}, 2}, via), std::vector<std::uint32_t>{1});
    EXPECT_EQ(scene.query(Aabb{{edge - 2, -2, -2}, {edge + 2, 2, 2}}, via),
              std::vector<std::uint32_t>{1});
    EXPECT_EQ(scene.query(Sphere{{0, 0, 0}, 1e17f}, via), std::vector<std::uint32_t>{});
    const Aabb all{Vec3f::Constant(-kRange), Vec3f::Constant(kRange)};
    EXPECT_EQ(scene.query(all, via), (std::vector<std::uint32_t>{0, 1, 2}));
    test::expectError([&] { scene.query(Sphere{{0, 0, 0}, -1}, via); }, "Scene::query: radius");
    test::expectError([&] { scene.query(Aabb{{1, 0, 0}, {0, 1, 1}}, via); }, "Scene::query: min.x");
  }
}

}  // namespace
}  // namespace simdphys

// Mesh queries other than rays, on every path: segments, overlap with every shape, refit; the
// tree's structure over triangles; procedural meshes; and the errors meshes report.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "expect_error.hpp"
#include "mesh_oracles.hpp"
#include "paths.hpp"
#include "rays.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

class MeshQueries : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(MeshQueries);

// Every triangle is in exactly one leaf, leaves hold 1..8, each block lane holds its triangle's
// vertices, and every slot box contains what is below it.
TEST_P(MeshQueries, TreeStructureOverTriangles) {
  const Mesh soup = test::randomSoup(51, 5000, 60, 3);
  const MeshBvh bvh(soup);
  const Bvh& tree = bvh.bvh();
  std::vector<int> seen(soup.size(), 0);
  std::size_t leaves = 0;
  for (const BvhNode& n : tree.nodes())
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t c = n.child[k];
      if (c == BvhNode::kEmpty || !BvhNode::isLeaf(c)) continue;
      const std::uint32_t first = BvhNode::leafFirst(c), count = BvhNode::leafCount(c);
      ASSERT_LE(count, MeshBvh::kLeafSize);
      ++leaves;
      const std::uint32_t lane = first % TriangleBlock::kWidth;
      ASSERT_LE(lane + count, TriangleBlock::kWidth) << "a leaf lies within one block";
      const TriangleBlock& b = bvh.blocks()[first / TriangleBlock::kWidth];
      for (std::uint32_t l = lane; l < lane + count; ++l) {
        const std::uint32_t id = tree.order()[first - lane + l];
        ASSERT_EQ(b.id[l], id);
        ++seen[id];
        const Triangle t = soup.triangle(id);
        for (const Vec3f& v : {t.a, t.b, t.c}) {
          EXPECT_LE(n.minX[k], v.x());
          EXPECT_GE(n.maxX[k], v.x());
          EXPECT_LE(n.minY[k], v.y());
          EXPECT_GE(n.maxY[k], v.y());
          EXPECT_LE(n.minZ[k], v.z());
          EXPECT_GE(n.maxZ[k], v.z());
        }
        EXPECT_EQ(b.v[2][1][l], t.c.y());
      }
    }
  for (std::size_t i = 0; i < soup.size(); ++i) ASSERT_EQ(seen[i], 1) << "triangle " << i;
  // Leaves share blocks (Bvh::build packs them): fewer blocks than leaves.
  EXPECT_LT(bvh.blocks().size(), leaves);
  EXPECT_LE(tree.depth(), BvhNode::kMaxDepth);
  // Each child node's leafSpan names exactly its own leaves' blocks (walks prefetch them by it).
  int spans = 0;
  for (const BvhNode& n : tree.nodes())
    for (int k = 0; k < BvhNode::kWidth; ++k) {
      const std::uint32_t c = n.child[k];
      if (c == BvhNode::kEmpty || BvhNode::isLeaf(c)) {
        EXPECT_EQ(n.leafSpan[k], BvhNode::kEmpty);
        continue;
      }
      std::vector<std::uint32_t> blocks;
      for (std::uint32_t g : tree.nodes()[c].child)
        if (g != BvhNode::kEmpty && BvhNode::isLeaf(g)) blocks.push_back(TriangleBlock::of(g));
      std::sort(blocks.begin(), blocks.end());
      blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
      if (blocks.empty()) {
        EXPECT_EQ(n.leafSpan[k], BvhNode::kEmpty);
        continue;
      }
      ASSERT_NE(n.leafSpan[k], BvhNode::kEmpty) << "a node's leaves lie together";
      ++spans;
      const std::uint32_t first = BvhNode::leafFirst(n.leafSpan[k]);
      ASSERT_EQ(BvhNode::leafCount(n.leafSpan[k]), blocks.size());
      for (std::size_t b = 0; b < blocks.size(); ++b) EXPECT_EQ(blocks[b], first + b);
    }
  EXPECT_GT(spans, 0);
}

// Segments, overlaps and refit against brute force on every path: brute force depends on no path,
// so it is computed once and every path is run in this process.
TEST(MeshQueries, SegmentsEqualBruteForceOnEveryPath) {
  const Mesh soup = test::randomSoup(52, 2000, 30, 4);
  workloads::Random r(53);
  std::vector<Segment> segments;
  std::vector<ElementHit> expected;
  std::vector<bool> crosses;
  for (int i = 0; i < 1500; ++i) {
    const Vec3f a(r.uniform(-35, 35), r.uniform(-35, 35), r.uniform(-35, 35));
    const Vec3f b = a + r.uniform(0, 20) * r.unitDirection();
    const Segment s{a, b};
    // Brute force: raycast.hpp's linecast per triangle (t a distance), the same rule.
    std::vector<ElementHit> hits;
    for (std::uint32_t k = 0; k < soup.size(); ++k)
      if (auto h = linecast(soup.triangle(k), s)) hits.push_back({k, h->t});
    bool any = false;
    for (std::uint32_t k = 0; k < soup.size() && !any; ++k) any = linetest(soup.triangle(k), s);
    segments.push_back(s), expected.push_back(test::closestByRule(hits)), crosses.push_back(any);
  }
  EXPECT_GT(std::count(crosses.begin(), crosses.end(), true), 50);
  test::forEveryPath([&] {
    const MeshBvh bvh(soup);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const ElementHit found = bvh.linecast(segments[i]);
      EXPECT_EQ(found.index, expected[i].index) << "segment " << i;
      // t: the tree's t (in units of b - a) times the length, against the per-triangle
      // linecast's same product: exact.
      if (expected[i].hit()) {
        EXPECT_EQ(found.t, expected[i].t) << "segment " << i;
      }
      EXPECT_EQ(bvh.linetest(segments[i]), crosses[i]) << "segment " << i;
    }
    // A segment lying in a triangle's plane, inside it: no crossing, but the linetest touches.
    Mesh flat;
    flat.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 0, 4}};
    flat.triangles = {{0, 1, 2}};
    const MeshBvh one(flat);
    const Segment inPlane{{0.5f, 0, 0.5f}, {1.5f, 0, 0.5f}};
    EXPECT_FALSE(one.linecast(inPlane).hit());
    EXPECT_TRUE(one.linetest(inPlane));
  });
}

TEST(MeshQueries, OverlapsEqualBruteForceOnEveryPath) {
  const Mesh soup = test::randomSoup(54, 3000, 40, 3);
  struct Query {
    Sphere sphere;
    Aabb box;
    Obb obb;
    Triangle tri;
    std::vector<std::uint32_t> expected[4];  // sphere, box, obb, triangle
  };
  workloads::Random r(55);
  std::vector<Query> queries;
  std::size_t found = 0;
  for (int i = 0; i < 200; ++i) {
    const Vec3f c(r.uniform(-45, 45), r.uniform(-45, 45), r.uniform(-45, 45));
    const Sphere sphere{c, r.uniform(0, 6)};
    const Vec3f h(r.uniform(0, 5), r.uniform(0, 5), r.uniform(0, 5));
    const Aabb box{c - h, c + h};
    const Obb obb{c, h, Eigen::AngleAxisf(r.uniform(0, 3), r.unitDirection()).toRotationMatrix()};
    const Triangle tri{c + 5 * r.unitDirection(), c + 5 * r.unitDirection(),
                       c + 5 * r.unitDirection()};
    queries.push_back({sphere,
                       box,
                       obb,
                       tri,
                       {test::bruteOverlapping(soup, sphere), test::bruteOverlapping(soup, box),
                        test::bruteOverlapping(soup, obb), test::bruteOverlapping(soup, tri)}});
    found += queries.back().expected[0].size();
  }
  EXPECT_GT(found, 100u);
  test::forEveryPath([&] {
    const MeshBvh bvh(soup);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      const std::string at = "query " + std::to_string(i);
      EXPECT_EQ(bvh.overlapping(q.sphere), q.expected[0]) << at;
      EXPECT_EQ(bvh.overlapping(q.box), q.expected[1]) << at;
      EXPECT_EQ(bvh.overlapping(q.obb), q.expected[2]) << at;
      EXPECT_EQ(bvh.overlapping(q.tri), q.expected[3]) << at;
    }
  });
}

// Refit after the heightfield's heights change: the same answers as a rebuild on the moved mesh
// (both equal brute force on it, exactly: the triangle tests do not depend on the tree).
TEST(MeshQueries, RefitAnswersLikeARebuildOnEveryPath) {
  Mesh mesh = workloads::makeHeightfield(33);
  const std::vector<Vec3f> original = mesh.vertices;
  std::vector<Vec3f> moved = mesh.vertices;
  for (Vec3f& v : moved) v.y() = 2 * v.y() + 0.1f * v.x() - 5;
  mesh.vertices = moved;
  const RayStream rays = workloads::makeIncoherentRays(3000);
  std::vector<ElementHit> expected;
  for (std::size_t i = 0; i < rays.size(); ++i)
    expected.push_back(test::bruteRaycast(mesh, rays[i]));
  const Sphere s{{10, 0, 10}, 8};
  const std::vector<std::uint32_t> overlapping = test::bruteOverlapping(mesh, s);
  test::forEveryPath([&] {
    MeshBvh bvh(Mesh{original, mesh.triangles});
    bvh.refit(moved);
    const MeshBvh rebuilt(mesh);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const ElementHit a = bvh.raycast(rays[i]), b = rebuilt.raycast(rays[i]);
      EXPECT_EQ(a.index, expected[i].index) << "ray " << i;
      EXPECT_EQ(b.index, expected[i].index) << "ray " << i;
      if (expected[i].hit()) {
        EXPECT_EQ(a.t, expected[i].t) << "ray " << i;
      }
    }
    EXPECT_EQ(bvh.overlapping(s), overlapping);
    test::expectError([&] { bvh.refit(std::vector<Vec3f>(3)); }, "MeshBvh::refit: 3 vertices");
    std::vector<Vec3f> bad = moved;
    bad[7].x() = NAN;
    test::expectError([&] { bvh.refit(bad); }, "vertex 7");
  });
}

// Procedural meshes: closed and facing out (every normal points away from the centre), so a ray
// from inside hits from the back and one from outside at the centre hits the front.
TEST(ProceduralMeshes, BoxAndSphereAreClosedAndFaceOut) {
  const Vec3f centre(1, 2, 3);
  const Mesh meshes[] = {boxMesh({centre - Vec3f(1, 2, 3), centre + Vec3f(1, 2, 3)}),
                         sphereMesh(centre, 2, 8, 12)};
  for (const Mesh& m : meshes) {
    for (std::size_t i = 0; i < m.size(); ++i) {
      const Triangle t = m.triangle(i);
      EXPECT_GT(t.normal().dot((t.a + t.b + t.c) / 3 - centre), 0) << "triangle " << i;
    }
    const MeshBvh bvh(m);
    workloads::Random r(56);
    for (int k = 0; k < 500; ++k)
      EXPECT_TRUE(bvh.raycast({centre, r.unitDirection()}).hit()) << "ray " << k;
  }
  EXPECT_EQ(meshes[0].size(), 12u);
  EXPECT_EQ(meshes[1].size(), 2u * 12 * 7);
  const Mesh hf = workloads::makeHeightfield(3);
  ASSERT_EQ(hf.size(), 8u);
  EXPECT_EQ(hf.triangles[1], (std::array<std::uint32_t, 3>{0, 4, 3}));  // W2's second triangle
}

// Bvh::build's blocks (bvh.hpp): leaves of up to 4 in blocks of 8 lie within one block, several
// to a block, each primitive in one leaf, and every slot no leaf takes repeats its block's first.
TEST(BvhBlocks, LeavesArePackedIntoBlocks) {
  const Mesh soup = test::randomSoup(52, 3000, 60, 3);
  std::vector<Aabb> bounds;
  for (std::size_t i = 0; i < soup.size(); ++i) {
    const Triangle t = soup.triangle(i);
    bounds.push_back({t.a.cwiseMin(t.b).cwiseMin(t.c), t.a.cwiseMax(t.b).cwiseMax(t.c)});
  }
  Bvh tree;
  tree.build(bounds, {4, 8});
  const auto order = tree.order();
  ASSERT_EQ(order.size() % 8, 0u);
  std::vector<int> taken(order.size(), 0), seen(soup.size(), 0);
  std::size_t leaves = 0;
  for (const BvhNode& n : tree.nodes())
    for (std::uint32_t c : n.child) {
      if (c == BvhNode::kEmpty || !BvhNode::isLeaf(c)) continue;
      ++leaves;
      const std::uint32_t first = BvhNode::leafFirst(c), count = BvhNode::leafCount(c);
      ASSERT_LE(count, 4u);
      ASSERT_LE(first % 8 + count, 8u) << "leaf at " << first << " straddles a block";
      for (std::uint32_t s = first; s < first + count; ++s) ++taken[s], ++seen[order[s]];
    }
  for (std::size_t i = 0; i < soup.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
  for (std::size_t s = 0; s < order.size(); ++s) {
    ASSERT_LE(taken[s], 1) << "slot " << s << " in two leaves";
    if (taken[s] == 0) EXPECT_EQ(order[s], order[s / 8 * 8]) << "slot " << s;
  }
  // Leaves of 1 to 4 in blocks of 8: one block each would give as many blocks as leaves.
  EXPECT_LT(order.size() / 8, leaves);
}

TEST(MeshErrors, BadMeshesAreNamed) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 7}};
  test::expectError([&] { MeshBvh b(m); }, "MeshBvh: triangle 1: vertex index 7 is out of range");
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  test::expectError([&] { MeshBvh b(m); }, "triangle 1 (vertices 0, 1, 3) is degenerate");
  m.triangles = {{0, 1, 2}};
  m.vertices[2].z() = INFINITY;
  test::expectError([&] { MeshBvh b(m); }, "vertex 2");
  test::expectError([] { heightfieldMesh(1, 4, 0, 1, 0, 1, [](double, double) { return 0.0; }); },
                    "heightfieldMesh: 1 x 4");
  test::expectError([] { sphereMesh({0, 0, 0}, 1, 1, 8); }, "sphereMesh");
  Bvh tree;
  std::vector<Aabb> bounds = {{{0, 0, 0}, {1, 1, 1}}, {{0, 0, 0}, {-1, 1, 1}}};
  test::expectError([&] { tree.build(bounds, {4, 4}); }, "Bvh::build: bounds 1: min.x");
  test::expectError([&] { tree.build(bounds, {17, 17}); }, "maxLeafSize 17");
  const MeshBvh bvh(workloads::makeHeightfield(5));
  std::vector<std::uint32_t> out;
  test::expectError(
      [&] {
        bvh.bvh().query({{0, 0, 0}, {1, 1, 1}}, out);
      },
      "Bvh::query: the tree has leaves of several primitives");
}

}  // namespace
}  // namespace simdphys

// Rigid bodies against triangle meshes: the sphere-triangle and box-triangle manifolds of
// rigid/manifold.hpp, mesh.hpp's active edges, and bodies resting and sliding on a mesh floor as
// they do on a plane (no ghost edges between its triangles).
//
// Expected values are closed forms worked out by hand, and for random box-triangle pairs a
// 13-axis separating-axis oracle written here in double (projecting all 8 corners and 3 vertices
// onto each axis, unlike the code under test) cross-checked with EPA.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <vector>

#include "gjk_oracles.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "simdphys/rigid/manifold.hpp"
#include "simdphys/world.hpp"

namespace simdphys {
namespace {

using namespace test;

template <class T>
class MeshManifolds : public ::testing::Test {};
TYPED_TEST_SUITE(MeshManifolds, Scalars, ScalarName);

template <class T>
TriangleT<T> triangle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return {a.cast<T>(), b.cast<T>(), c.cast<T>()};
}

// ---- sphere-triangle: closed forms ---------------------------------------------------------

// The triangle (0,0,0), (4,0,0), (0,0,4) in the plane y = 0 (its normal -y by its winding; the
// surface is two-sided). Tolerance 16 eps * L (L = 4), as rigid_manifold_test's closed forms.
TYPED_TEST(MeshManifolds, SphereTriangleClosedForm) {
  using T = TypeParam;
  const T tol = 16 * std::numeric_limits<T>::epsilon() * 4;
  const TriangleT<T> t = triangle<T>({0, 0, 0}, {4, 0, 0}, {0, 0, 4});
  // Above the face: straight down, 0.3 - 0.5 deep.
  ManifoldT<T> m = collide(SphereT<T>{Vec3<T>(1, T(0.3), 1), T(0.5)}, t, T(0));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0, -1, 0), tol));
  EXPECT_NEAR(m.points[0].separation, T(-0.2), tol);
  EXPECT_TRUE(closeTo(m.points[0].point, Vec3d(1, 0.3 - 0.5 - 0.5 * -0.2, 1), tol));
  // Below it (two-sided): straight up.
  m = collide(SphereT<T>{Vec3<T>(1, T(-0.3), 1), T(0.5)}, t, T(0));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0, 1, 0), tol));
  // Beyond the hypotenuse x + z = 4, level with the plane: towards the edge's closest point
  // (2, 0, 2), distance sqrt(2) * (3 - 2) = sqrt(2), speculative within 1.
  m = collide(SphereT<T>{Vec3<T>(3, 0, 3), T(0.5)}, t, T(1));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(-1, 0, -1) / std::sqrt(2.0), tol));
  EXPECT_NEAR(m.points[0].separation, T(std::sqrt(2.0) - 0.5), tol);
  // Beyond the vertex (4,0,0): towards it; out of reach with maxSeparation 0.2.
  m = collide(SphereT<T>{Vec3<T>(5, 0, -1), T(0.5)}, t, T(1));
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(-1, 0, 1) / std::sqrt(2.0), tol));
  EXPECT_EQ(collide(SphereT<T>{Vec3<T>(5, 0, -1), T(0.5)}, t, T(0.2)).count, 0);
}

// ---- box-triangle: closed forms -------------------------------------------------------------

// A unit box resting 0.01 deep on a large triangle under it: the four bottom corners, each
// 0.01 deep, normal straight down, the same as against the plane y = 0.
TYPED_TEST(MeshManifolds, BoxRestingOnATriangleIsTheBoxOnThePlane) {
  using T = TypeParam;
  const T tol = 16 * std::numeric_limits<T>::epsilon() * 8;
  const TriangleT<T> t = triangle<T>({-8, 0, -8}, {-8, 0, 8}, {8, 0, 0});
  const ObbT<T> b{Vec3<T>(0, T(0.49), 0), Vec3<T>(T(0.5), T(0.5), T(0.5)), Mat3<T>::Identity()};
  const ManifoldT<T> m = collide(b, t, T(0.02));
  const ManifoldT<T> plane = collide(b, PlaneT<T>{Vec3<T>::UnitY(), T(0)}, T(0.02));
  ASSERT_EQ(m.count, 4);
  ASSERT_EQ(plane.count, 4);
  EXPECT_TRUE(closeTo(m.normal, plane.normal, tol));
  std::set<std::uint32_t> ids;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(m.points[std::size_t(i)].separation, T(-0.01), tol);
    EXPECT_NEAR(m.points[std::size_t(i)].point.y(), T(-0.005), tol);  // midway into the overlap
    EXPECT_NEAR(std::abs(m.points[std::size_t(i)].point.x()), T(0.5), tol);
    EXPECT_NEAR(std::abs(m.points[std::size_t(i)].point.z()), T(0.5), tol);
    ids.insert(m.points[std::size_t(i)].id);
  }
  EXPECT_EQ(ids.size(), 4u);
  // Lifted 0.05 above it: nothing within 0.02, four speculative points within 0.1.
  ObbT<T> above = b;
  above.center.y() = T(0.55);
  EXPECT_EQ(collide(above, t, T(0.02)).count, 0);
  EXPECT_EQ(collide(above, t, T(0.1)).count, 4);
}

// A small triangle under the middle of a large box's bottom face: the box's face is the
// reference and the triangle's three corners are the points, 0.1 deep.
TYPED_TEST(MeshManifolds, SmallTriangleUnderABoxFace) {
  using T = TypeParam;
  const T tol = 16 * std::numeric_limits<T>::epsilon() * 8;
  const TriangleT<T> t = triangle<T>({0, 0, 0}, {0.5, 0, 0}, {0, 0, 0.5});
  const ObbT<T> b{Vec3<T>(0, T(1.9), 0), Vec3<T>(2, 2, 2), Mat3<T>::Identity()};
  const ManifoldT<T> m = collide(b, t, T(0));
  ASSERT_EQ(m.count, 3);
  EXPECT_TRUE(closeTo(m.normal, Vec3d(0, -1, 0), tol));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.points[std::size_t(i)].separation, T(-0.1), tol);
}

// ---- box-triangle against the oracles -------------------------------------------------------

struct Sat {
  double separation = -INFINITY, runnerUp = -INFINITY;
  Vec3d axis = Vec3d::UnitY();  // from the box towards the triangle
  bool face = false;            // the best axis is the triangle's normal
};

// Brute force over the 13 axes: all 8 corners and 3 vertices projected on each.
Sat satOracle(const Obbd& b, const Triangled& t) {
  const std::array<Vec3d, 8> c = corners(b);
  const std::array<Vec3d, 3> v{t.a, t.b, t.c};
  std::vector<std::pair<Vec3d, bool>> axes{{(t.b - t.a).cross(t.c - t.a).normalized(), true}};
  for (int i = 0; i < 3; ++i) axes.push_back({b.axes.col(i), false});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3d e = v[std::size_t((j + 1) % 3)] - v[std::size_t(j)];
      const Vec3d x = b.axes.col(i).cross(e);
      if (x.norm() > 1e-6 * e.norm()) axes.push_back({x.normalized(), false});
    }
  Sat s;
  for (const auto& [l, face] : axes) {
    double bLo = INFINITY, bHi = -INFINITY, tLo = INFINITY, tHi = -INFINITY;
    for (const Vec3d& p : c) bLo = std::min(bLo, l.dot(p)), bHi = std::max(bHi, l.dot(p));
    for (const Vec3d& p : v) tLo = std::min(tLo, l.dot(p)), tHi = std::max(tHi, l.dot(p));
    const double sep = std::max(tLo - bHi, bLo - tHi);
    const Vec3d dir = tLo - bHi >= bLo - tHi ? l : Vec3d(-l);
    if (sep > s.separation)
      s.runnerUp = s.separation, s = {sep, s.runnerUp, dir, face};
    else
      s.runnerUp = std::max(s.runnerUp, sep);
  }
  return s;
}

double boundaryDistance(const Obbd& b, const Vec3d& p) {
  const Vec3d excess = (b.axes.transpose() * (p - b.center)).cwiseAbs() - b.halfExtents;
  return excess.maxCoeff() > 0 ? excess.cwiseMax(0.0).norm() : -excess.maxCoeff();
}

// Random boxes (half extents 0.1 to 1) and triangles (edges up to about 3) overlapping them,
// every triangle edge active, against the oracle (double):
//  - A's surface point (point - separation / 2 * normal) lies on the box's boundary and B's on the
//    triangle, within 1e-9 (coordinates up to L = 4; the clipping divides by sines of edge
//    angles, 1e-9 is about 5e5 eps * L) plus the clip's snap (kBoxClipSnap times the box's
//    size: a corner that close outside a side plane is kept as it is);
//  - the deepest separation lies between the oracle's separation minus the face preference
//    (kBoxAxisRelativeTolerance |s| + kBoxAxisAbsoluteTolerance size: the manifold may take a
//    deeper face axis) and the oracle's separation plus 1e-9 (no axis is shallower than the least);
//  - where the best axis beats the runner-up by more than the preference, the normal is the
//    oracle's axis within 1e-6 (the sine cut-off for nearly parallel edges, 1.5e-8 radians, and
//    rounding), and EPA's depth agrees with the oracle within 1e-6 (EPA's own tolerance).
TEST(MeshManifoldsRandom, BoxTriangleAgainstSatAndEpa) {
  Rng rng(4242);
  int cases = 0, determined = 0, faces = 0;
  Worst surface("box-triangle points on surfaces", kEps<double>);
  for (int i = 0; i < 300; ++i) {
    const Obbd b{rng.point(-1, 1), rng.point(0.1, 1), rng.rotation()};
    const Vec3d centre = b.center + rng.dir() * rng.u(0, 1.2) * b.halfExtents.norm();
    const Triangled t{centre + rng.point(-1.5, 1.5), centre + rng.point(-1.5, 1.5),
                      centre + rng.point(-1.5, 1.5)};
    if ((t.b - t.a).cross(t.c - t.a).norm() < 0.05) continue;  // slivers: no clear normal
    const Sat sat = satOracle(b, t);
    if (sat.separation > 0) continue;
    ++cases;
    const Manifoldd m = collide(b, t, 1e-9);
    ASSERT_GE(m.count, 1) << i;
    const double size = b.halfExtents.maxCoeff();
    const double tol = 1e-9 + kBoxClipSnap<double> * size;
    const double preference = kBoxAxisRelativeTolerance<double> * std::abs(sat.separation) +
                              kBoxAxisAbsoluteTolerance<double> * size + 1e-9;
    double deepest = INFINITY;
    for (int k = 0; k < m.count; ++k) {
      const ContactPointT<double>& c = m.points[std::size_t(k)];
      const Vec3d onA = c.point - c.separation / 2 * m.normal;
      const Vec3d onB = c.point + c.separation / 2 * m.normal;
      EXPECT_LE(std::abs(boundaryDistance(b, onA)), tol) << i << " point " << k;
      EXPECT_LE(distanceTo(t, onB), tol) << i << " point " << k;
      surface.add(distanceTo(t, onB), 4);
      deepest = std::min(deepest, c.separation);
    }
    EXPECT_GE(deepest, sat.separation - preference - 1e-9) << i;
    EXPECT_LE(deepest, sat.separation + 1e-9) << i;
    if (sat.separation - sat.runnerUp <= preference) continue;
    ++determined;
    faces += sat.face;
    EXPECT_TRUE(closeTo(m.normal, sat.axis, 1e-6)) << i;
    const std::optional<Penetrationd> pen = epa(b, t);
    if (sat.separation < -1e-6) {
      ASSERT_TRUE(pen.has_value()) << i;
      EXPECT_TRUE(closeTo(-pen->depth, sat.separation, 1e-6)) << i;
    }
  }
  // The draw must exercise what it claims.
  EXPECT_GE(cases, 150);
  EXPECT_GE(determined, cases / 2);
  EXPECT_GE(faces, 10);
  std::printf("[ cases    ] %d overlapping, %d determined axes (%d the triangle's face)\n", cases,
              determined, faces);
}

// ---- active edges ---------------------------------------------------------------------------

// Two triangles sharing the edge from (0,0,0) to (0,0,1) (vertices 0 and 1), folded along it:
// the second's far vertex at (cos a, sin a, 0.5) for a fold angle a, the first's at (-1, 0, 0.5),
// wound so both normals face up (+y) when flat.
Mesh fold(double angle) {
  Mesh m;
  m.vertices = {Vec3f(0, 0, 0), Vec3f(0, 0, 1), Vec3f(-1, 0, 0.5f),
                Vec3f(float(std::cos(angle)), float(std::sin(angle)), 0.5f)};
  m.triangles = {{1, 0, 2}, {0, 1, 3}};
  return m;
}

TEST(ActiveEdges, FlatConvexAndConcaveFolds) {
  // Both triangles' shared edge: edge 0 of the first (1 -> 0), edge 0 of the second (0 -> 1).
  const auto shared = [](const Mesh& m) {
    const std::vector<std::uint8_t> a = activeEdges(m);
    EXPECT_EQ(a[0] & 6, 6) << "boundary edges are active";
    EXPECT_EQ(a[1] & 6, 6) << "boundary edges are active";
    EXPECT_EQ(a[0] & 1, a[1] & 1) << "an edge is active for both its triangles or neither";
    return (a[0] & 1) != 0;
  };
  ASSERT_GT(fold(0).triangle(0).normal().y(), 0);  // the winding this test assumes
  ASSERT_GT(fold(0).triangle(1).normal().y(), 0);
  EXPECT_FALSE(shared(fold(0)));    // flat
  EXPECT_TRUE(shared(fold(-0.3)));  // a ridge: the second falls away below the first's plane
  EXPECT_FALSE(shared(fold(0.3)));  // a valley: it rises
  // A ridge of 1 degree is within kActiveEdgeCosine (about 2.6 degrees): flat enough.
  EXPECT_FALSE(shared(fold(-std::numbers::pi / 180)));
  EXPECT_TRUE(shared(fold(-std::numbers::pi / 36)));  // 5 degrees
}

TEST(ActiveEdges, HeightfieldInteriorIsInactive) {
  const Mesh m = heightfieldMesh(5, 5, 0, 4, 0, 4, [](double, double) { return 0.0; });
  const std::vector<std::uint8_t> a = activeEdges(m);
  int active = 0;
  for (std::uint8_t bits : a) active += std::popcount(unsigned(bits));
  EXPECT_EQ(active, 16);  // the 4 x 4 cells' outline: 16 edges, each in one triangle
}

// A box resting on the first of two coplanar triangles, one face parallel to and 0.005 from their
// shared diagonal, not over the second: the second, as a triangle with all edges active, gives a
// ghost contact (the box's face against the diagonal, a sideways normal); with the mesh's active
// edges it gives the floor's normal or nothing.
TEST(ActiveEdges, NoGhostContactBetweenCoplanarTriangles) {
  Mesh m = heightfieldMesh(2, 2, -4, 4, -4, 4, [](double, double) { return 0.0; });
  const std::vector<std::uint8_t> a = activeEdges(m);
  // Cell (0, 0)'s triangles share the diagonal from (-4,-4) to (4,4); the box sits on the side of
  // triangle 0, (v(0,0), v(1,0), v(1,1)) (x > z), with a corner 0.005 from the diagonal.
  const double d = 0.505 / std::sqrt(2.0);
  const Obbd b{Vec3d(0.5 + d, 0.5, 0.5 - d), Vec3d(0.5, 0.5, 0.5),
               Eigen::AngleAxisd(std::numbers::pi / 4, Vec3d::UnitY()).toRotationMatrix()};
  const Triangled second = seen(m.triangle(1));
  const Manifoldd ghost = collide(b, second, 0.02, 7);
  ASSERT_GE(ghost.count, 1);
  EXPECT_LT(std::abs(ghost.normal.y()), 0.5) << "a sideways normal: a ghost";
  const Manifoldd smooth = collide(b, second, 0.02, a[1]);
  EXPECT_EQ(a[1] & 7, 6) << "the diagonal is inactive, the outline active";
  for (int k = 0; k < smooth.count; ++k) EXPECT_NEAR(std::abs(smooth.normal.y()), 1.0, 1e-9);
}

// ---- bodies on a mesh floor -----------------------------------------------------------------

// The floor y = 0 over [-10, 10]^2 as a 20 x 20 cell heightfield (800 triangles), or as a plane.
World floorWorld(bool mesh) {
  World world;
  if (mesh)
    world.obstacles().add(std::make_shared<const MeshBvh>(
        heightfieldMesh(21, 21, -10, 10, -10, 10, [](double, double) { return 0.0; })));
  else
    world.obstacles().add(Plane{Vec3f::UnitY(), 0.0f});
  return world;
}

// A box thrown along the floor at 6 m/s (along a diagonal, across hundreds of triangle edges)
// slides to a stop after v^2 / (2 mu g) = 36 / (2 * 0.6 * 9.82) = 3.055 m, as on the plane; a
// ghost edge would trip it (stopping it short or tipping it over).
TEST(RigidOnMesh, BoxSlidesAcrossTheMeshAsOnThePlane) {
  std::vector<Vec3f> end;
  for (bool mesh : {false, true}) {
    World world = floorWorld(mesh);
    BodyDef d;
    d.position = {-4, 0.5f, -3}, d.velocity = Vec3f(3, 0, 1).normalized() * 6.0f;
    const Handle h = world.bodies().add(d);
    float deepest = 0;
    for (int i = 0; i < 120; ++i) {
      world.step();
      deepest = std::max(deepest, world.bodies().deepestPenetration());
    }
    const Vec3f p = world.bodies().position(h);
    // The closed form within 5 cm: the first step's contact forms after a substep of free motion
    // and the soft contact's settling shift the start by about v h = 1.7 cm.
    EXPECT_NEAR((p - d.position).norm(), 3.055f, 0.05f) << (mesh ? "mesh" : "plane");
    EXPECT_NEAR(p.y(), 0.5f, 0.005f) << "still flat on its face, within the slop";
    EXPECT_LT(world.bodies().velocity(h).norm(), 1e-3f);
    EXPECT_LT(deepest, 0.01f);
    end.push_back(p);
  }
  // Mesh and plane agree within 1 cm: the same contact, split into manifolds differently.
  EXPECT_LT((end[0] - end[1]).norm(), 0.01f);
}

// A sphere and a box dropped onto the mesh floor come to rest on it, at its surface.
TEST(RigidOnMesh, BodiesDroppedOnTheMeshComeToRest) {
  World world = floorWorld(true);
  BodyDef box, ball;
  box.position = {0.3f, 2, 0.7f};
  box.orientation = Quatf(Eigen::AngleAxisf(0.4f, Vec3f(1, 0, 1).normalized()));
  ball.shape = BodyShape::kSphere, ball.radius = 0.4f, ball.position = {3.1f, 3, -2.2f};
  const Handle hb = world.bodies().add(box), hs = world.bodies().add(ball);
  float deepest = 0;
  for (int i = 0; i < 300; ++i) {
    world.step();
    deepest = std::max(deepest, world.bodies().deepestPenetration());
  }
  // On a face (one of the box's axes vertical) at half height, the sphere at its radius, each
  // within the slop (0.005 m); penetration never past 1 cm (the drops reach 6 m/s, 0.1 m a step).
  const Mat3f r = world.bodies().orientation(hb).toRotationMatrix();
  EXPECT_GT(r.cwiseAbs().row(1).maxCoeff(), 0.999f);
  EXPECT_NEAR(world.bodies().position(hb).y(), 0.5f, 0.005f);
  EXPECT_NEAR(world.bodies().position(hs).y(), 0.4f, 0.005f);
  EXPECT_LT(deepest, 0.01f);
}

}  // namespace
}  // namespace simdphys

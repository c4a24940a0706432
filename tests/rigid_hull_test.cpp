// Convex hull bodies (rigid/hull.hpp): the shape's faces and mass properties against closed forms
// (a box, a tetrahedron, a prism), its manifolds against box-box's (a hull of a box's corners must
// collide as the box does) and against EPA and the shapes' own surfaces on random pairs, and hull
// bodies in a world: resting, stacking, tipping, sliding over a mesh, on every path, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "simdphys/geometry3d/epa.hpp"
#include "simdphys/random.hpp"
#include "simdphys/rigid/manifold.hpp"
#include "simdphys/snapshot.hpp"
#include "simdphys/world.hpp"
#include "tests/expect_error.hpp"
#include "tests/paths.hpp"

namespace simdphys {
namespace {

using test::expectError;

std::vector<Vec3f> boxCorners(const Vec3f& half, const Vec3f& centre = Vec3f::Zero(),
                              const Mat3f& axes = Mat3f::Identity()) {
  std::vector<Vec3f> out;
  for (int v = 0; v < 8; ++v)
    out.push_back(centre + axes * Vec3f((v & 1) ? half.x() : -half.x(),
                                        (v & 2) ? half.y() : -half.y(),
                                        (v & 4) ? half.z() : -half.z()));
  return out;
}

Mat3f randomRotation(Random& r) {
  return Quatf(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1))
      .normalized()
      .toRotationMatrix();
}

// The largest distance of x outside the hull's faces (negative inside): for a convex polytope,
// its signed distance outside, and within a face's rounding of 0 on its surface.
double outside(const HullShape& s, const Vec3d& centre, const Mat3d& axes, const Vec3d& x) {
  const Vec3d local = axes.transpose() * (x - centre);
  double worst = -1e30;
  for (int f = 0; f < s.faceCount(); ++f)
    worst = std::max(worst, s.faceNormal(f).cast<double>().dot(local) - double(s.faceOffset(f)));
  return worst;
}

TEST(HullShape, BoxCornersGiveTheBoxsFacesAndMassProperties) {
  Random r(7);
  const Vec3f half(1.0f, 0.5f, 0.25f), centre(3, -2, 1);
  const Mat3f axes = randomRotation(r);
  std::vector<Vec3f> points = boxCorners(half, centre, axes);
  points.push_back(centre);                       // interior
  points.push_back(points[3]);                    // repeated
  points.push_back((points[0] + points[1]) / 2);  // on an edge
  const HullShape s(points);
  ASSERT_EQ(s.vertices().size(), 8u);
  ASSERT_EQ(s.faceCount(), 6);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(s.face(f).size(), 4u) << "face " << f;
  // Closed forms: volume 8abc; inertia per unit mass (b^2 + c^2) / 3 and its turns, ascending
  // (the eigen solver's order). Float input rounded at 6e-8 of 3.6 m: 1e-5 relative holds.
  EXPECT_NEAR(s.volume(), 8 * 1.0 * 0.5 * 0.25, 1e-5);
  const Vec3d expected((0.25 + 0.0625) / 3,  // about the long axis: b^2 + c^2
                       (1 + 0.0625) / 3, (1 + 0.25) / 3);
  EXPECT_NEAR(s.inertia().x(), expected.x(), 1e-5);
  EXPECT_NEAR(s.inertia().y(), expected.y(), 1e-5);
  EXPECT_NEAR(s.inertia().z(), expected.z(), 1e-5);
  EXPECT_LT((s.centre() - centre).norm(), 1e-5f);
  // The shape's frame is the box's, up to the order and signs of its axes: every input point is
  // at centre + rotation * a vertex, and the vertices are the box's corners about the origin.
  for (const Vec3f& v : s.vertices()) {
    EXPECT_NEAR(std::abs(v.x()), 1.0f, 1e-5f);
    EXPECT_NEAR(std::abs(v.y()), 0.5f, 1e-5f);
    EXPECT_NEAR(std::abs(v.z()), 0.25f, 1e-5f);
  }
  for (int k = 0; k < 8; ++k) {
    const Vec3f back = s.centre() + s.rotation() * s.vertices()[std::size_t(k)];
    const double nearest =
        std::min_element(points.begin(), points.end(),
                         [&](auto& a, auto& b) { return (a - back).norm() < (b - back).norm(); })
            ->
            operator-(back)
            .norm();
    EXPECT_LT(nearest, 1e-5);
  }
  // Faces wind counter-clockwise about their outward normals.
  for (int f = 0; f < s.faceCount(); ++f) {
    const auto face = s.face(f);
    const Vec3f& a = s.vertices()[face[0]];
    const Vec3f n = (s.vertices()[face[1]] - a).cross(s.vertices()[face[2]] - a);
    EXPECT_GT(n.dot(s.faceNormal(f)), 0) << "face " << f;
    EXPECT_NEAR(s.faceNormal(f).dot(a), s.faceOffset(f), 1e-5f);
  }
}

TEST(HullShape, TetrahedronAndPrismAgainstClosedForms) {
  // The tetrahedron of the unit axes: volume 1/6, centroid (1/4, 1/4, 1/4), 4 triangles.
  const HullShape t(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_EQ(t.faceCount(), 4);
  EXPECT_NEAR(t.volume(), 1.0 / 6, 1e-7);
  EXPECT_LT((t.centre() - Vec3f::Constant(0.25f)).norm(), 1e-6f);
  // Its inertia per unit mass about the centroid: the covariance of a uniform tetrahedron with a
  // vertex at the origin is (sum of v v^T + s s^T) / 20, s the sum of its vertices: (I + J) / 20
  // here (J all ones), less c c^T = J / 16 for the centroid, so C = I / 20 - J / 80, with
  // eigenvalues 1/80 (along (1, 1, 1)) and 4/80 (twice). I = tr(C) - C: 8/80 and 5/80 twice.
  EXPECT_NEAR(t.inertia().x(), 5.0 / 80, 1e-6);
  EXPECT_NEAR(t.inertia().y(), 5.0 / 80, 1e-6);
  EXPECT_NEAR(t.inertia().z(), 8.0 / 80, 1e-6);

  // A 32-sided prism of radius 1 and height 2: 34 faces, two of 32 vertices; its volume is the
  // polygon's area (n/2 sin(2 pi / n)) times the height.
  std::vector<Vec3f> prism;
  const int n = 32;
  for (int k = 0; k < n; ++k) {
    const float a = 2 * std::numbers::pi_v<float> * float(k) / n;
    prism.push_back({std::cos(a), -1, std::sin(a)});
    prism.push_back({std::cos(a), 1, std::sin(a)});
  }
  const HullShape p(prism);
  EXPECT_EQ(p.faceCount(), n + 2);
  EXPECT_EQ(p.vertices().size(), std::size_t(2 * n));
  int caps = 0;
  for (int f = 0; f < p.faceCount(); ++f) caps += p.face(f).size() == std::size_t(n) ? 1 : 0;
  EXPECT_EQ(caps, 2);
  EXPECT_NEAR(p.volume(), n / 2.0 * std::sin(2 * std::numbers::pi / n) * 2, 1e-5);
}

TEST(HullShape, BadPointsAreRefused) {
  expectError(
      [] {
        HullShape(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
      },
      "point count is 3, must be in [4, 4096]");
  expectError(
      [] {
        HullShape(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
      },
      "the points are flat");
  expectError(
      [] {
        HullShape(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
      },
      "the points are flat");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expectError(
      [&] {
        HullShape(std::vector<Vec3f>{{0, 0, 0}, {1, 0, 0}, {0, nan, 0}, {0, 0, 1}});
      },
      "point 2");
  // 400 points on a sphere: every one a vertex, more than 256.
  std::vector<Vec3f> ball;
  Random r(3);
  for (int i = 0; i < 400; ++i)
    ball.push_back(Vec3f(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)).normalized());
  expectError([&] { HullShape{ball}; }, "the hull's vertex count");
}

// Hard point sets: a grid (many coplanar and collinear points), a sphere's points jittered by a
// float's rounding, duplicates, a thin slab just thicker than the flatness tolerance. Each either
// makes a proper hull, or is refused with an Error: convex (every vertex behind every face's
// plane, within 2e-5 of the points' extent: the hull's merging tolerance of 1e-5 and the float
// rounding of the re-expressed vertices), every face of at least 3 corners, Euler's
// V - E + F = 2, every input point behind every face's plane within the same 2e-5 (a point that
// near adds no vertex, and merging moves a face by at most that), and a volume no larger than
// the points' box.
TEST(HullShape, HardPointSetsMakeProperHullsOrAreRefused) {
  Random r(21);
  int built = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Vec3f> pts;
    const int kind = trial % 4;
    if (kind == 0) {  // a 4 x 4 x 4 grid, shuffled by the order of generation
      for (int i = 0; i < 64; ++i) pts.push_back({float(i % 4), float(i / 4 % 4), float(i / 16)});
    } else if (kind == 1) {  // a sphere, jittered by a few ulps
      for (int i = 0; i < 100; ++i) {
        Vec3f v = Vec3f(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)).normalized();
        pts.push_back(v + Vec3f::Constant(r.uniform(-1e-7f, 1e-7f)));
      }
    } else if (kind == 2) {  // a few points, each repeated
      for (int i = 0; i < 6; ++i) {
        const Vec3f v(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
        for (int k = 0; k < 3; ++k) pts.push_back(v);
      }
    } else {  // a slab of thickness 2e-5 to 1e-3 of its width
      const float thick = r.uniform(2e-5f, 1e-3f);
      for (int i = 0; i < 30; ++i)
        pts.push_back({r.uniform(-1, 1), r.uniform(0, thick), r.uniform(-1, 1)});
    }
    SCOPED_TRACE(trial);
    try {
      const HullShape s(pts);
      ++built;
      Vec3f lo = pts[0], hi = pts[0];
      for (const Vec3f& p : pts) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      const float extent = (hi - lo).maxCoeff();
      std::size_t edges = 0;
      for (int f = 0; f < s.faceCount(); ++f) {
        const auto face = s.face(f);
        ASSERT_GE(face.size(), 3u);
        edges += face.size();
        for (const Vec3f& v : s.vertices())
          EXPECT_LE(s.faceNormal(f).dot(v) - s.faceOffset(f), 2e-5f * extent) << "face " << f;
      }
      EXPECT_EQ(int(s.vertices().size()) - int(edges / 2) + s.faceCount(), 2);
      for (const Vec3f& p : pts) {
        const Vec3f local = s.rotation().conjugate() * (p - s.centre());
        for (int f = 0; f < s.faceCount(); ++f)
          EXPECT_LE(s.faceNormal(f).dot(local) - s.faceOffset(f), 2e-5f * extent) << kind;
      }
      EXPECT_LE(s.volume(), (hi - lo).prod() * (1 + 1e-5f));
      EXPECT_GT(s.volume(), 0);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("HullShape"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(built, 60);  // every set here is a solid (measured: none refused)
}

// A hull of a box's corners collides as the box: box-box's normal, depth and points, on random
// overlapping and nearly touching pairs (the hull's faces are the box's, so the clipping is the
// same; the normal comes from EPA rather than the separating axis test).
TEST(HullManifolds, BoxHullCollidesAsTheBox) {
  Random r(11);
  int sameAxis = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3d ha(r.uniform(0.2f, 1), r.uniform(0.2f, 1), r.uniform(0.2f, 1));
    const ObbT<double> b{Vec3d(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)),
                         Vec3d(r.uniform(0.2f, 1), r.uniform(0.2f, 1), r.uniform(0.2f, 1)),
                         randomRotation(r).cast<double>()};
    const HullShape shape(boxCorners(ha.cast<float>()));
    // The shape's frame may permute the box's axes: place it so that it is the box `a`.
    const Mat3d axesA = randomRotation(r).cast<double>();
    const Vec3d centreA(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1));
    const PlacedHullT<double> a{&shape, centreA + axesA * shape.centre().cast<double>(),
                                axesA * shape.rotation().cast<double>().toRotationMatrix()};
    const ObbT<double> boxA{centreA, ha, axesA};
    const ManifoldT<double> want = collide(boxA, b, 0.02);
    const ManifoldT<double> got = collide(a, b, 0.02);
    if (want.count == 0) continue;
    SCOPED_TRACE(trial);
    ASSERT_GT(got.count, 0);
    if (want.normal.dot(got.normal) > 1 - 1e-9) {
      ++sameAxis;
      // The same axis, so the same faces clipped: the same points and separations (in any
      // order), to the rounding of the hull's float vertices (its frame re-expresses the corners
      // in float: a few 1e-7 m for unit boxes).
      ASSERT_EQ(got.count, want.count);
      for (int i = 0; i < want.count; ++i) {
        const ContactPointT<double>& w = want.points[std::size_t(i)];
        const auto g = std::min_element(
            got.points.begin(), got.points.begin() + got.count, [&](auto& x, auto& y) {
              return (x.point - w.point).norm() < (y.point - w.point).norm();
            });
        EXPECT_LT((g->point - w.point).norm(), 1e-6);
        EXPECT_NEAR(g->separation, w.separation, 1e-6);
      }
    } else {
      // Another axis within box-box's stickiness (a face over an edge within 5% of the depth
      // plus 1e-3 of the smaller box): no point deeper than the least penetration (EPA's) by
      // more than that.
      const auto pen = epa(boxA, b);
      ASSERT_TRUE(pen.has_value());
      const double sticky =
          0.05 * pen->depth + 1e-3 * std::min(ha.maxCoeff(), b.halfExtents.maxCoeff());
      for (int i = 0; i < got.count; ++i)
        EXPECT_GE(got.points[std::size_t(i)].separation, -pen->depth - sticky - 1e-6);
    }
  }
  // Deep random overlaps often have several axes within the stickiness, between which the two
  // decide differently (box-box's edge axes are its closed forms, the hull's edge contact is
  // EPA's, and rounding differs); 77 of the 200 pairs take the same axis here (measured): the
  // comparison ran.
  EXPECT_GT(sameAxis, 50);
}

// Random irregular hulls against boxes, spheres and each other: the deepest point's depth is
// EPA's, and every point's two surface points lie on the two surfaces (within rounding) or, for a
// clipped face point, on the reference face with the other within the reported separation.
TEST(HullManifolds, RandomPairsAgreeWithEpaAndLieOnTheSurfaces) {
  Random r(5);
  const auto randomHull = [&] {
    std::vector<Vec3f> pts;
    for (int i = 0; i < 12; ++i)
      pts.push_back({r.uniform(-1, 1), r.uniform(-0.6f, 0.6f), r.uniform(-0.8f, 0.8f)});
    return HullShape(pts);
  };
  int overlapping = 0;
  for (int trial = 0; trial < 150; ++trial) {
    SCOPED_TRACE(trial);
    const HullShape sa = randomHull(), sb = randomHull();
    const PlacedHullT<double> a{&sa, Vec3d::Zero(), randomRotation(r).cast<double>()};
    const PlacedHullT<double> b{&sb, Vec3d(r.uniform(-1.5f, 1.5f), r.uniform(-1.5f, 1.5f), 0),
                                randomRotation(r).cast<double>()};
    std::vector<Vec3d> va, vb;
    for (const Vec3f& v : sa.vertices()) va.push_back(a.center + a.axes * v.cast<double>());
    for (const Vec3f& v : sb.vertices()) vb.push_back(b.center + b.axes * v.cast<double>());
    const auto pen = epa(ConvexHullT<double>{va}, ConvexHullT<double>{vb});
    const ManifoldT<double> m = collide(a, b, 0.0);
    if (!pen || pen->depth < 1e-6) continue;
    ++overlapping;
    ASSERT_GT(m.count, 0);
    double deepest = 0;
    for (int i = 0; i < m.count; ++i) {
      const ContactPointT<double>& p = m.points[std::size_t(i)];
      deepest = std::min(deepest, p.separation);
      // A's point and B's, each on its own surface: 1e-9 m for rounding of unit-sized shapes
      // in double; a point clipped from the incident face lies on that face, and its partner on
      // the reference face, so both are on their surfaces.
      const Vec3d onA = p.point - 0.5 * p.separation * m.normal;
      const Vec3d onB = p.point + 0.5 * p.separation * m.normal;
      EXPECT_LT(std::abs(outside(sa, a.center, a.axes, onA)), 1e-6);
      EXPECT_LT(std::abs(outside(sb, b.center, b.axes, onB)), 1e-6);
    }
    // No deeper than the least penetration (EPA's) by more than box-box's stickiness (a face's
    // axis taken within 5% of the depth plus 1e-3 of the shapes' size, about 0.6 m); a single
    // point (an edge or vertex contact) is EPA's own.
    const double sticky = 0.05 * pen->depth + 1e-3 * 0.6;
    EXPECT_LE(-deepest, pen->depth + sticky + 1e-6);
    if (m.points[0].id == 0xFFFFu) {
      EXPECT_NEAR(-deepest, pen->depth, 1e-9);
    }
  }
  EXPECT_GT(overlapping, 40);
}

TEST(HullManifolds, TetrahedronOnAPlaneAndOnATriangle) {
  const HullShape t(std::vector<Vec3f>{{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}, {0, 1, 0}});
  // Its base face down, 0.01 into the plane y = 0: three points at -0.01.
  // Placed so that its input points are where they were, 0.01 down.
  const PlacedHullT<float> a{&t, t.centre() + Vec3f(0, -0.01f, 0), t.rotation().toRotationMatrix()};
  const ManifoldT<float> m = collide(a, PlaneT<float>{Vec3f::UnitY(), 0}, 0.02f);
  ASSERT_EQ(m.count, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.points[std::size_t(i)].separation, -0.01f, 1e-6f);
  EXPECT_LT((m.normal + Vec3f::UnitY()).norm(), 1e-7f);
  // On a large triangle of the plane: the same three points, normal down, from the face clip.
  const TriangleT<float> floor{{-10, 0, -10}, {0, 0, 10}, {10, 0, -10}};
  const ManifoldT<float> f = collide(a, floor, 0.02f, 0);
  ASSERT_EQ(f.count, 3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f.points[std::size_t(i)].separation, -0.01f, 1e-6f);
  EXPECT_LT((f.normal + Vec3f::UnitY()).norm(), 1e-6f);
}

// Two cubes side by side on a diagonal, their vertical edges 0.1 mm apart: box-box finds no
// speculative contact (its face axes' clips are empty), and neither does the hull: a single point
// along GJK's normal there, which turns from step to step with rounding, made a W5 pyramid of
// hull cubes creep 0.5 m in 10 s (docs/rigid.md).
TEST(HullManifolds, DiagonalNeighboursBarelyApartHaveNoContact) {
  const HullShape cube(boxCorners(Vec3f::Constant(0.5f)));
  const Vec3f a(0, 0, 0), b(1.0001f, 0, 1.0001f);
  const ManifoldT<float> boxes = collide(Obb{a, Vec3f::Constant(0.5f), Mat3f::Identity()},
                                         Obb{b, Vec3f::Constant(0.5f), Mat3f::Identity()}, 0.02f);
  const ManifoldT<float> hulls = collide(PlacedHullT<float>{&cube, a, Mat3f::Identity()},
                                         PlacedHullT<float>{&cube, b, Mat3f::Identity()}, 0.02f);
  EXPECT_EQ(boxes.count, 0);
  EXPECT_EQ(hulls.count, 0);
  // Overlapping on the same diagonal, a contact there is: EPA's point, or a face's.
  const Vec3f c(0.999f, 0, 0.999f);
  EXPECT_GT(collide(PlacedHullT<float>{&cube, a, Mat3f::Identity()},
                    PlacedHullT<float>{&cube, c, Mat3f::Identity()}, 0.02f)
                .count,
            0);
}

// --- in a world -------------------------------------------------------------------------------

std::shared_ptr<const HullShape> cube() {
  return std::make_shared<const HullShape>(boxCorners(Vec3f::Constant(0.5f)));
}

BodyDef hullDef(std::shared_ptr<const HullShape> s, const Vec3f& at) {
  BodyDef d;
  d.shape = BodyShape::kHull, d.hull = std::move(s), d.position = at;
  return d;
}

class HullWorld : public test::OnEveryPath {};

// A stack of five hull cubes stands as five boxes stand, on every path: the same soft contacts,
// within a millimetre of the boxes after 5 s (their manifolds' normals come from EPA and their
// ids differ, so the two are not bitwise equal).
TEST_P(HullWorld, StackOfHullCubesStandsAsBoxesDo) {
  const auto shape = cube();
  std::vector<float> heights[2];
  for (int hull = 0; hull < 2; ++hull) {
    World world;
    RigidSettings s;
    s.sleeping = false;
    world.bodies().setSettings(s);
    world.obstacles().add(Plane{Vec3f::UnitY(), 0});
    std::vector<Handle> hs;
    for (int i = 0; i < 5; ++i) {
      BodyDef d = hullDef(shape, {0, 0.5f + float(i), 0});
      if (!hull) d.shape = BodyShape::kBox;
      hs.push_back(world.bodies().add(d));
    }
    for (int f = 0; f < 300; ++f) world.step();
    for (const Handle h : hs) {
      const Vec3f p = world.bodies().position(h);
      heights[hull].push_back(p.y());
      EXPECT_LT(Vec3f(p.x(), 0, p.z()).norm(), 1e-3f) << "drifted";
    }
  }
  for (int i = 0; i < 5; ++i)
    EXPECT_NEAR(heights[1][std::size_t(i)], heights[0][std::size_t(i)], 1e-3f);
}

SIMDPHYS_ON_EVERY_PATH(HullWorld);

// A tetrahedron dropped on a vertex tips over and rests on a face: still, its lowest vertex on
// the plane, a face normal straight down.
TEST(HullBodies, TetrahedronDroppedOnAVertexRestsOnAFace) {
  const auto t = std::make_shared<const HullShape>(
      std::vector<Vec3f>{{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}, {0, 1.2f, 0.1f}});
  World world;
  world.obstacles().add(Plane{Vec3f::UnitY(), 0});
  BodyDef d = hullDef(t, {0, 2, 0});
  d.orientation = Quatf(Eigen::AngleAxisf(2.5f, Vec3f(1, 0.3f, 0.2f).normalized()));
  const Handle h = world.bodies().add(d);
  for (int f = 0; f < 600; ++f) world.step();
  EXPECT_LT(world.bodies().velocity(h).norm(), 0.01f);
  EXPECT_LT(world.bodies().angularVelocity(h).norm(), 0.01f);
  const Mat3f R = world.bodies().orientation(h).toRotationMatrix();
  float lowest = 1e9f, down = 0;
  for (const Vec3f& v : t->vertices())
    lowest = std::min(lowest, (world.bodies().position(h) + R * v).y());
  for (int f = 0; f < t->faceCount(); ++f) down = std::max(down, -(R * t->faceNormal(f)).y());
  // Within the linear slop (5 mm) of the plane, a face within 0.5 degrees of flat.
  EXPECT_NEAR(lowest, 0.0f, 0.005f);
  EXPECT_GT(down, std::cos(0.5f * std::numbers::pi_v<float> / 180));
}

// A hull cube thrown across a floor of 800 triangles stops after v^2 / (2 mu g), as the box of
// rigid_mesh_test does: the active edges hold for hulls too.
TEST(HullBodies, HullSlidesOverAMeshFloorToTheClosedFormDistance) {
  World world;
  world.obstacles().add(std::make_shared<const MeshBvh>(
      heightfieldMesh(21, 21, -10, 10, -10, 10, [](double, double) { return 0.0; })));
  BodyDef d = hullDef(cube(), {-4, 0.5f, -3});
  d.velocity = Vec3f(3, 0, 1).normalized() * 6.0f;  // along a diagonal, across many edges
  const Handle h = world.bodies().add(d);
  for (int f = 0; f < 120; ++f) world.step();
  const Vec3f p = world.bodies().position(h);
  // 36 / (2 * 0.6 * 9.82) = 3.055 m, within rigid_mesh_test's 5 cm for the box (the first
  // contact forms after a substep of free motion, and the soft contact settles).
  EXPECT_NEAR((p - d.position).norm(), 3.055f, 0.05f);
  EXPECT_NEAR(p.y(), 0.5f, 0.005f) << "still flat on its face, within the slop";
  EXPECT_LT(world.bodies().velocity(h).norm(), 1e-3f);
}

TEST(HullBodies, SnapshotsKeepTheirShapesAndStepTheSame) {
  World world;
  world.obstacles().add(Plane{Vec3f::UnitY(), 0});
  const auto shape = cube();
  world.bodies().add(hullDef(shape, {0, 0.6f, 0}));
  world.bodies().add(hullDef(shape, {0.2f, 1.7f, 0}));
  for (int f = 0; f < 10; ++f) world.step();
  World copy = restore(snapshot(world));
  EXPECT_EQ(stateHash(copy), stateHash(world));
  for (int f = 0; f < 20; ++f) world.step(), copy.step();
  EXPECT_EQ(stateHash(copy), stateHash(world));
  EXPECT_EQ(copy.bodies().hull(copy.bodies().handle(0))->faceCount(), 6);
}

TEST(HullBodies, BadInputIsRefusedAndChangesNothing) {
  World world;
  BodyDef d;
  d.shape = BodyShape::kHull;
  expectError([&] { world.bodies().add(d); }, "hull is empty");
  d = hullDef(cube(), {0, 0, 0});
  d.mass = 0;
  expectError([&] { world.bodies().add(d); }, "mass");
  EXPECT_EQ(world.bodies().size(), 0u);
  d.mass = 1;
  const Handle h = world.bodies().add(d);
  expectError([&] { (void)world.bodies().box(h); }, "is not a box");
  expectError([&] { (void)world.bodies().sphere(h); }, "is not a sphere");
  EXPECT_EQ(world.bodies().hull(h)->faceCount(), 6);
}

}  // namespace
}  // namespace simdphys

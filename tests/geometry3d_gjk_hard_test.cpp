// Named hard cases of GJK and EPA (include/simdphys/geometry3d/{gjk,epa}.hpp): touching shapes,
// deep and identical ones, degenerate input, large coordinates with small shapes, tiny shapes,
// parallel faces, Minkowski sums and differences, non-finite input. Tolerances as in
// geometry3d_gjk_test.cpp: 64 eps * L unless stated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "gjk_oracles.hpp"

namespace simdphys {
namespace {

using namespace test;

template <class T>
class Gjk : public ::testing::Test {};
TYPED_TEST_SUITE(Gjk, Scalars, ScalarName);

// ---- named hard cases -----------------------------------------------------------------------

// Touching shapes: distance exactly 0 in exact arithmetic. Where the inputs are exact (small
// integers) GJK's arithmetic is exact too and the answer is 0; otherwise within 64 eps * L.
TYPED_TEST(Gjk, TouchingFaceFace) {
  using T = TypeParam;
  const AabbT<T> a{v3<T>(0, 0, 0), v3<T>(1, 1, 1)}, b{v3<T>(1, 0.25, -0.5), v3<T>(2, 3, 0.5)};
  const GjkResultT<T> r = gjkDistance(a, b);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(std::abs(double(r.pointA.x()) - 1), 4 * kEps<T>);  // on the shared face
  const auto p = epa(a, b);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0));
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), 0.0);
  // The same with two OBBs turned alike (rounded axes): within tolerance.
  const Mat3<T> rot = Eigen::AngleAxis<T>(T(0.7), v3<T>(1, 2, 3).normalized()).toRotationMatrix();
  const ObbT<T> oa{v3<T>(0.5, 0.5, 0.5), v3<T>(0.5, 1, 1), rot};
  const ObbT<T> ob{oa.center + rot.col(0) * T(1.25), v3<T>(0.75, 0.5, 0.5), rot};
  const double tol = 64 * kEps<T> * 4;  // L = 4
  const GjkResultT<T> s = gjkDistance(oa, ob);
  EXPECT_TRUE(s.intersecting);
  EXPECT_LE(double(s.distance), tol);
  const auto q = epa(oa, ob);
  ASSERT_TRUE(q.has_value());
  EXPECT_LE(double(q->depth), tol);
  EXPECT_LE(maxDiff(q->normal, rot.col(0)), 1e-3);  // the face normal (rounding: far below)
}

TYPED_TEST(Gjk, TouchingEdgeEdge) {
  using T = TypeParam;
  // Two crossing segments meeting at the origin.
  const SegmentT<T> a{v3<T>(-1, 0, 0), v3<T>(1, 0, 0)}, b{v3<T>(0, -1, 0), v3<T>(0, 3, 0)};
  const GjkResultT<T> r = gjkDistance(a, b);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(maxDiff(r.pointA, Vec3d::Zero()), 4 * kEps<T>);  // barycentric weights' rounding
  // Two boxes turned 45 degrees, one about z (top edge along z at y = 2s), one about x (bottom
  // edge along x at y = 2s): their edges cross at (0, 2s, 0). s = sqrt(1/2) rounded, the same
  // in both boxes, so the touching is exact up to the rounding of 4s - 2s.
  const T s = std::sqrt(T(0.5));
  ObbT<T> za{Vec3<T>::Zero(), v3<T>(1, 1, 1), Mat3<T>::Identity()};
  za.axes << s, -s, 0, s, s, 0, 0, 0, 1;
  ObbT<T> xb{v3<T>(0, 4 * s, 0), v3<T>(1, 1, 1), Mat3<T>::Identity()};
  xb.axes << 1, 0, 0, 0, s, -s, 0, s, s;
  const double tol = 64 * kEps<T> * 6;  // L = 6
  const GjkResultT<T> g = gjkDistance(za, xb);
  EXPECT_TRUE(g.intersecting);
  EXPECT_LE(double(g.distance), tol);
  EXPECT_LE(maxDiff(g.pointA, Vec3d(0, 2 * double(s), 0)), tol);
  const auto p = epa(za, xb);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(double(p->depth), tol);
  // Apart by 1e-3 along y: the distance is exactly that gap, between the crossing edges.
  const ObbT<T> apart{xb.center + v3<T>(0, 0.001, 0), xb.halfExtents, xb.axes};
  const GjkResultT<T> d = gjkDistance(za, apart);
  EXPECT_FALSE(d.intersecting);
  EXPECT_LE(std::abs(double(d.distance) - 0.001), tol);
}

TYPED_TEST(Gjk, TouchingVertexFace) {
  using T = TypeParam;
  // A triangle standing on the top face of a box with one vertex; a hull doing the same.
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  const TriangleT<T> t{v3<T>(0.25, 1, 0.5), v3<T>(2, 3, 0), v3<T>(-1, 4, 1)};
  const GjkResultT<T> r = gjkDistance(t, box);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  EXPECT_LE(maxDiff(r.pointA, Vec3d(0.25, 1, 0.5)), 64 * kEps<T> * 4);
  const auto p = epa(box, t);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(double(p->depth), 64 * kEps<T> * 4);
  const std::vector<Vec3<T>> pyramid = {v3<T>(0, 1, 0), v3<T>(-1, 2, -1), v3<T>(1, 2, -1),
                                        v3<T>(0, 2, 1)};
  EXPECT_TRUE(gjkIntersect(box, ConvexHullT<T>{pyramid}));
  // Touching spheres: centres r1 + r2 apart on an axis.
  EXPECT_TRUE(gjkIntersect(SphereT<T>{v3<T>(0, 0, 0), T(1)}, SphereT<T>{v3<T>(3, 0, 0), T(2)}));
  EXPECT_EQ(
      gjkDistance(SphereT<T>{v3<T>(0, 0, 0), T(1)}, SphereT<T>{v3<T>(3, 0, 0), T(2)}).distance,
      T(0));
}

// Deep penetration: one shape wholly inside the other.
TYPED_TEST(Gjk, DeepPenetration) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 10;  // L = 10
  const AabbT<T> big{v3<T>(-4, -3, -5), v3<T>(4, 3, 5)};
  const AabbT<T> small{v3<T>(0.5, 1, -1), v3<T>(1.5, 2, 1)};
  // B (small) leaves by moving +y by big.max.y - small.min.y = 2, the least of 3.5 (+x),
  // 5.5 (-x), 2 (+y), 5 (-y), 6 (+z), 6 (-z).
  auto p = epa(big, small);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2), tol);
  EXPECT_LE(maxDiff(p->normal, Vec3d(0, 1, 0)), tol);
  // A sphere inside the box: its centre 1 from the -x face, radius 0.5: depth 1.5 along +x
  // (the box, as B, moves +x).
  p = epa(SphereT<T>{v3<T>(-3, 0, 0), T(0.5)}, big);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1.5), tol);
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), tol);
  // Concentric spheres: depth r1 + r2, any unit normal.
  p = epa(SphereT<T>{v3<T>(1, 2, 3), T(2)}, SphereT<T>{v3<T>(1, 2, 3), T(0.5)});
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2.5), tol);
  EXPECT_LE(std::abs(double(p->normal.norm()) - 1), tol);
  // An OBB deep in an OBB turned the same way: the same as boxes in that frame.
  const Mat3<T> rot =
      Eigen::AngleAxis<T>(T(1.1), v3<T>(-1, 2, 0.5).normalized()).toRotationMatrix();
  const ObbT<T> outer{v3<T>(1, 1, 1), v3<T>(4, 3, 5), rot};
  const ObbT<T> inner{outer.center + rot * v3<T>(2.5, 0, 0), v3<T>(0.5, 0.5, 0.5), rot};
  p = epa(outer, inner);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 2), tol);  // 4 - 2.5 + 0.5 along local +x
  EXPECT_LE(maxDiff(p->normal, rot.col(0)), tol);
}

TYPED_TEST(Gjk, IdenticalShapes) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 8;
  const Mat3<T> rot = Eigen::AngleAxis<T>(T(0.4), v3<T>(0, 1, 1).normalized()).toRotationMatrix();
  const ObbT<T> o{v3<T>(3, -2, 1), v3<T>(0.5, 2, 1), rot};
  const GjkResultT<T> r = gjkDistance(o, o);
  EXPECT_TRUE(r.intersecting);
  EXPECT_EQ(r.distance, T(0));
  auto p = epa(o, o);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1), tol);  // twice the least half extent, 0.5
  EXPECT_LE(std::abs(std::abs(double(p->normal.dot(rot.col(0)))) - 1), tol);
  const SphereT<T> s{v3<T>(1, 1, 1), T(0.75)};
  p = epa(s, s);
  ASSERT_TRUE(p.has_value());
  EXPECT_LE(std::abs(double(p->depth) - 1.5), tol);
  // A triangle against itself: flat, so the depth is 0 along its normal.
  const TriangleT<T> t{v3<T>(0, 0, 0), v3<T>(2, 0, 0), v3<T>(0, 2, 0)};
  p = epa(t, t);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0));
  EXPECT_LE(std::abs(std::abs(double(p->normal.z())) - 1), tol);
  const std::vector<Vec3<T>> pts = {v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(0, 0, 1)};
  p = epa(ConvexHullT<T>{pts}, ConvexHullT<T>{pts});
  ASSERT_TRUE(p.has_value());
  // The tetrahedron against itself: the least translation is its least width, the distance
  // from a vertex to the opposite face: 1/sqrt(3) (from the origin to x + y + z = 1).
  EXPECT_LE(std::abs(double(p->depth) - 1 / std::sqrt(3.0)), tol);
}

TYPED_TEST(Gjk, DegenerateTriangleAndRepeatedPoints) {
  using T = TypeParam;
  const double tol = 64 * kEps<T> * 8;
  // Collinear vertices: the triangle is the segment from (0,0,0) to (4,0,0).
  const TriangleT<T> line{v3<T>(0, 0, 0), v3<T>(4, 0, 0), v3<T>(1, 0, 0)};
  for (const auto& [p, expected] : std::vector<std::pair<Vec3<T>, double>>{{v3<T>(2, 3, 4), 5.0},
                                                                           {v3<T>(-3, 0, 4), 5.0},
                                                                           {v3<T>(7, 4, 0), 5.0},
                                                                           {v3<T>(2, 0, 0), 0.0}}) {
    const GjkResultT<T> r = gjkDistance(SphereT<T>{p, T(0)}, line);
    EXPECT_TRUE(std::isfinite(r.distance));
    EXPECT_LE(std::abs(double(r.distance) - expected), tol) << p.transpose();
  }
  // All three vertices the same: a point.
  const TriangleT<T> dot{v3<T>(1, 1, 1), v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  EXPECT_LE(std::abs(double(gjkDistance(SphereT<T>{v3<T>(1, 1, 4), T(1)}, dot).distance) - 2), tol);
  // A flat triangle cutting a box: finite depth (the box must leave the plane's way).
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  const auto p = epa(box, line);
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(std::isfinite(p->depth) && p->normal.allFinite());
  // The segment through the box from x = 0 to 4 leaves by moving it 1 in y or z, or 1 in -x.
  EXPECT_LE(std::abs(double(p->depth) - 1), tol);
  // Hulls with repeated and collinear points; a zero-size box; a zero-length segment.
  const std::vector<Vec3<T>> rep = {v3<T>(3, 0, 0), v3<T>(3, 0, 0), v3<T>(3, 0, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(ConvexHullT<T>{rep}, box).distance) - 2), tol);
  const std::vector<Vec3<T>> col = {v3<T>(3, 0, 0), v3<T>(5, 0, 0), v3<T>(4, 0, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(ConvexHullT<T>{col}, box).distance) - 2), tol);
  const AabbT<T> point{v3<T>(0, 5, 0), v3<T>(0, 5, 0)};
  EXPECT_LE(std::abs(double(gjkDistance(point, box).distance) - 4), tol);
  const SegmentT<T> zero{v3<T>(0, 0, 3), v3<T>(0, 0, 3)};
  EXPECT_LE(std::abs(double(gjkDistance(zero, box).distance) - 2), tol);
  const auto q = epa(zero, AabbT<T>{v3<T>(-1, -1, 2.5), v3<T>(1, 1, 4)});
  ASSERT_TRUE(q.has_value());  // a point inside a box: out through the nearest face, 0.5 away
  EXPECT_LE(std::abs(double(q->depth) - 0.5), tol);
  EXPECT_LE(maxDiff(q->normal, Vec3d(0, 0, 1)), tol);  // the box (B) moves +z
}

// Coordinates of 1e5 with sizes of 1e-2. A float there is spaced 2^-7 = 0.0078, so a float
// computation in world coordinates would be wrong by about the size of the shapes. GJK works
// relative to a point of A, from each shape's own data: the distance keeps float's relative
// precision of the 1e-2 problem (bound 64 eps * L with L = 0.1, not 1e5); only the returned points
// carry their world rounding (bound: half a spacing, 2^-8, plus that).
TYPED_TEST(Gjk, LargeCoordinatesSmallShapes) {
  using T = TypeParam;
  Worst dist("at 1e5, sizes 1e-2: distance (L = 0.1), " + typeName<T>(), kEps<T>);
  Worst pen("at 1e5, sizes 1e-2: EPA depth (L = 0.1), " + typeName<T>(), kEps<T>);
  const double L = 0.1;
  const double tol = 64 * kEps<T> * L;
  const double pointTol = 0.5 * 0x1p-7 + tol;  // for T = double, a tiny part of this is used
  Rng rng(707);
  for (int i = 0; i < 500; ++i) {
    // The shapes in float (what a float user has), then exactly in double for the reference.
    const Vec3f base(1e5f + float(rng.u(-1, 1)), 1e5f, -1e5f);
    const Vec3f h1 = rng.point(0.002, 0.01).cast<float>();
    const Vec3f h2 = rng.point(0.002, 0.01).cast<float>();
    const Vec3f off = (rng.point(-0.03, 0.03)).cast<float>();
    const Aabb af = Aabb::fromCenter(base, h1), bf = Aabb::fromCenter(base + off, h2);
    const Aabbd a = seen(af), b = seen(bf);
    const Vec3d gaps = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0);
    const GjkResultT<T> r = gjkDistance(inScalar<T>(a), inScalar<T>(b));
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (gaps.norm() > tol) {
      dist.add(std::abs(double(r.distance) - gaps.norm()), L);
      ASSERT_LE(std::abs(double(r.distance) - gaps.norm()), tol) << i;
      ASSERT_LE(distanceTo(a, r.pointA.template cast<double>()), pointTol) << i;
    } else if (gaps.maxCoeff() == 0) {
      double least = INFINITY;
      for (int k = 0; k < 3; ++k)
        least = std::min({least, a.max[k] - b.min[k], b.max[k] - a.min[k]});
      const auto p = epa(inScalar<T>(a), inScalar<T>(b));
      ASSERT_TRUE(p.has_value()) << i;
      ASSERT_LT(p->iterations, kEpaMaxIterations);
      pen.add(std::abs(double(p->depth) - least), L);
      ASSERT_LE(std::abs(double(p->depth) - least), tol) << i;
    }
    // OBBs (turned in float) and a point against a triangle, whose supports compute at 1e5:
    // the double reference runs on the same float shapes, exactly converted; the OBB verdict
    // also against the SAT oracle, the point-triangle distance against the closed form.
    const Mat3f rot = Eigen::AngleAxisf(float(rng.u(0, 6.28)), rng.dir().cast<float>().normalized())
                          .toRotationMatrix();
    const Obb oa{base, h1, rot}, ob{base + off, h2, rot * Eigen::AngleAxisf(0.5f, Vec3f::UnitZ())};
    const Obbd oad{seenVec(oa.center), seenVec(oa.halfExtents), oa.axes.cast<double>()};
    const Obbd obd{seenVec(ob.center), seenVec(ob.halfExtents), ob.axes.cast<double>()};
    const GjkResultT<T> o = gjkDistance(inScalar<T>(oad), inScalar<T>(obd));
    const GjkResultd od = gjkDistance(oad, obd);
    ASSERT_LT(o.iterations, kGjkMaxIterations);
    dist.add(std::abs(double(o.distance) - od.distance), L);
    ASSERT_LE(std::abs(double(o.distance) - od.distance), tol) << i;
    // The float axes are orthonormal to 1e-7 only: the oracle's face normals are off by that
    // times the 1e-2 sizes, 1e-9, far below tol for float; the verdict is compared past both.
    const Sat sat = satOracle(oad, obd);
    if (std::abs(sat.separation) > tol + 1e-8) {
      ASSERT_EQ(o.intersecting, sat.separation < 0) << i;
    }
    const Triangle tf{base + rng.point(-0.02, 0.02).cast<float>(),
                      base + rng.point(-0.02, 0.02).cast<float>(),
                      base + rng.point(-0.02, 0.02).cast<float>()};
    const Vec3f pf = base + rng.point(-0.03, 0.03).cast<float>();
    const Triangled td{seenVec(tf.a), seenVec(tf.b), seenVec(tf.c)};
    const Vec3d pd = seenVec(pf);
    // The oracle too works relative to the shapes (at 1e5 double's own rounding is 1e-11); the
    // subtractions are exact (Sterbenz: the values are within a factor of 2).
    const Vec3d at = base.cast<double>();
    const double toTriangle =
        (closestOnTriangle(pd - at, td.a - at, td.b - at, td.c - at) - (pd - at)).norm();
    const GjkResultT<T> t = gjkDistance(SphereT<T>{pd.cast<T>(), T(0)}, inScalar<T>(td));
    ASSERT_LT(t.iterations, kGjkMaxIterations);
    if (toTriangle > tol) {
      dist.add(std::abs(double(t.distance) - toTriangle), L);
      ASSERT_LE(std::abs(double(t.distance) - toTriangle), tol) << i;
    }
    // Spheres there too: centre line.
    const Sphere sa{base, h1.x()}, sb{base + off, h2.x()};
    const double truth =
        (seen(sb).center - seen(sa).center).norm() - double(sa.radius) - double(sb.radius);
    const GjkResultT<T> s = gjkDistance(inScalar<T>(seen(sa)), inScalar<T>(seen(sb)));
    ASSERT_LT(s.iterations, kGjkMaxIterations);
    if (truth > tol) {
      dist.add(std::abs(double(s.distance) - truth), L);
      ASSERT_LE(std::abs(double(s.distance) - truth), tol) << i;
    }
  }
}

// Tiny shapes (1e-6) near the origin and near 1: the answer scales with them (the tolerances
// are relative to the shapes, L = 1e-5, not to 1).
TYPED_TEST(Gjk, TinyShapes) {
  using T = TypeParam;
  Worst dist("tiny 1e-6 shapes: distance (L = 1e-5), " + typeName<T>(), kEps<T>);
  for (const double where : {0.0, 1.0}) {
    Rng rng(808);
    for (int i = 0; i < 300; ++i) {
      const Vec3d c0 = Vec3d::Constant(where);
      const Vec3d c1 = c0 + rng.point(-3e-6, 3e-6);
      // Round the shapes to T first; the oracle uses exactly those.
      const SphereT<T> st{c0.cast<T>(), T(rng.u(0.2e-6, 1e-6))};
      const AabbT<T> bt{c1.cast<T>(), (c1 + rng.point(0.2e-6, 1e-6)).cast<T>()};
      const Sphered s = seen(st);
      const Aabbd b = seen(bt);
      const double L = 1e-5;  // the shapes' own span, wherever they are
      const double tol = 64 * kEps<T> * L;
      const Vec3d q = clampToAabb(s.center, b);
      const double truth = (q - s.center).norm() - s.radius;
      const GjkResultT<T> r = gjkDistance(st, bt);
      ASSERT_LT(r.iterations, kGjkMaxIterations);
      if ((q - s.center).norm() > 0 && truth > tol) {
        dist.add(std::abs(double(r.distance) - truth), L);
        ASSERT_LE(std::abs(double(r.distance) - truth), tol)
            << i << " at " << where << " d " << r.distance << " truth " << truth << " q "
            << q.transpose() << " c " << s.center.transpose() << " r " << s.radius << " bmin "
            << b.min.transpose() << " btmin " << bt.min.transpose().template cast<double>();
      } else if (truth < -tol && (q - s.center).norm() > 0) {
        const auto p = epa(st, bt);
        ASSERT_TRUE(p.has_value());
        ASSERT_LE(std::abs(double(p->depth) + truth), tol) << i;
      }
    }
  }
}

// Parallel box faces: the Minkowski difference of two boxes turned alike has large flat faces
// made of coplanar triangles, where EPA's new points are coplanar with old faces.
TYPED_TEST(Gjk, ParallelBoxFacesEpa) {
  using T = TypeParam;
  Worst pen("parallel faces: EPA depth vs per-axis overlap, " + typeName<T>(), kEps<T>);
  const AabbT<T> a{v3<T>(0, 0, 0), v3<T>(2, 2, 2)};
  // Equal y and z extents, overlapping by 1 in x: depth 1 along +x.
  auto p = epa(a, AabbT<T>{v3<T>(1, 0, 0), v3<T>(3, 2, 2)});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(1));
  EXPECT_LE(maxDiff(p->normal, Vec3d(1, 0, 0)), 0.0);
  // Flat on flat: the same footprint, 0.5 deep in z.
  p = epa(a, AabbT<T>{v3<T>(0, 0, 1.5), v3<T>(2, 2, 3.5)});
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->depth, T(0.5));
  EXPECT_LE(maxDiff(p->normal, Vec3d(0, 0, 1)), 0.0);
  // Random boxes turned alike (rounded axes), with coincident face planes on some axes.
  Rng rng(909);
  for (int i = 0; i < 500; ++i) {
    const Mat3d rot = rng.rotation();
    const Vec3d ha = rng.point(0.2, 2);
    Vec3d hb = rng.point(0.2, 2);
    Vec3d local((ha + hb).cwiseProduct(rng.point(-0.9, 0.9)));
    if (i % 2) hb[i % 3] = ha[i % 3], local[i % 3] = 0;  // coincident faces on one axis
    const Obbd ad{rng.point(-3, 3), ha, rot};
    const Obbd bd{ad.center + rot * local, hb, rot};
    double least = INFINITY;
    for (int k = 0; k < 3; ++k) least = std::min(least, ha[k] + hb[k] - std::abs(local[k]));
    const double L = extent(ad) + extent(bd);
    const double tol = 64 * kEps<T> * L;
    const auto q = epa(inScalar<T>(ad), inScalar<T>(bd));
    ASSERT_TRUE(q.has_value()) << i;
    ASSERT_LT(q->iterations, kEpaMaxIterations);
    pen.add(std::abs(double(q->depth) - least), L);
    ASSERT_LE(std::abs(double(q->depth) - least), tol) << i;
  }
}

// A capsule (segment + sphere as a Minkowski sum) against a sphere: distance between the
// segment and the centre minus both radii.
TYPED_TEST(Gjk, CapsuleAsMinkowskiSum) {
  using T = TypeParam;
  Rng rng(1010);
  for (int i = 0; i < 500; ++i) {
    const Segmentd seg{rng.point(-2, 2), rng.point(-2, 2)};
    const double rc = rng.u(0.1, 1), rs = rng.u(0.1, 1);
    const Vec3d c = rng.point(-3, 3);
    const MinkowskiSumT<SegmentT<T>, SphereT<T>> capsule{inScalar<T>(seg),
                                                         {Vec3<T>::Zero(), T(rc)}};
    const SphereT<T> sphere{c.cast<T>(), T(rs)};
    const double truth =
        (closestOnSegment(seenVec(sphere.center), seen(capsule.a).start, seen(capsule.a).end) -
         seenVec(sphere.center))
            .norm() -
        double(T(rc)) - double(T(rs));
    const double L = 8;
    const double tol = 64 * kEps<T> * L;
    const GjkResultT<T> r = gjkDistance(capsule, sphere);
    ASSERT_LT(r.iterations, kGjkMaxIterations);
    if (truth > tol) {
      ASSERT_LE(std::abs(double(r.distance) - truth), tol) << i;
    } else if (truth < -tol) {
      ASSERT_TRUE(r.intersecting);
      const auto p = epa(capsule, sphere);
      ASSERT_TRUE(p.has_value());
      // Centre off the segment: the depth is the centre-line one.
      if (truth + double(T(rc)) + double(T(rs)) > 1e-3) {
        ASSERT_LE(std::abs(double(p->depth) + truth), tol) << i;
      }
    }
  }
}

// A translation of B by slightly more than EPA's depth along its normal separates the shapes,
// and slightly less does not: the answer is usable as a contact.
TYPED_TEST(Gjk, EpaTranslationSeparates) {
  using T = TypeParam;
  Rng rng(1111);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Obbd a{rng.point(-1, 1), rng.point(0.2, 1), rng.rotation()};
    const Obbd b{rng.point(-1, 1), rng.point(0.2, 1), rng.rotation()};
    const auto p = epa(inScalar<T>(a), inScalar<T>(b));
    if (!p || p->depth < T(0.01)) continue;
    ASSERT_LT(p->iterations, kEpaMaxIterations);
    ++checked;
    const Vec3d n = p->normal.template cast<double>();
    const double d = double(p->depth);
    const double L = extent(a) + extent(b);
    const double margin = 1e3 * kEps<T> * L;  // well beyond GJK's touching tolerance
    EXPECT_FALSE(gjkIntersect(inScalar<T>(a), inScalar<T>(translated(b, n * (d + margin))))) << i;
    EXPECT_TRUE(gjkIntersect(inScalar<T>(a), inScalar<T>(translated(b, n * (d - margin))))) << i;
  }
  EXPECT_GT(checked, 100);
}

// GJK on the Minkowski difference A - B against a point at the origin is GJK on A and B: the
// same distance (the difference's core and radius are built from A's and B's). Sums and
// differences nest.
TYPED_TEST(Gjk, MinkowskiDifferenceAgainstOrigin) {
  using T = TypeParam;
  Rng rng(1212);
  const SphereT<T> origin{Vec3<T>::Zero(), T(0)};
  for (int i = 0; i < 300; ++i) {
    const ObbT<T> a = inScalar<T>(Obbd{rng.point(-2, 2), rng.point(0.1, 1), rng.rotation()});
    const SphereT<T> b{rng.point(-2, 2).cast<T>(), T(rng.u(0.1, 1))};
    const double tol = 64 * kEps<T> * 8;  // L = 8: coordinates and sizes up to 4 each
    const GjkResultT<T> direct = gjkDistance(a, b);
    const GjkResultT<T> viaDifference =
        gjkDistance(MinkowskiDifferenceT<ObbT<T>, SphereT<T>>{a, b}, origin);
    ASSERT_LT(viaDifference.iterations, kGjkMaxIterations);
    ASSERT_EQ(direct.intersecting, viaDifference.intersecting) << i;
    ASSERT_LE(std::abs(double(direct.distance) - double(viaDifference.distance)), tol) << i;
  }
  // A sum holding a difference: (segment - point) + sphere is a capsule moved by -point.
  const SegmentT<T> seg{v3<T>(0, 0, 0), v3<T>(4, 0, 0)};
  const MinkowskiSumT<MinkowskiDifferenceT<SegmentT<T>, SphereT<T>>, SphereT<T>> capsule{
      {seg, {v3<T>(1, 0, 0), T(0)}}, {Vec3<T>::Zero(), T(0.5)}};
  // The capsule spans x in [-1, 3] with radius 0.5: a point at (2, 3, 0) is 2.5 away.
  EXPECT_LE(std::abs(double(gjkDistance(capsule, SphereT<T>{v3<T>(2, 3, 0), T(0)}).distance) - 2.5),
            64 * kEps<T> * 4);
}

// Non-finite input is the caller's to reject (validate()); it must still not hang or crash:
// every loop is capped.
TYPED_TEST(Gjk, NonFiniteInputTerminates) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  for (const SphereT<T>& bad : {SphereT<T>{v3<T>(nan, 0, 0), T(1)}, SphereT<T>{v3<T>(0, 0, 0), nan},
                                SphereT<T>{v3<T>(inf, 0, 0), T(1)}}) {
    const GjkResultT<T> r = gjkDistance(bad, box);
    EXPECT_LE(r.iterations, kGjkMaxIterations);
    const auto p = epa(bad, box);
    if (p) {
      EXPECT_LE(p->iterations, kEpaMaxIterations);
    }
  }
}

}  // namespace
}  // namespace simdphys

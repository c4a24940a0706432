// Tests of include/simdphys/geometry3d/raycast.hpp, in float and in double. Expected values are
// worked by hand in the comments beside them; oracles (containment, surface distance,
// barycentric coordinates) are written here in double, independently of the code under test.
// "eps" is the machine epsilon of the scalar type: 1.19e-7 (float), 2.22e-16 (double).
#include "simdphys/geometry3d/raycast.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "workloads.hpp"

namespace simdphys {
namespace {

template <class T>
constexpr double kEps = std::numeric_limits<T>::epsilon();
template <class T>
constexpr T kInf = std::numeric_limits<T>::infinity();

template <class T>
Vec3<T> v3(double x, double y, double z) {
  return Vec3<T>(T(x), T(y), T(z));
}
Vec3d wide(const Vec3f& v) { return v.cast<double>(); }
Vec3d wide(const Vec3d& v) { return v; }

template <class T>
RayT<T> ray(const Vec3<T>& origin, const Vec3<T>& direction) {
  return {origin, direction};
}

// The unit direction from a to b, normalised in double and rounded to T (unit within eps).
template <class T>
Vec3<T> unitTowards(const Vec3<T>& a, const Vec3<T>& b) {
  return (wide(b) - wide(a)).normalized().template cast<T>();
}

double maxAbs(const Vec3d& v) { return v.cwiseAbs().maxCoeff(); }

// Checks a hit record against hand-worked values: t and point within `tol`, normal within
// `normalTol` (it is unit, so its error is absolute), the inside flag exactly.
template <class T>
::testing::AssertionResult isHit(const std::optional<RayHitT<T>>& h, double t, const Vec3d& point,
                                 const Vec3d& normal, bool inside, double tol,
                                 double normalTol = 16 * kEps<T>) {
  if (!h) return ::testing::AssertionFailure() << "no hit; expected t = " << t;
  const double dt = std::abs(double(h->t) - t);
  const double dp = maxAbs(wide(h->point) - point);
  const double dn = maxAbs(wide(h->normal) - normal);
  if (dt <= tol && dp <= tol && dn <= normalTol && h->inside == inside)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "hit t = " << h->t << " point (" << h->point.transpose() << ") normal ("
         << h->normal.transpose() << ") inside " << h->inside << "\nexpected t = " << t
         << " point (" << point.transpose() << ") normal (" << normal.transpose() << ") inside "
         << inside << "\n|dt| " << dt << ", |dpoint| " << dp << " (tol " << tol << "), |dnormal| "
         << dn << " (tol " << normalTol << ")";
}

template <class T>
::testing::AssertionResult isMiss(const std::optional<RayHitT<T>>& h) {
  if (!h) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "unexpected hit t = " << h->t << " point (" << h->point.transpose() << ") normal ("
         << h->normal.transpose() << ") inside " << h->inside;
}

// ---- oracles, in double -------------------------------------------------------------------------
// Signed "measures": negative inside, zero on the surface, positive outside. For the boxes it is
// the largest signed distance to a face plane, which is the Euclidean distance inside and on
// the faces, and between it and sqrt(3) times less outside.

template <class T>
double measure(const SphereT<T>& s, const Vec3d& p) {
  return (p - wide(s.center)).norm() - double(s.radius);
}
template <class T>
double measure(const AabbT<T>& b, const Vec3d& p) {
  return std::max((wide(b.min) - p).maxCoeff(), (p - wide(b.max)).maxCoeff());
}
template <class T>
Vec3d obbLocal(const ObbT<T>& b, const Vec3d& p) {
  return b.axes.template cast<double>().transpose() * (p - wide(b.center));
}
template <class T>
double measure(const ObbT<T>& b, const Vec3d& p) {
  return (obbLocal(b, p).cwiseAbs() - wide(b.halfExtents)).maxCoeff();
}

// Barycentric coordinates of p (projected on the plane) in double: weights of a, b, c.
template <class T>
Vec3d barycentric(const TriangleT<T>& tri, const Vec3d& p) {
  const Vec3d a = wide(tri.a), b = wide(tri.b), c = wide(tri.c);
  const Vec3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  const double u = n.dot((b - p).cross(c - p)) / n2;
  const double v = n.dot((c - p).cross(a - p)) / n2;
  return {u, v, 1 - u - v};
}

// ---- typed suites -----------------------------------------------------------------------------

using Scalars = ::testing::Types<float, double>;
struct ScalarName {
  template <class T>
  static std::string GetName(int) {
    return std::is_same_v<T, float> ? "float" : "double";
  }
};

template <class T>
class SphereRaycast : public ::testing::Test {};
template <class T>
class AabbRaycast : public ::testing::Test {};
template <class T>
class ObbRaycast : public ::testing::Test {};
template <class T>
class PlaneRaycast : public ::testing::Test {};
template <class T>
class TriangleRaycast : public ::testing::Test {};
template <class T>
class Linecast : public ::testing::Test {};
template <class T>
class HardCase : public ::testing::Test {};
template <class T>
class Property : public ::testing::Test {};
TYPED_TEST_SUITE(SphereRaycast, Scalars, ScalarName);
TYPED_TEST_SUITE(AabbRaycast, Scalars, ScalarName);
TYPED_TEST_SUITE(ObbRaycast, Scalars, ScalarName);
TYPED_TEST_SUITE(PlaneRaycast, Scalars, ScalarName);
TYPED_TEST_SUITE(TriangleRaycast, Scalars, ScalarName);
TYPED_TEST_SUITE(Linecast, Scalars, ScalarName);
TYPED_TEST_SUITE(HardCase, Scalars, ScalarName);
TYPED_TEST_SUITE(Property, Scalars, ScalarName);

// Hand-worked cases below involve values up to 10 and a handful of rounded operations each; a
// result within 16 eps * 10 of the exact value is right to its last few bits.
template <class T>
constexpr double kHandTol = 16 * kEps<T> * 10;

// ---- sphere
// ---------------------------------------------------------------------------------------

TYPED_TEST(SphereRaycast, HandWorked) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const SphereT<T> unit{v3<T>(0, 0, 0), T(1)};
  const Vec3<T> z = v3<T>(0, 0, 1);
  // Head-on from z = -5: the near pole (0, 0, -1) at t = 4, outward normal (0, 0, -1).
  EXPECT_TRUE(isHit(raycast(unit, ray(v3<T>(0, 0, -5), z)), 4, {0, 0, -1}, {0, 0, -1}, false, tol));
  // Off-centre by 0.6: half chord sqrt(1 - 0.36) = 0.8, entry z = -0.8, t = 5 - 0.8 = 4.2; the
  // normal is the point itself (unit sphere at the origin).
  EXPECT_TRUE(isHit(raycast(unit, ray(v3<T>(0, 0.6, -5), z)), 4.2, {0, 0.6, -0.8}, {0, 0.6, -0.8},
                    false, tol));
  // From the centre: leaves at (0, 0, 1), t = 1; outward (0, 0, 1) negated to face the ray.
  EXPECT_TRUE(isHit(raycast(unit, ray(v3<T>(0, 0, 0), z)), 1, {0, 0, 1}, {0, 0, -1}, true, tol));
  // From (0, 0.6, 0) inside: leaves at z = 0.8, t = 0.8, normal -(0, 0.6, 0.8).
  EXPECT_TRUE(isHit(raycast(unit, ray(v3<T>(0, 0.6, 0), z)), 0.8, {0, 0.6, 0.8}, {0, -0.6, -0.8},
                    true, tol));
  // A sphere of radius 2 at (1, 2, 3), ray down from z = 10 through its centre: top at z = 5.
  const SphereT<T> off{v3<T>(1, 2, 3), T(2)};
  EXPECT_TRUE(isHit(raycast(off, ray(v3<T>(1, 2, 10), v3<T>(0, 0, -1))), 5, {1, 2, 5}, {0, 0, 1},
                    false, tol));
  // The line at distance 1.5 > 1 from the centre misses.
  EXPECT_TRUE(isMiss(raycast(unit, ray(v3<T>(0, 1.5, -5), z))));
  // The sphere behind the ray misses (the book reports t = -6, see BookErrors).
  EXPECT_TRUE(isMiss(raycast(unit, ray(v3<T>(0, 0, -5), v3<T>(0, 0, -1)))));
  // tMax is closed: the hit at t = 4 is found with tMax = 4, not with 3.99.
  EXPECT_TRUE(raycast(unit, ray(v3<T>(0, 0, -5), z), T(4)).has_value());
  EXPECT_TRUE(isMiss(raycast(unit, ray(v3<T>(0, 0, -5), z), T(3.99))));
  // The exit counts against tMax too: from the centre the exit is at 1.
  EXPECT_TRUE(isMiss(raycast(unit, ray(v3<T>(0, 0, 0), z), T(0.5))));
}

// ---- AABB ---------------------------------------------------------------------------------------

TYPED_TEST(AabbRaycast, HandWorked) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const AabbT<T> box{v3<T>(1, 2, 3), v3<T>(3, 4, 5)};
  // Along +x at (y, z) = (3, 4): enters x = 1 at t = 1 through the -x face.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(0, 3, 4), v3<T>(1, 0, 0))), 1, {1, 3, 4}, {-1, 0, 0},
                    false, tol));
  // Along -x from x = 5: enters x = 3 at t = 2 through the +x face.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(5, 3, 4), v3<T>(-1, 0, 0))), 2, {3, 3, 4}, {1, 0, 0},
                    false, tol));
  // Down from z = 10: top face z = 5 at t = 5.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(2, 3, 10), v3<T>(0, 0, -1))), 5, {2, 3, 5}, {0, 0, 1},
                    false, tol));
  // Oblique (0.6, 0.8, 0) from (0, 0, 4): x slab t in [1/0.6, 3/0.6] = [1.67, 5], y slab
  // [2/0.8, 4/0.8] = [2.5, 5]: enters at 2.5 through y = 2, at (1.5, 2, 4).
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(0, 0, 4), v3<T>(0.6, 0.8, 0))), 2.5, {1.5, 2, 4},
                    {0, -1, 0}, false, tol));
  // From the centre (2, 3, 4) along +y: leaves y = 4 at t = 1; outward +y negated.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(2, 3, 4), v3<T>(0, 1, 0))), 1, {2, 4, 4}, {0, -1, 0},
                    true, tol));
  // From the centre along -z: leaves z = 3 at t = 1; outward -z negated is +z.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(2, 3, 4), v3<T>(0, 0, -1))), 1, {2, 3, 3}, {0, 0, 1},
                    true, tol));
  // Misses: y = 5 is above the box; the box behind the ray.
  EXPECT_TRUE(isMiss(raycast(box, ray(v3<T>(0, 5, 4), v3<T>(1, 0, 0)))));
  EXPECT_TRUE(isMiss(raycast(box, ray(v3<T>(5, 3, 4), v3<T>(1, 0, 0)))));
  // Corner: from the origin along (1,1,1)/sqrt 3 to the corner (1, 1, 1) of [1, 2]^3 at
  // t = sqrt 3. All three slabs give the same t (the same operations on the same values), so the
  // tie rule picks the x face: normal (-1, 0, 0).
  const AabbT<T> cube{v3<T>(1, 1, 1), v3<T>(2, 2, 2)};
  const T c = T(1) / std::sqrt(T(3));
  EXPECT_TRUE(isHit(raycast(cube, ray(v3<T>(0, 0, 0), Vec3<T>(c, c, c))), std::sqrt(3.0), {1, 1, 1},
                    {-1, 0, 0}, false, tol));
}

// ---- OBB ----------------------------------------------------------------------------------------

// A quarter turn about z: local x is world +y, local y is world -x (columns of the matrix).
template <class T>
Mat3<T> quarterTurnZ() {
  Mat3<T> m;
  m << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  return m;
}

TYPED_TEST(ObbRaycast, HandWorked) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  // Centre (1, 0, 0), half extents (2, 0.5, 1) along local x = world y, local y = world -x:
  // world x in [0.5, 1.5], y in [-2, 2], z in [-1, 1].
  const ObbT<T> box{v3<T>(1, 0, 0), v3<T>(2, 0.5, 1), quarterTurnZ<T>()};
  EXPECT_NO_THROW(validate(box, "test"));
  // Along +x from (-3, 0, 0): enters x = 0.5 at t = 3.5, outward normal world -x.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(-3, 0, 0), v3<T>(1, 0, 0))), 3.5, {0.5, 0, 0},
                    {-1, 0, 0}, false, tol));
  // Down -y from (1, 5, 0): enters y = 2 at t = 3, normal +y.
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(1, 5, 0), v3<T>(0, -1, 0))), 3, {1, 2, 0}, {0, 1, 0},
                    false, tol));
  // From the centre along +z: leaves z = 1 at t = 1, normal -z (inside).
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(1, 0, 0), v3<T>(0, 0, 1))), 1, {1, 0, 1}, {0, 0, -1},
                    true, tol));
  // The unit cube turned 45 degrees about z: its faces are the lines |x +- y| = sqrt 2. The ray
  // along +x at y = 0.2 crosses the face y - x = sqrt 2 (outward normal (-1, 1, 0)/sqrt 2, the
  // local +y axis) at x = 0.2 - sqrt 2, t = 5 + 0.2 - sqrt 2 = 3.7857864376.
  const T h = std::sqrt(T(2)) / 2;
  Mat3<T> r45;
  r45 << h, -h, 0, h, h, 0, 0, 0, 1;
  const ObbT<T> turned{v3<T>(0, 0, 0), v3<T>(1, 1, 1), r45};
  const double s = std::sqrt(2.0);
  EXPECT_TRUE(isHit(raycast(turned, ray(v3<T>(-5, 0.2, 0), v3<T>(1, 0, 0))), 5.2 - s,
                    {0.2 - s, 0.2, 0}, {-s / 2, s / 2, 0}, false, tol));
  EXPECT_TRUE(isMiss(raycast(turned, ray(v3<T>(-5, 1.5, 0), v3<T>(1, 0, 0)))));  // 1.5 > sqrt 2
}

// ---- plane --------------------------------------------------------------------------------------

TYPED_TEST(PlaneRaycast, HandWorked) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const PlaneT<T> y2{v3<T>(0, 1, 0), T(-2)};  // y = 2
  // Down from y = 5: t = 3, normal +y (the front faces the ray).
  EXPECT_TRUE(isHit(raycast(y2, ray(v3<T>(0, 5, 0), v3<T>(0, -1, 0))), 3, {0, 2, 0}, {0, 1, 0},
                    false, tol));
  // Up from y = -1 (behind): two-sided, t = 3, normal -y.
  EXPECT_TRUE(isHit(raycast(y2, ray(v3<T>(0, -1, 0), v3<T>(0, 1, 0))), 3, {0, 2, 0}, {0, -1, 0},
                    false, tol));
  // Oblique (0.6, -0.8, 0) from (0, 5, 0): t = 3 / 0.8 = 3.75 at (2.25, 2, 0).
  EXPECT_TRUE(isHit(raycast(y2, ray(v3<T>(0, 5, 0), v3<T>(0.6, -0.8, 0))), 3.75, {2.25, 2, 0},
                    {0, 1, 0}, false, tol));
  // Origin on the plane, oblique upwards: t = 0, normal -y faces the ray.
  EXPECT_TRUE(isHit(raycast(y2, ray(v3<T>(1, 2, 3), v3<T>(0.6, 0.8, 0))), 0, {1, 2, 3}, {0, -1, 0},
                    false, tol));
  // In the plane, parallel above it, moving away: no hit.
  EXPECT_TRUE(isMiss(raycast(y2, ray(v3<T>(0, 2, 0), v3<T>(1, 0, 0)))));
  EXPECT_TRUE(isMiss(raycast(y2, ray(v3<T>(0, 3, 0), v3<T>(1, 0, 0)))));
  EXPECT_TRUE(isMiss(raycast(y2, ray(v3<T>(0, 5, 0), v3<T>(0, 1, 0)))));
  // Tilted plane 0.6 x + 0.8 y = 5 and the x axis: x = 5 / 0.6 = 8.3333; the ray comes from the
  // back (n.d = 0.6 > 0), so the normal is -n.
  const PlaneT<T> tilted{v3<T>(0.6, 0.8, 0), T(-5)};
  EXPECT_TRUE(isHit(raycast(tilted, ray(v3<T>(0, 0, 0), v3<T>(1, 0, 0))), 5 / 0.6, {5 / 0.6, 0, 0},
                    {-0.6, -0.8, 0}, false, tol));
}

// ---- triangle -----------------------------------------------------------------------------------

TYPED_TEST(TriangleRaycast, HandWorked) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  // Counter-clockwise seen from +z: normal (1,0,0) x (0,1,0) = +z.
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  const Vec3<T> down = v3<T>(0, 0, -1), up = v3<T>(0, 0, 1);
  EXPECT_TRUE(isHit(raycast(tri, ray(v3<T>(0.25, 0.25, 5), down)), 5, {0.25, 0.25, 0}, {0, 0, 1},
                    false, tol));
  // From below: back face, two-sided, normal -z faces the ray.
  EXPECT_TRUE(isHit(raycast(tri, ray(v3<T>(0.25, 0.25, -2), up)), 2, {0.25, 0.25, 0}, {0, 0, -1},
                    false, tol));
  // On an edge (ab, then bc) and on each vertex: closed, they hit.
  EXPECT_TRUE(raycast(tri, ray(v3<T>(0.5, 0, 5), down)).has_value());
  EXPECT_TRUE(raycast(tri, ray(v3<T>(0.5, 0.5, 5), down)).has_value());
  EXPECT_TRUE(raycast(tri, ray(v3<T>(0, 0, 5), down)).has_value());
  EXPECT_TRUE(raycast(tri, ray(v3<T>(1, 0, 5), down)).has_value());
  EXPECT_TRUE(raycast(tri, ray(v3<T>(0, 1, 5), down)).has_value());
  // Outside: beyond the hypotenuse (0.6 + 0.6 > 1), left of the y axis.
  EXPECT_TRUE(isMiss(raycast(tri, ray(v3<T>(0.6, 0.6, 5), down))));
  EXPECT_TRUE(isMiss(raycast(tri, ray(v3<T>(-0.1, 0.5, 5), down))));
  // Oblique (0.6, 0, -0.8) from (0.1, 0.1, 1): z = 0 at t = 1.25, point (0.85, 0.1, 0), inside.
  EXPECT_TRUE(isHit(raycast(tri, ray(v3<T>(0.1, 0.1, 1), v3<T>(0.6, 0, -0.8))), 1.25,
                    {0.85, 0.1, 0}, {0, 0, 1}, false, tol));
  // Edge-on (the ray in the triangle's plane): no hit, as for a plane.
  EXPECT_TRUE(isMiss(raycast(tri, ray(v3<T>(-1, 0.25, 0), v3<T>(1, 0, 0)))));
  EXPECT_TRUE(isMiss(raycast(tri, ray(v3<T>(0.25, 0.25, 5), down), T(4.9))));  // beyond tMax
  // The triangle (1,0,0), (0,1,0), (0,0,1): normal (-1,1,0) x (-1,0,1) = (1,1,1), plane
  // x + y + z = 1. From the origin along (1,1,1)/sqrt 3: t = 1/sqrt 3 at the centroid; the ray
  // comes from the back, so the normal is -(1,1,1)/sqrt 3.
  const TriangleT<T> slanted{v3<T>(1, 0, 0), v3<T>(0, 1, 0), v3<T>(0, 0, 1)};
  const T c = T(1) / std::sqrt(T(3));
  const double k = 1 / std::sqrt(3.0);
  EXPECT_TRUE(isHit(raycast(slanted, ray(v3<T>(0, 0, 0), Vec3<T>(c, c, c))), k,
                    {1 / 3.0, 1 / 3.0, 1 / 3.0}, {-k, -k, -k}, false, tol));
}

TYPED_TEST(TriangleRaycast, BarycentricAndPrecomputedRay) {
  using T = TypeParam;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  const WatertightRayT<T> r(ray(v3<T>(0.25, 0.25, 5), v3<T>(0, 0, -1)));
  // (0.25, 0.25) = 0.5 a + 0.25 b + 0.25 c.
  const auto h = intersectTriangle(r, tri);
  ASSERT_TRUE(h.has_value());
  EXPECT_NEAR(h->t, 5, kHandTol<T>);
  EXPECT_NEAR(h->u, 0.5, kHandTol<T>);
  EXPECT_NEAR(h->v, 0.25, kHandTol<T>);
  EXPECT_NEAR(h->w, 0.25, kHandTol<T>);
  // The overload taking the precomputed ray gives the same record, bit for bit, as the plain one,
  // on random rays and triangles.
  workloads::Random rng(31);
  for (int i = 0; i < 500; ++i) {
    TriangleT<T> t;
    for (Vec3<T>* v : {&t.a, &t.b, &t.c})
      *v = v3<T>(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    const RayT<T> q{v3<T>(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)),
                    rng.unitDirection().template cast<T>()};
    const auto plain = raycast(t, q);
    const auto pre = raycast(t, WatertightRayT<T>(q));
    ASSERT_EQ(plain.has_value(), pre.has_value());
    if (!plain) continue;
    EXPECT_EQ(plain->t, pre->t);
    EXPECT_EQ(plain->normal, pre->normal);
    EXPECT_EQ(plain->point, pre->point);
  }
}

// ---- linecast and linetest
// ------------------------------------------------------------------------

template <class T>
SegmentT<T> seg(const Vec3<T>& a, const Vec3<T>& b) {
  return {a, b};
}

TYPED_TEST(Linecast, Sphere) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const SphereT<T> s{v3<T>(0, 0, 0), T(1)};
  // Through: enters at distance 4 from the start.
  const auto through = seg(v3<T>(0, 0, -5), v3<T>(0, 0, 5));
  EXPECT_TRUE(isHit(linecast(s, through), 4, {0, 0, -1}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(linetest(s, through));
  // Ends 1 short of the sphere.
  const auto shortOf = seg(v3<T>(0, 0, -5), v3<T>(0, 0, -2));
  EXPECT_TRUE(isMiss(linecast(s, shortOf)));
  EXPECT_FALSE(linetest(s, shortOf));
  // Ends exactly on the surface: touching counts, t = length = 4. (d = (0,0,4), e.d/d.d = 1.25,
  // half chord 1/4, near root (24/16) / (1.25 + 0.25) = 1 exactly.)
  const auto touching = seg(v3<T>(0, 0, -5), v3<T>(0, 0, -1));
  EXPECT_TRUE(isHit(linecast(s, touching), 4, {0, 0, -1}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(linetest(s, touching));
  // Wholly inside: touches the solid, crosses no surface.
  const auto within = seg(v3<T>(0, 0, -0.5), v3<T>(0, 0, 0.5));
  EXPECT_TRUE(linetest(s, within));
  EXPECT_TRUE(isMiss(linecast(s, within)));
  // From the centre out: the exit at distance 1, inside, normal facing the segment.
  EXPECT_TRUE(
      isHit(linecast(s, seg(v3<T>(0, 0, 0), v3<T>(0, 0, 3))), 1, {0, 0, 1}, {0, 0, -1}, true, tol));
  // Degenerate segments are points: inside, on the surface, outside.
  EXPECT_TRUE(linetest(s, seg(v3<T>(0, 0.5, 0), v3<T>(0, 0.5, 0))));
  EXPECT_TRUE(linetest(s, seg(v3<T>(0, 1, 0), v3<T>(0, 1, 0))));
  EXPECT_FALSE(linetest(s, seg(v3<T>(0, 1.5, 0), v3<T>(0, 1.5, 0))));
  EXPECT_TRUE(isMiss(linecast(s, seg(v3<T>(0, 0.5, 0), v3<T>(0, 0.5, 0)))));
}

TYPED_TEST(Linecast, Aabb) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const AabbT<T> box{v3<T>(1, 2, 3), v3<T>(3, 4, 5)};
  EXPECT_TRUE(isHit(linecast(box, seg(v3<T>(0, 3, 4), v3<T>(5, 3, 4))), 1, {1, 3, 4}, {-1, 0, 0},
                    false, tol));
  // Ending exactly on the face x = 1: t = (1 - 0) / 1 = 1 <= 1, a touch.
  EXPECT_TRUE(linetest(box, seg(v3<T>(0, 3, 4), v3<T>(1, 3, 4))));
  EXPECT_TRUE(isHit(linecast(box, seg(v3<T>(0, 3, 4), v3<T>(1, 3, 4))), 1, {1, 3, 4}, {-1, 0, 0},
                    false, tol));
  EXPECT_FALSE(linetest(box, seg(v3<T>(0, 3, 4), v3<T>(0.5, 3, 4))));
  // Wholly inside (the book says false, see BookErrors).
  EXPECT_TRUE(linetest(box, seg(v3<T>(1.5, 3, 4), v3<T>(2.5, 3, 4))));
  EXPECT_TRUE(isMiss(linecast(box, seg(v3<T>(1.5, 3, 4), v3<T>(2.5, 3, 4)))));
  // Points: inside, on a face, outside.
  EXPECT_TRUE(linetest(box, seg(v3<T>(2, 3, 4), v3<T>(2, 3, 4))));
  EXPECT_TRUE(linetest(box, seg(v3<T>(1, 3, 4), v3<T>(1, 3, 4))));
  EXPECT_FALSE(linetest(box, seg(v3<T>(0, 0, 0), v3<T>(0, 0, 0))));
}

TYPED_TEST(Linecast, Obb) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const ObbT<T> box{v3<T>(1, 0, 0), v3<T>(2, 0.5, 1), quarterTurnZ<T>()};
  // As in ObbRaycast: enters x = 0.5 at distance 3.5.
  EXPECT_TRUE(isHit(linecast(box, seg(v3<T>(-3, 0, 0), v3<T>(3, 0, 0))), 3.5, {0.5, 0, 0},
                    {-1, 0, 0}, false, tol));
  EXPECT_FALSE(linetest(box, seg(v3<T>(-3, 0, 0), v3<T>(0, 0, 0))));
  EXPECT_TRUE(linetest(box, seg(v3<T>(1, 0, 0), v3<T>(1, 1, 0))));  // inside
  EXPECT_TRUE(isMiss(linecast(box, seg(v3<T>(1, 0, 0), v3<T>(1, 1, 0)))));
  EXPECT_TRUE(linetest(box, seg(v3<T>(1, 1.9, 0.9), v3<T>(1, 1.9, 0.9))));   // point inside
  EXPECT_FALSE(linetest(box, seg(v3<T>(1, 2.1, 0.9), v3<T>(1, 2.1, 0.9))));  // point outside
}

TYPED_TEST(Linecast, Plane) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const PlaneT<T> y2{v3<T>(0, 1, 0), T(-2)};
  EXPECT_TRUE(isHit(linecast(y2, seg(v3<T>(0, 5, 0), v3<T>(0, -1, 0))), 3, {0, 2, 0}, {0, 1, 0},
                    false, tol));
  // Ending on the plane: signed distances 3 and 0, crossing at 3 / (3 - 0) = 1 exactly.
  EXPECT_TRUE(isHit(linecast(y2, seg(v3<T>(0, 5, 0), v3<T>(0, 2, 0))), 3, {0, 2, 0}, {0, 1, 0},
                    false, tol));
  EXPECT_TRUE(linetest(y2, seg(v3<T>(0, 5, 0), v3<T>(0, 2, 0))));
  EXPECT_FALSE(linetest(y2, seg(v3<T>(0, 5, 0), v3<T>(0, 3, 0))));
  // Lying in the plane: touches it, crosses nothing.
  EXPECT_TRUE(linetest(y2, seg(v3<T>(0, 2, 0), v3<T>(5, 2, 0))));
  EXPECT_TRUE(isMiss(linecast(y2, seg(v3<T>(0, 2, 0), v3<T>(5, 2, 0)))));
  // Points.
  EXPECT_TRUE(linetest(y2, seg(v3<T>(1, 2, 1), v3<T>(1, 2, 1))));
  EXPECT_FALSE(linetest(y2, seg(v3<T>(1, 3, 1), v3<T>(1, 3, 1))));
}

TYPED_TEST(Linecast, Triangle) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_TRUE(isHit(linecast(tri, seg(v3<T>(0.25, 0.25, 1), v3<T>(0.25, 0.25, -1))), 1,
                    {0.25, 0.25, 0}, {0, 0, 1}, false, tol));
  EXPECT_FALSE(linetest(tri, seg(v3<T>(0.25, 0.25, 1), v3<T>(0.25, 0.25, 0.5))));
  // In the triangle's plane: across it, through vertex a only, ending on edge ab, and beside it.
  EXPECT_TRUE(linetest(tri, seg(v3<T>(-1, 0.25, 0), v3<T>(2, 0.25, 0))));
  EXPECT_TRUE(isMiss(linecast(tri, seg(v3<T>(-1, 0.25, 0), v3<T>(2, 0.25, 0)))));
  EXPECT_TRUE(linetest(tri, seg(v3<T>(-1, 1, 0), v3<T>(1, -1, 0))));
  EXPECT_TRUE(linetest(tri, seg(v3<T>(0.5, -1, 0), v3<T>(0.5, 0, 0))));
  EXPECT_FALSE(linetest(tri, seg(v3<T>(-1, 2, 0), v3<T>(2, 2, 0))));
  EXPECT_FALSE(linetest(tri, seg(v3<T>(0.5, -1, 0), v3<T>(0.5, -0.5, 0))));
  // Points: on the triangle, just above it, in its plane outside it.
  EXPECT_TRUE(linetest(tri, seg(v3<T>(0.25, 0.25, 0), v3<T>(0.25, 0.25, 0))));
  EXPECT_FALSE(linetest(tri, seg(v3<T>(0.25, 0.25, 0.001), v3<T>(0.25, 0.25, 0.001))));
  EXPECT_FALSE(linetest(tri, seg(v3<T>(0.6, 0.6, 0), v3<T>(0.6, 0.6, 0))));
}

// ---- named hard cases ---------------------------------------------------------------------------

// Rays parallel to a slab (direction component +0 or -0) whose origin lies exactly on one of the
// slab's planes. The slab test computes (plane - origin) / 0 = 0 / 0 = NaN there; a closed box
// must count the plane as inside, so the ray hits. Every face of [0, 1]^3, both zero signs.
TYPED_TEST(HardCase, ParallelToSlabWithOriginOnItsPlane) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const AabbT<T> box{v3<T>(0, 0, 0), v3<T>(1, 1, 1)};
  for (int a = 0; a < 3; ++a) {  // the axis the ray is parallel to (origin on its plane)
    const int b = (a + 1) % 3;   // the axis the ray travels along
    const int c = (a + 2) % 3;   // the third axis: also parallel, origin mid-slab
    for (T face : {T(0), T(1)}) {
      for (T zero : {T(0), -T(0)}) {
        SCOPED_TRACE("parallel axis " + std::to_string(a) + ", face " + std::to_string(face) +
                     ", zero " + (std::signbit(zero) ? "-0" : "+0"));
        Vec3<T> d;
        d[a] = zero;
        d[b] = 1;
        d[c] = zero;
        Vec3<T> o;
        o[a] = face;
        o[b] = -2;
        o[c] = T(0.5);
        // From outside: enters the b = 0 face at t = 2, normal -e_b.
        Vec3d point = wide(o), normal = Vec3d::Zero();
        point[b] = 0;
        normal[b] = -1;
        EXPECT_TRUE(isHit(raycast(box, ray(o, d)), 2, point, normal, false, tol));
        // Going the other way (d[b] = -1) from b = 3: enters b = 1 at t = 2, normal +e_b.
        Vec3<T> o2 = o, d2 = d;
        o2[b] = 3;
        d2[b] = -1;
        point[b] = 1;
        normal[b] = 1;
        EXPECT_TRUE(isHit(raycast(box, ray(o2, d2)), 2, point, normal, false, tol));
        // From a point on the face itself (b = 0.25): inside the closed box, leaves b = 1 at
        // t = 0.75 with the outward +e_b negated.
        Vec3<T> o3 = o;
        o3[b] = T(0.25);
        point[b] = 1;
        normal[b] = -1;
        EXPECT_TRUE(isHit(raycast(box, ray(o3, d)), 0.75, point, normal, true, tol));
        // Along an edge: the origin on the plane of axis c as well.
        Vec3<T> o4 = o;
        o4[c] = face;
        EXPECT_TRUE(raycast(box, ray(o4, d)).has_value());
        // One ulp outside the plane: a miss, so the closedness is exact, not a tolerance.
        Vec3<T> o5 = o;
        o5[a] = std::nextafter(face, face == 0 ? -kInf<T> : kInf<T>);
        EXPECT_TRUE(isMiss(raycast(box, ray(o5, d))));
        // And the linetest along the same line agrees.
        Vec3<T> end = o;
        end[b] = 5;
        EXPECT_TRUE(linetest(box, seg(o, end)));
        Vec3<T> end5 = o5;
        end5[b] = 5;
        EXPECT_FALSE(linetest(box, seg(o5, end5)));
      }
    }
  }
}

// A W2-style heightfield (../shared/WORKLOADS.md): G x G vertices over x, z in [-4, 4], spacing
// 0.5 (exact in binary), heights y = 8 sin(0.07 x) cos(0.05 z) + 3 sin(0.31 x + 0.17 z), two
// triangles per cell in W2's order.
template <class T>
struct Grid {
  static constexpr int kG = 17;
  std::vector<Vec3<T>> vertices;
  std::vector<TriangleT<T>> triangles;
  Grid() {
    for (int j = 0; j < kG; ++j)
      for (int i = 0; i < kG; ++i) {
        const double x = -4 + 0.5 * i, z = -4 + 0.5 * j;
        vertices.push_back(v3<T>(
            x, 8 * std::sin(0.07 * x) * std::cos(0.05 * z) + 3 * std::sin(0.31 * x + 0.17 * z), z));
      }
    for (int j = 0; j + 1 < kG; ++j)
      for (int i = 0; i + 1 < kG; ++i) {
        triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      }
  }
  const Vec3<T>& v(int i, int j) const { return vertices[std::size_t(j * kG + i)]; }
};

// The number of triangles a ray hits (the closest hit is not needed: any hit means no leak).
template <class T, class Hit>
int hitCount(const Grid<T>& g, const RayT<T>& r, Hit&& hit) {
  int n = 0;
  for (const TriangleT<T>& tri : g.triangles) n += hit(tri, r) ? 1 : 0;
  return n;
}

// Rays through the grid's shared edges and vertices, built so that they pass through them
// exactly where floating point allows it:
// - vertical rays, both ways, through every vertex and through the midpoint and quarter points
//   of every edge (horizontal, vertical, diagonal): the shear of a vertical ray is exact, so
//   they meet the edges exactly;
// - horizontal rays along z in the plane x = const of a grid column, and along x in a grid row's
//   plane z = const, at the height of a vertex or halfway between two: they cross the row's or
//   column's shared edges exactly (the edge function of an edge in the ray's plane is exactly 0);
// - random directions aimed at random points of interior edges and at interior vertices, from 20
//   units away: the rounded ray passes within an ulp or two of the edge, whose neighbourhood the
//   mesh covers. The directions are within 23 degrees of vertical (x and z components at most
//   0.3 of y), steeper than the terrain's steepest slope (56 degrees: |grad y| <= 8 * 0.07 +
//   3 * 0.31 = 1.49), so the mesh does not fold in the ray's view. (A ray more grazing than the
//   surface can be tangent to it along a silhouette edge, where the two triangles face the ray
//   from opposite sides and rounding may legitimately put the ray just outside both.)
template <class T>
Vec3<T> steepDirection(workloads::Random& rng) {
  const double y = rng.uniform(0, 1) < 0.5f ? -1 : 1;
  return Vec3d(0.3 * rng.uniform(-1, 1), y, 0.3 * rng.uniform(-1, 1)).normalized().cast<T>();
}

template <class T>
std::vector<RayT<T>> edgeAndVertexRays(const Grid<T>& g) {
  std::vector<RayT<T>> rays;
  const int G = Grid<T>::kG;
  for (int j = 0; j < G; ++j)
    for (int i = 0; i < G; ++i) {
      const Vec3<T>& p = g.v(i, j);
      for (double f : {0.0, 0.25, 0.5})
        for (int e = 0; e < 3; ++e) {
          if (f == 0 && e > 0) continue;
          const double dx = e == 0 || e == 2 ? 0.5 * f : 0, dz = e == 1 || e == 2 ? 0.5 * f : 0;
          if ((dx > 0 && i + 1 >= G) || (dz > 0 && j + 1 >= G)) continue;
          const T x = T(double(p.x()) + dx), z = T(double(p.z()) + dz);
          rays.push_back({Vec3<T>(x, T(50), z), v3<T>(0, -1, 0)});
          rays.push_back({Vec3<T>(x, T(-50), z), v3<T>(0, 1, 0)});
        }
    }
  for (int k = 0; k < G; ++k)
    for (int m = 0; m + 1 < G; ++m) {
      const Vec3<T>&c0 = g.v(k, m), &c1 = g.v(k, m + 1);  // column x = const
      const Vec3<T>&r0 = g.v(m, k), &r1 = g.v(m + 1, k);  // row z = const
      for (T y : {c0.y(), T((double(c0.y()) + double(c1.y())) / 2)}) {
        rays.push_back({Vec3<T>(c0.x(), y, T(-10)), v3<T>(0, 0, 1)});
        rays.push_back({Vec3<T>(c0.x(), y, T(10)), v3<T>(0, 0, -1)});
      }
      for (T y : {r0.y(), T((double(r0.y()) + double(r1.y())) / 2)}) {
        rays.push_back({Vec3<T>(T(-10), y, r0.z()), v3<T>(1, 0, 0)});
        rays.push_back({Vec3<T>(T(10), y, r0.z()), v3<T>(-1, 0, 0)});
      }
    }
  workloads::Random rng(2);
  for (int j = 1; j + 1 < G; ++j)
    for (int i = 1; i + 1 < G; ++i) {
      const Vec3<T>& p = g.v(i, j);
      for (const Vec3<T>* q : {&g.v(i + 1, j), &g.v(i, j + 1), &g.v(i + 1, j + 1)}) {
        const T s = T(rng.uniform(0.05f, 0.95f));
        const Vec3<T> target = p + s * (*q - p);
        const Vec3<T> d = steepDirection<T>(rng);
        rays.push_back({target - T(20) * d, d});
      }
      const Vec3<T> d = steepDirection<T>(rng);
      rays.push_back({p - T(20) * d, d});
    }
  return rays;
}

TYPED_TEST(HardCase, SharedEdgesAndVerticesOfAGridDoNotLeak) {
  using T = TypeParam;
  const Grid<T> g;
  const std::vector<RayT<T>> rays = edgeAndVertexRays(g);
  ASSERT_GT(rays.size(), 4000u);
  int leaks = 0;
  for (const RayT<T>& r : rays) {
    const int n = hitCount(g, r, [](const TriangleT<T>& t, const RayT<T>& q) {
      return raycast(t, WatertightRayT<T>(q)).has_value();
    });
    if (n == 0 && ++leaks <= 5)
      ADD_FAILURE() << "leak: origin (" << r.origin.transpose() << ") direction ("
                    << r.direction.transpose() << ")";
  }
  EXPECT_EQ(leaks, 0) << "of " << rays.size() << " rays";
  // The vertical rays through vertices hit at the vertex: t = 50 - y (a few roundings of 50).
  for (int j = 0; j < Grid<T>::kG; ++j)
    for (int i = 0; i < Grid<T>::kG; ++i) {
      const Vec3<T>& p = g.v(i, j);
      const RayT<T> down{Vec3<T>(p.x(), T(50), p.z()), v3<T>(0, -1, 0)};
      T best = kInf<T>;
      for (const TriangleT<T>& t : g.triangles)
        if (auto h = raycast(t, down)) best = std::min(best, h->t);
      EXPECT_NEAR(best, 50 - double(p.y()), 16 * kEps<T> * 60);
    }
}

// Grazing: tangent to a sphere, along a box face and edge, along an OBB face. Closed shapes:
// touching is a hit; one ulp away is a miss.
TYPED_TEST(HardCase, GrazingRays) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const Vec3<T> x = v3<T>(1, 0, 0);
  // Unit sphere, line y = 1: tangent at (0, 1, 0), t = 5. (e = (5, -1, 0), m = (0, -1, 0),
  // r^2 - |m|^2 = 0, near root (26 - 1) / 5 = 5.) The normal (0, 1, 0) is perpendicular to the ray.
  const SphereT<T> s{v3<T>(0, 0, 0), T(1)};
  EXPECT_TRUE(isHit(raycast(s, ray(v3<T>(-5, 1, 0), x)), 5, {0, 1, 0}, {0, 1, 0}, false, tol));
  EXPECT_TRUE(isMiss(raycast(s, ray(Vec3<T>(T(-5), std::nextafter(T(1), T(2)), T(0)), x))));
  // Box [-1, 1]^3, along the top face y = 1: enters x = -1 at t = 4.
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(-5, 1, 0), x)), 4, {-1, 1, 0}, {-1, 0, 0}, false, tol));
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(-5, 1, 1), x)), 4, {-1, 1, 1}, {-1, 0, 0}, false, tol));
  EXPECT_TRUE(isMiss(raycast(box, ray(Vec3<T>(T(-5), std::nextafter(T(1), T(2)), T(0)), x))));
  // The same line from a point of the face: in the closed box, it leaves at x = 1 (t = 1).
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(0, 1, 0), x)), 1, {1, 1, 0}, {-1, 0, 0}, true, tol));
  // The OBB of ObbRaycast (world y in [-2, 2]) along its face y = 2: in local coordinates the
  // origin is on the plane of local x, the direction's local x is exactly 0. Enters x = 0.5 at 3.5.
  const ObbT<T> obb{v3<T>(1, 0, 0), v3<T>(2, 0.5, 1), quarterTurnZ<T>()};
  EXPECT_TRUE(
      isHit(raycast(obb, ray(v3<T>(-3, 2, 0), x)), 3.5, {0.5, 2, 0}, {-1, 0, 0}, false, tol));
  EXPECT_TRUE(isMiss(raycast(obb, ray(Vec3<T>(T(-3), std::nextafter(T(2), T(3)), T(0)), x))));
}

// Degenerate triangles (collinear or repeated vertices) have no area and no normal: simdphys
// defines them as never hit, by raycasts, linecasts and linetests alike. A thin but
// non-degenerate sliver is hit normally.
TYPED_TEST(HardCase, DegenerateTriangles) {
  using T = TypeParam;
  const TriangleT<T> collinear{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(2, 0, 0)};
  const TriangleT<T> repeated{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(1, 0, 0)};
  const TriangleT<T> point{v3<T>(1, 1, 1), v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  const Vec3<T> down = v3<T>(0, -1, 0);
  // Through the segment the collinear triangle covers: exactly, straight down and obliquely.
  EXPECT_TRUE(isMiss(raycast(collinear, ray(v3<T>(0.5, 1, 0), down))));
  EXPECT_TRUE(isMiss(raycast(
      collinear, ray(v3<T>(1.5, 1, 1), unitTowards<T>(v3<T>(1.5, 1, 1), v3<T>(1.5, 0, 0))))));
  EXPECT_TRUE(isMiss(raycast(collinear, ray(v3<T>(1, 0, 5), v3<T>(0, 0, -1)))));  // via vertex b
  EXPECT_TRUE(isMiss(raycast(repeated, ray(v3<T>(0.5, 1, 0), down))));
  EXPECT_TRUE(isMiss(raycast(point, ray(v3<T>(1, 5, 1), down))));
  EXPECT_FALSE(linetest(collinear, seg(v3<T>(0.5, 1, 0), v3<T>(0.5, -1, 0))));
  EXPECT_TRUE(isMiss(linecast(collinear, seg(v3<T>(0.5, 1, 0), v3<T>(0.5, -1, 0)))));
  EXPECT_FALSE(linetest(collinear, seg(v3<T>(-1, 0, 0), v3<T>(3, 0, 0))));     // along it
  EXPECT_FALSE(linetest(collinear, seg(v3<T>(0.5, 0, 0), v3<T>(0.5, 0, 0))));  // a point on it
  // A sliver (0,0,0), (1,0,0), (2,0.001,0): at x = 1.5 it spans y in [0.0005, 0.00075]. Normal
  // (1,0,0) x (2,0.001,0) = (0, 0, 0.001), unit +z, facing a ray going down z.
  const TriangleT<T> sliver{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(2, 0.001, 0)};
  EXPECT_TRUE(isHit(raycast(sliver, ray(v3<T>(1.5, 0.0006, 5), v3<T>(0, 0, -1))), 5,
                    {1.5, 0.0006, 0}, {0, 0, 1}, false, kHandTol<T>));
  EXPECT_TRUE(isMiss(raycast(sliver, ray(v3<T>(1.5, 0.0004, 5), v3<T>(0, 0, -1)))));
}

// Zero-size boxes (a point, a flat box), a zero-extent OBB and a zero-radius sphere: closed, so
// a ray through them hits; the normal is the face normal of the slab reached last (the lowest
// axis on ties), for the sphere -direction.
TYPED_TEST(HardCase, ZeroSizeBoxes) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const AabbT<T> point{v3<T>(1, 2, 3), v3<T>(1, 2, 3)};
  const Vec3<T> z = v3<T>(0, 0, 1);
  EXPECT_TRUE(isHit(raycast(point, ray(v3<T>(1, 2, 0), z)), 3, {1, 2, 3}, {0, 0, -1}, false, tol));
  // From the point itself: t = 0 (entry = exit = 0).
  EXPECT_TRUE(isHit(raycast(point, ray(v3<T>(1, 2, 3), z)), 0, {1, 2, 3}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isMiss(raycast(point, ray(Vec3<T>(T(1), std::nextafter(T(2), T(3)), T(0)), z))));
  // Diagonally to the point box (1,1,1): each slab gives 1 / d with the same d, the same t.
  const AabbT<T> corner{v3<T>(1, 1, 1), v3<T>(1, 1, 1)};
  const T c = T(1) / std::sqrt(T(3));
  EXPECT_TRUE(isHit(raycast(corner, ray(v3<T>(0, 0, 0), Vec3<T>(c, c, c))), std::sqrt(3.0),
                    {1, 1, 1}, {-1, 0, 0}, false, tol));
  // A flat box y = 1, x and z in [0, 2]: crossed from above at t = 4; met edge-on in its plane.
  const AabbT<T> flat{v3<T>(0, 1, 0), v3<T>(2, 1, 2)};
  EXPECT_TRUE(isHit(raycast(flat, ray(v3<T>(1, 5, 1), v3<T>(0, -1, 0))), 4, {1, 1, 1}, {0, 1, 0},
                    false, tol));
  EXPECT_TRUE(isHit(raycast(flat, ray(v3<T>(-1, 1, 1), v3<T>(1, 0, 0))), 1, {0, 1, 1}, {-1, 0, 0},
                    false, tol));
  EXPECT_TRUE(linetest(flat, seg(v3<T>(1, 1, 1), v3<T>(1, 1, 1))));
  // An OBB of zero extents at (1, 2, 3), turned a quarter about z: the ray along z through it.
  const ObbT<T> obb{v3<T>(1, 2, 3), v3<T>(0, 0, 0), quarterTurnZ<T>()};
  EXPECT_TRUE(isHit(raycast(obb, ray(v3<T>(1, 2, 0), z)), 3, {1, 2, 3}, {0, 0, -1}, false, tol));
  // A zero-radius sphere: hit only through its centre, normal -direction.
  const SphereT<T> dot{v3<T>(1, 2, 3), T(0)};
  EXPECT_TRUE(isHit(raycast(dot, ray(v3<T>(1, 2, 0), z)), 3, {1, 2, 3}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isHit(raycast(dot, ray(v3<T>(1, 2, 3), z)), 0, {1, 2, 3}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isMiss(raycast(dot, ray(v3<T>(1, 2.001, 0), z))));
}

// A ray starting on the surface. Sphere: heading in hits at t = 0 (entry), heading out hits at
// t = 0 with inside = true (exit), tangent hits at t = 0 (entry = exit) with the normal
// perpendicular to the ray. Boxes the same; planes and triangles hit at t = 0.
TYPED_TEST(HardCase, RayStartingOnTheSurface) {
  using T = TypeParam;
  const double tol = kHandTol<T>;
  const SphereT<T> s{v3<T>(0, 0, 0), T(1)};
  const Vec3<T> z = v3<T>(0, 0, 1);
  EXPECT_TRUE(isHit(raycast(s, ray(v3<T>(0, 0, -1), z)), 0, {0, 0, -1}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isHit(raycast(s, ray(v3<T>(0, 0, 1), z)), 0, {0, 0, 1}, {0, 0, -1}, true, tol));
  EXPECT_TRUE(isHit(raycast(s, ray(v3<T>(1, 0, 0), z)), 0, {1, 0, 0}, {1, 0, 0}, false, tol));
  const AabbT<T> box{v3<T>(-1, -1, -1), v3<T>(1, 1, 1)};
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(0, 0, -1), z)), 0, {0, 0, -1}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isHit(raycast(box, ray(v3<T>(0, 0, 1), z)), 0, {0, 0, 1}, {0, 0, -1}, true, tol));
  const ObbT<T> obb{v3<T>(0, 0, 0), v3<T>(1, 1, 1), quarterTurnZ<T>()};
  EXPECT_TRUE(isHit(raycast(obb, ray(v3<T>(0, 0, -1), z)), 0, {0, 0, -1}, {0, 0, -1}, false, tol));
  EXPECT_TRUE(isHit(raycast(obb, ray(v3<T>(0, 0, 1), z)), 0, {0, 0, 1}, {0, 0, -1}, true, tol));
  const PlaneT<T> plane{z, T(0)};
  EXPECT_TRUE(isHit(raycast(plane, ray(v3<T>(3, 4, 0), z)), 0, {3, 4, 0}, {0, 0, -1}, false, tol));
  const TriangleT<T> tri{v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(0, 1, 0)};
  EXPECT_TRUE(isHit(raycast(tri, ray(v3<T>(0.25, 0.25, 0), z)), 0, {0.25, 0.25, 0}, {0, 0, -1},
                    false, tol));
}

// The edge functions fall back to more precision when they round to exactly 0. Float:
// (1 + 2^-12)^2 = 1 + 2^-11 + 2^-24 rounds (tie to even) to 1 + 2^-11 = (1 + 2^-11) * 1, so the
// float difference is 0 while the exact one is 2^-24. Double: (1 + 2^-27)^2 = 1 + 2^-26 + 2^-54
// rounds to 1 + 2^-26, exact difference 2^-54.
TYPED_TEST(HardCase, EdgeFunctionFallbackDecidesTheSign) {
  using T = TypeParam;
  const int k = std::is_same_v<T, float> ? 12 : 27;
  const T a = T(1) + std::ldexp(T(1), -k);         // 1 + 2^-k
  const T cc = T(1) + std::ldexp(T(1), -(k - 1));  // 1 + 2^-(k-1)
  const T ab = a * a;
  const T cd = cc * T(1);
  EXPECT_EQ(ab - cd, T(0)) << "the plain difference rounds to 0";
  EXPECT_EQ(detail::rays::differenceOfProducts(a, a, cc, T(1)), std::ldexp(T(1), -2 * k));
  EXPECT_EQ(detail::rays::differenceOfProducts(cc, T(1), a, a), -std::ldexp(T(1), -2 * k));
  EXPECT_EQ(detail::rays::differenceOfProducts(T(3), T(5), T(5), T(3)), T(0));  // really zero
}

// Shapes of size 1e-2 at coordinates of 1e5, rays from about 1 away. The float results are
// compared with double results computed from the same (float) inputs. Bound: the differences
// origin - shape are exact (Sterbenz: operands within a factor of 2), after which every value is
// of the size of the distance D = |origin - centre| + size ~ 2, so t is within 32 eps_f * D
// (eps_f * D is an ulp of the quantities involved; 32 covers ~10 roundings and the shear or
// rotation). For the plane n.p + d the two terms are ~1.7e5 and cancel; simdphys evaluates it in
// double for float input, so the same bound holds. Only rays aimed at the central half of each
// shape are compared, where t is not sensitive to the direction (grazing hits are).
TEST(HardCaseFloat, LargeCoordinatesSmallShapes) {
  workloads::Random rng(5);
  const Vec3d base(1e5, -1e5, 1e5);
  std::map<std::string, int> compared;
  for (int i = 0; i < 400; ++i) {
    const Vec3f centre =
        (base + Vec3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))).cast<float>();
    const float size = rng.uniform(0.005f, 0.01f);
    const Vec3f origin =
        (wide(centre) + Vec3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)))
            .cast<float>();
    // The aim point in double (in float it would be rounded to 2^-7 = 0.0078, about the size).
    const Vec3d target = wide(centre) + 0.5 * size * rng.uniform(0, 1) * wide(rng.unitDirection());
    const Ray r{origin, (target - wide(origin)).normalized().cast<float>()};
    const Rayd rd = cast<double>(r);
    const double D = maxAbs(wide(origin) - wide(centre)) * std::sqrt(3.0) + 2 * size;
    const double bound = 32 * kEps<float> * D;
    const auto compare = [&](const auto& f, const auto& d, const char* what) {
      ASSERT_TRUE(f.has_value() && d.has_value()) << what << " case " << i;
      EXPECT_NEAR(f->t, d->t, bound) << what << " case " << i;
      ++compared[what];
    };
    const Sphere s{centre, size};
    compare(raycast(s, r), raycast(cast<double>(s), rd), "sphere");
    const Aabb b = Aabb::fromCenter(centre, Vec3f::Constant(size));
    compare(raycast(b, r), raycast(cast<double>(b), rd), "aabb");
    const Mat3f axes =
        Eigen::AngleAxisd(rng.uniform(0, 6.28f), rng.unitDirection().cast<double>().normalized())
            .toRotationMatrix()
            .cast<float>();
    const Obb o{centre, Vec3f::Constant(size), axes};
    compare(raycast(o, r), raycast(cast<double>(o), rd), "obb");
    const Vec3f n = rng.unitDirection();
    const Plane p{n, -n.dot(centre)};  // the plane's d is the float rounding of -n.c
    if (std::abs(n.dot(r.direction)) > 0.3f)
      compare(raycast(p, r), raycast(cast<double>(p), rd), "plane");
    // A triangle near the centre with vertices on the float grid there (2^-7 apart: a triangle
    // of size 1e-2 can only be that coarse at 1e5), facing the ray enough (|cos| > 0.3) not to be
    // grazing; only rays meeting it well inside (barycentric > 0.05) are compared.
    const auto gridPoint = [&] {
      Vec3f q = centre;
      for (int k = 0; k < 3; ++k) q[k] += std::ldexp(std::round(rng.uniform(-2.5f, 2.5f)), -7);
      return q;
    };
    const Triangle t{gridPoint(), gridPoint(), gridPoint()};
    const Vec3d tn = (wide(t.b) - wide(t.a)).cross(wide(t.c) - wide(t.a)).normalized();
    const auto tf = raycast(t, r);
    const auto td = raycast(cast<double>(t), rd);
    if (std::abs(tn.dot(wide(r.direction))) > 0.3 && td) {
      const Vec3d w = barycentric(cast<double>(t), wide(td->point));
      if (w.minCoeff() > 0.05) compare(tf, td, "triangle");
    }
  }
  // Every sphere, box and OBB; the planes not too oblique (~70%); the triangles hit well inside.
  EXPECT_EQ(compared["sphere"], 400);
  EXPECT_EQ(compared["aabb"], 400);
  EXPECT_EQ(compared["obb"], 400);
  EXPECT_GT(compared["plane"], 200);
  EXPECT_GT(compared["triangle"], 40);
}

// Shapes of size 1e-6. (a) The whole scene at that scale (origin ~1e-5 from the shape): nothing
// in simdphys is an absolute epsilon, so float keeps its relative precision and the same bound as
// above holds, relative to D ~ 2e-5. (b) The shape 1e-6 wide at distance ~1 from the origin: the
// bound 32 eps_f D ~ 4e-6 is larger than the shape (an ulp of 1 is 1.2e-7, a float ray cannot do
// better), but every ray aimed at the central half still hits, in float as in double.
TEST(HardCaseFloat, TinyShapes) {
  workloads::Random rng(7);
  int compared = 0;
  for (double scale : {1e-6, 1.0}) {
    for (int i = 0; i < 300; ++i) {
      const double size = 1e-6 * rng.uniform(0.5f, 1.0f);
      const Vec3d c = (scale == 1.0 ? 1.0 : 1e-5) *
                      Vec3d(rng.uniform(0.5f, 1), rng.uniform(0.5f, 1), rng.uniform(0.5f, 1));
      const Vec3f centre = c.cast<float>();
      const Vec3f origin = (scale == 1.0 ? Vec3d::Zero() : Vec3d(c * -0.5)).cast<float>();
      const Vec3d target =
          wide(centre) + 0.5 * size * rng.uniform(0, 1) * wide(rng.unitDirection());
      const Ray r{origin, (target - wide(origin)).normalized().cast<float>()};
      const Rayd rd = cast<double>(r);
      const double D = (wide(origin) - wide(centre)).norm() + 2 * size;
      const double bound = 32 * kEps<float> * D;
      const auto compare = [&](const auto& f, const auto& d, const char* what) {
        ASSERT_TRUE(f.has_value() && d.has_value()) << what << " scale " << scale << " case " << i;
        EXPECT_NEAR(f->t, d->t, bound) << what << " scale " << scale << " case " << i;
        ++compared;
      };
      const Sphere s{centre, float(size)};
      compare(raycast(s, r), raycast(cast<double>(s), rd), "sphere");
      const Aabb b = Aabb::fromCenter(centre, Vec3f::Constant(float(size)));
      compare(raycast(b, r), raycast(cast<double>(b), rd), "aabb");
      const Mat3f axes =
          Eigen::AngleAxisd(rng.uniform(0, 6.28f), rng.unitDirection().cast<double>().normalized())
              .toRotationMatrix()
              .cast<float>();
      const Obb o{centre, Vec3f::Constant(float(size)), axes};
      compare(raycast(o, r), raycast(cast<double>(o), rd), "obb");
      // An equilateral triangle facing the ray, centred on the shape's centre, circumradius 4
      // sizes (inscribed radius 2 sizes, around the aim within 0.5 size).
      const Vec3d dir = wide(r.direction);
      const Vec3d u = dir.unitOrthogonal(), v = dir.cross(u);
      const Triangle t{(wide(centre) + 4 * size * u).cast<float>(),
                       (wide(centre) + 4 * size * (-0.5 * u + 0.866 * v)).cast<float>(),
                       (wide(centre) + 4 * size * (-0.5 * u - 0.866 * v)).cast<float>()};
      compare(raycast(t, r), raycast(cast<double>(t), rd), "triangle");
    }
  }
  EXPECT_EQ(compared, 2 * 300 * 4);
}

// ---- the book's faults --------------------------------------------------------------------------
// The Game Physics Cookbook's raycasts (chapter 10, 11), worked by hand on each case.

// The book's sphere raycast has no test for a sphere behind the ray: from (0,0,0) along +z
// against the unit sphere at (0,0,-5) it computes e = (0,0,-5), a = e.d = -5, b^2 = 25 - 25 = 0,
// f = 1, and returns a hit at t = a - f = -6.
TEST(BookErrors, SphereBehindTheRayIsAMiss) {
  EXPECT_TRUE(isMiss(raycast(Sphere{{0, 0, -5}, 1}, Ray{{0, 0, 0}, {0, 0, 1}})));
}

// For a ray starting inside, the book returns the outward normal at the exit, which points along
// the ray (dot > 0). simdphys negates it so every normal faces the ray.
TEST(BookErrors, InsideNormalsFaceTheRay) {
  const Ray r{{0.1f, 0.2f, 0.3f}, Vec3f(1, 2, 2) / 3};
  const auto s = raycast(Sphere{{0, 0, 0}, 1}, r);
  const auto b = raycast(Aabb{{-1, -1, -1}, {1, 1, 1}}, r);
  const auto o = raycast(Obb{{0, 0, 0}, {1, 1, 1}, quarterTurnZ<float>()}, r);
  for (const auto& h : {s, b, o}) {
    ASSERT_TRUE(h.has_value());
    EXPECT_TRUE(h->inside);
    EXPECT_LT(h->normal.dot(r.direction), 0);
  }
  // The sphere's exit point p is on the unit sphere: its outward normal is p, ours -p.
  EXPECT_LT(maxAbs(wide(s->normal) + wide(s->point)), 1e-6);
}

// The book replaces a direction component with |d| <= FLT_EPSILON by 0.00001. For the long box
// [0, 1e6] x [0, 1] x [0, 1] and the ray from (-1, -0.5, 0.5) along +x (y = -0.5 is outside the
// box) that gives y-slab t in [0.5/1e-5, 1.5/1e-5] = [5e4, 1.5e5], z-slab [-5e4, 5e4], x-slab
// [1, 1e6 + 1]: tmin = 5e4 <= tmax = 5e4, a hit at t = 5e4 that is not on the box. simdphys
// divides by the zero itself: (0 - (-0.5)) / 0 = +inf, a miss.
TEST(BookErrors, AabbZeroDirectionIsNotReplacedByASmallNumber) {
  const Aabb longBox{{0, 0, 0}, {1e6f, 1, 1}};
  EXPECT_TRUE(isMiss(raycast(longBox, Ray{{-1, -0.5f, 0.5f}, {1, 0, 0}})));
  EXPECT_TRUE(isMiss(raycast(longBox, Ray{{-1, -0.5f, 0.5f}, {1, -0.0f, 0}})));
  // And a direction component of 1e-8 is not zero: from (0, -0.5, 0.5) it climbs 0.5 in 5e7,
  // beyond the box's length; the book's replacement by 1e-5 would hit at t = 5e4.
  const Vec3f d = Vec3f(1, 1e-8f, 0).normalized();
  EXPECT_TRUE(isMiss(raycast(longBox, Ray{{0, -0.5f, 0.5f}, d})));
}

// The book's OBB raycast tests a parallel axis i with `-e[i] - size[i] > 0 || -e.x + size[i] < 0`
// (e.x for every axis). The unit OBB at the origin and the ray from (-5, 0.5, 0) along +x: on
// axis y (parallel), e = centre - origin = (5, -0.5, 0), so -e.x + 1 = -4 < 0 and the book returns
// "no hit" for a ray that enters the box at x = -1, t = 4.
TEST(BookErrors, ObbParallelAxisUsesItsOwnAxis) {
  const Obb unit{{0, 0, 0}, {1, 1, 1}, Mat3f::Identity()};
  EXPECT_TRUE(isHit(raycast(unit, Ray{{-5, 0.5f, 0}, {1, 0, 0}}), 4, {-1, 0.5, 0}, {-1, 0, 0},
                    false, kHandTol<float>));
}

// The book's Linetest(AABB / OBB) is "raycast t <= length": a segment wholly inside the box
// gives the exit t > length, so false, while its Linetest(Sphere) says true for a segment inside
// the sphere. And a degenerate segment normalises a zero vector (NaN direction): false even
// inside. simdphys: touching means sharing a point, for every shape.
TEST(BookErrors, LinetestOfSegmentsInsideAndOfPoints) {
  const Aabb box{{-1, -1, -1}, {1, 1, 1}};
  EXPECT_TRUE(linetest(box, Segment{{-0.5f, 0, 0}, {0.5f, 0, 0}}));
  EXPECT_TRUE(linetest(Obb{{0, 0, 0}, {1, 1, 1}}, Segment{{-0.5f, 0, 0}, {0.5f, 0, 0}}));
  EXPECT_TRUE(linetest(Sphere{{0, 0, 0}, 1}, Segment{{-0.5f, 0, 0}, {0.5f, 0, 0}}));
  EXPECT_TRUE(linetest(box, Segment{{0.5f, 0, 0}, {0.5f, 0, 0}}));
  // The book's Linetest(Plane) returns false for a segment lying in the plane (n.ab == 0).
  EXPECT_TRUE(linetest(Plane{{0, 1, 0}, 0}, Segment{{0, 0, 0}, {1, 0, 0}}));
}

// The book's plane raycast is one-sided (n.d >= 0 returns no hit) and its triangle raycast goes
// through it: a ray reaching the back of a triangle misses. W2 and simdphys are two-sided.
TEST(BookErrors, PlaneAndTriangleAreTwoSided) {
  const Ray fromBelow{{0.25f, 0.25f, -1}, {0, 0, 1}};
  EXPECT_TRUE(raycast(Plane{{0, 0, 1}, 0}, fromBelow).has_value());
  EXPECT_TRUE(raycast(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, fromBelow).has_value());
}

// The book's triangle raycast intersects the plane, then accepts the rounded hit point if its
// barycentric coordinates are in [0, 1]. That method is not watertight: re-implemented here
// (two-sided, to isolate the leak), it lets some of the grid's edge and vertex rays through,
// which the watertight test above does not. This also shows that the no-leak test can fail.
std::optional<float> planeThenBarycentric(const Triangle& tri, const Ray& r) {
  const Vec3f n = (tri.b - tri.a).cross(tri.c - tri.a).normalized();
  const float nd = n.dot(r.direction);
  if (nd == 0) return std::nullopt;
  const float t = n.dot(tri.a - r.origin) / nd;
  if (!(t >= 0)) return std::nullopt;
  const Vec3f p = r.origin + t * r.direction;
  const Vec3f e0 = tri.b - tri.a, e1 = tri.c - tri.a, e2 = p - tri.a;
  const float d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = e2.dot(e0),
              d21 = e2.dot(e1);
  const float den = d00 * d11 - d01 * d01;
  const float v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  const float u = 1 - v - w;
  if (u >= 0 && v >= 0 && w >= 0) return t;
  return std::nullopt;
}

TEST(BookErrors, PlaneThenBarycentricTriangleTestLeaks) {
  const Grid<float> g;
  int leaks = 0;
  for (const Ray& r : edgeAndVertexRays(g))
    leaks += hitCount(g, r, [](const Triangle& t, const Ray& q) {
               return planeThenBarycentric(t, q).has_value();
             }) == 0;
  EXPECT_GT(leaks, 0);
}

// The book's sphere test computes the squared distance of the line from the centre as
// |e|^2 - (e.d)^2, which cancels: for a sphere of radius 1e-3 at distance ~100 in float both
// terms are ~1e4, their rounding errors ~1e-3, far more than r^2 = 1e-6, so aimed rays are
// reported as misses at random. simdphys uses the perpendicular vector instead.
TEST(BookErrors, SmallFarSphereKeepsItsPrecision) {
  workloads::Random rng(11);
  int bookMisses = 0, ours = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const Vec3f centre(60 + rng.uniform(0, 1), 50 + rng.uniform(0, 1), 60 + rng.uniform(0, 1));
    const float radius = 1e-3f;
    const Vec3f target = (wide(centre) + 0.3 * radius * wide(rng.unitDirection())).cast<float>();
    const Ray r{Vec3f::Zero(), unitTowards<float>(Vec3f::Zero(), target)};
    const Vec3f e = centre - r.origin;
    const float a = e.dot(r.direction);
    bookMisses += radius * radius - (e.squaredNorm() - a * a) < 0;  // the book's discriminant
    ours += raycast(Sphere{centre, radius}, r).has_value();
  }
  EXPECT_EQ(ours, n);
  EXPECT_GT(bookMisses, 0);
}

// ---- properties on random inputs ----------------------------------------------------------------

template <class T>
Vec3<T> randomIn(workloads::Random& r, float lo, float hi) {
  return v3<T>(r.uniform(lo, hi), r.uniform(lo, hi), r.uniform(lo, hi));
}

// A ray for a shape of the given centre and size: mostly from outside, aimed at or near the shape
// (so that hits, misses and grazes all occur), sometimes in a random direction, sometimes from
// inside.
template <class T>
RayT<T> randomRay(workloads::Random& r, const Vec3<T>& centre, float size) {
  const float kind = r.uniform(0, 1);
  Vec3<T> origin = kind < 0.15f ? Vec3<T>(centre + randomIn<T>(r, -0.5f * size, 0.5f * size))
                                : Vec3<T>(centre + randomIn<T>(r, -20, 20));
  if (kind < 0.7f) {
    const Vec3<T> target = centre + randomIn<T>(r, -1.3f * size, 1.3f * size);
    if (target != origin) return {origin, unitTowards<T>(origin, target)};
  }
  return {origin, r.unitDirection().template cast<T>()};
}

template <class T>
Mat3<T> randomRotation(workloads::Random& r) {
  // The float direction is unit to float precision only: normalised again in double.
  return Eigen::AngleAxisd(r.uniform(0, 6.2831853f), r.unitDirection().cast<double>().normalized())
      .toRotationMatrix()
      .template cast<T>();
}

struct Counts {
  int hits = 0, misses = 0, inside = 0;
};

// The properties of a hit or a miss on a closed convex solid, with `measure` its signed-distance
// oracle:
// - a hit has 0 <= t <= tMax, its point is o + t d and lies on the surface (|measure| <= tol),
//   the normal is unit (within 8 eps) and faces the ray (dot <= facingTol), `inside` says
//   whether the origin is in the solid;
// - no hit is closer: sampled points before t are outside (for an entry) or inside (for an
//   exit) the solid, within tol;
// - a miss misses: sampled points along the ray are never inside by more than tol.
// tol = 64 eps * scale, with scale the largest coordinate magnitude involved plus t: every
// computed quantity is a few (< 10) roundings away from exact, each of at most eps * scale.
template <class T, class Shape>
void checkSolid(const Shape& shape, const RayT<T>& r, const Vec3d& centre, double size,
                double facingTol, Counts& counts) {
  const auto h = raycast(shape, r);
  const Vec3d o = wide(r.origin), d = wide(r.direction);
  const double scale = maxAbs(o) + maxAbs(centre) + size + (h ? double(h->t) : 0);
  const double tol = 64 * kEps<T> * scale;
  const double m0 = measure(shape, o);
  if (!h) {
    ++counts.misses;
    EXPECT_GT(m0, -tol) << "a ray from inside always hits (the exit)";
    const double reach = (o - centre).norm() + 2 * size;
    for (int k = 0; k <= 400; ++k)
      ASSERT_GE(measure(shape, o + reach * k / 400 * d), -tol)
          << "missed, but sample " << k << " is inside";
    return;
  }
  ++counts.hits;
  counts.inside += h->inside;
  const double t = h->t;
  EXPECT_TRUE(t >= 0 && std::isfinite(t));
  EXPECT_LE(maxAbs(wide(h->point) - (o + t * d)), tol);
  EXPECT_LE(std::abs(measure(shape, wide(h->point))), tol) << "hit point off the surface";
  EXPECT_NEAR(h->normal.norm(), 1.0, 8 * kEps<T>);
  EXPECT_LE(wide(h->normal).dot(d), facingTol) << "normal does not face the ray";
  if (std::abs(m0) > tol) {
    EXPECT_EQ(h->inside, m0 < 0);
  }
  for (int k = 0; k < 64; ++k) {
    const double s = (t - tol) * k / 64;
    if (s < 0) break;
    const double m = measure(shape, o + s * d);
    if (h->inside) {
      ASSERT_LE(m, tol) << "exit at " << t << " but the ray is outside at " << s;
    } else {
      ASSERT_GE(m, -tol) << "entry at " << t << " but the ray is already inside at " << s;
    }
  }
  if (h->inside) {
    EXPECT_GE(measure(shape, o + (t + 4 * tol) * d), -tol) << "not out after the exit";
  }
}

TYPED_TEST(Property, Sphere) {
  using T = TypeParam;
  workloads::Random rng(101);
  Counts counts;
  for (int i = 0; i < 3000; ++i) {
    const SphereT<T> s{randomIn<T>(rng, -10, 10), T(rng.uniform(0.5f, 5))};
    const RayT<T> r = randomRay(rng, s.center, float(s.radius));
    // The sphere's normal is computed, not chosen: it faces the ray within a few ulps.
    checkSolid(s, r, wide(s.center), double(s.radius), 16 * kEps<T>, counts);
    // The normal is the outward one at the point (negated from inside).
    if (const auto h = raycast(s, r)) {
      const Vec3d outward = (wide(h->point) - wide(s.center)).normalized();
      const double scale = maxAbs(wide(r.origin)) + 10 + 5 + h->t;
      EXPECT_LE(maxAbs(wide(h->normal) - (h->inside ? -outward : outward)),
                64 * kEps<T> * scale / double(s.radius));
    }
  }
  EXPECT_GT(counts.hits, 600);
  EXPECT_GT(counts.misses, 600);
  EXPECT_GT(counts.inside, 200);
}

TYPED_TEST(Property, Aabb) {
  using T = TypeParam;
  workloads::Random rng(102);
  Counts counts;
  for (int i = 0; i < 3000; ++i) {
    const Vec3<T> c = randomIn<T>(rng, -10, 10), half = randomIn<T>(rng, 0.5f, 5);
    const AabbT<T> b{c - half, c + half};
    const RayT<T> r = randomRay(rng, c, 5);
    checkSolid(b, r, wide(c), 5 * std::sqrt(3.0), 0.0, counts);  // faces the ray exactly
    // The normal is a signed axis and the point lies exactly on that face.
    if (const auto h = raycast(b, r)) {
      int a;
      h->normal.cwiseAbs().maxCoeff(&a);
      EXPECT_EQ(std::abs(h->normal[a]), T(1));
      const T outward = h->inside ? -h->normal[a] : h->normal[a];
      EXPECT_EQ(h->point[a], outward > 0 ? b.max[a] : b.min[a]);
    }
  }
  EXPECT_GT(counts.hits, 600);
  EXPECT_GT(counts.misses, 600);
  EXPECT_GT(counts.inside, 200);
}

TYPED_TEST(Property, Obb) {
  using T = TypeParam;
  workloads::Random rng(103);
  Counts counts;
  for (int i = 0; i < 3000; ++i) {
    const ObbT<T> b{randomIn<T>(rng, -10, 10), randomIn<T>(rng, 0.5f, 5), randomRotation<T>(rng)};
    const RayT<T> r = randomRay(rng, b.center, 5);
    // The OBB normal is an axis of the box, chosen by the sign of the direction in the box frame;
    // in world space the dot product is recomputed: <= 0 within a few ulps.
    checkSolid(b, r, wide(b.center), 5 * std::sqrt(3.0), 16 * kEps<T>, counts);
    if (const auto h = raycast(b, r)) {
      const Vec3d outward = h->inside ? -wide(h->normal) : wide(h->normal);
      const Vec3d local = b.axes.template cast<double>().transpose() * outward;
      int a;
      local.cwiseAbs().maxCoeff(&a);
      EXPECT_NEAR(std::abs(local[a]), 1, 16 * kEps<T>);
      const double onFace = obbLocal(b, wide(h->point))[a] * (local[a] > 0 ? 1 : -1);
      EXPECT_NEAR(onFace, double(b.halfExtents[a]), 64 * kEps<T> * 40);
    }
  }
  EXPECT_GT(counts.hits, 600);
  EXPECT_GT(counts.misses, 600);
  EXPECT_GT(counts.inside, 200);
}

// Planes: the double oracle s(t) = n.(o + t d) + d crosses zero at tRef = -s(0) / n.d. Rays not
// within 1e-3 of parallel are compared with it: a hit iff tRef >= 0 (clear cases only: |tRef|
// above the tolerance), at t within tol / |n.d|; the point on the plane; the normal +-n facing
// the ray exactly.
TYPED_TEST(Property, Plane) {
  using T = TypeParam;
  workloads::Random rng(104);
  Counts counts;
  for (int i = 0; i < 3000; ++i) {
    const Vec3<T> n = rng.unitDirection().template cast<T>();
    const Vec3<T> p = randomIn<T>(rng, -10, 10);
    const PlaneT<T> plane{n, -n.dot(p)};
    const RayT<T> r = randomRay(rng, p, 5);
    const Vec3d o = wide(r.origin), d = wide(r.direction), nd = wide(n);
    const double rate = nd.dot(d);
    if (std::abs(rate) < 1e-3) continue;
    const double tRef = -(nd.dot(o) + double(plane.d)) / rate;
    const double tol = 64 * kEps<T> * (maxAbs(o) + 20 + std::abs(tRef)) / std::abs(rate);
    const auto h = raycast(plane, r);
    if (tRef < -tol) {
      EXPECT_TRUE(isMiss(h));
      ++counts.misses;
    } else if (tRef > tol) {
      ASSERT_TRUE(h.has_value());
      ++counts.hits;
      EXPECT_NEAR(h->t, tRef, tol);
      EXPECT_LE(std::abs(nd.dot(wide(h->point)) + double(plane.d)), tol);
      EXPECT_TRUE(h->normal == n || h->normal == Vec3<T>(-n));
      EXPECT_LE(h->normal.dot(r.direction), 0);
      EXPECT_FALSE(h->inside);
    }
  }
  EXPECT_GT(counts.hits, 600);
  EXPECT_GT(counts.misses, 600);
}

// Triangles: the double oracle intersects the plane at tRef and takes the barycentric
// coordinates there. Clear cases (the point further than 1e-4 (float) or 1e-10 (double) in
// barycentric units from every edge, the ray not within 1e-2 of parallel) must agree: a hit iff
// tRef >= 0 and all coordinates are positive; t within tol / |cos|; the normal +-n facing the ray.
TYPED_TEST(Property, Triangle) {
  using T = TypeParam;
  workloads::Random rng(105);
  Counts counts;
  const double margin = std::is_same_v<T, float> ? 1e-4 : 1e-10;
  for (int i = 0; i < 4000; ++i) {
    const Vec3<T> c = randomIn<T>(rng, -10, 10);
    const float size = rng.uniform(0.5f, 5);
    const TriangleT<T> tri{c + randomIn<T>(rng, -size, size), c + randomIn<T>(rng, -size, size),
                           c + randomIn<T>(rng, -size, size)};
    // Mostly aimed at a point of the triangle's plane near it (barycentric coordinates in
    // [-0.2, 1.2]), so that hits and near misses are both common.
    RayT<T> r = randomRay(rng, c, size);
    if (rng.uniform(0, 1) < 0.6f) {
      const T s = T(rng.uniform(-0.2f, 1.2f)), q = T(rng.uniform(-0.2f, 1.2f) * (1 - double(s)));
      const Vec3<T> target = tri.a + s * (tri.b - tri.a) + q * (tri.c - tri.a);
      if (target != r.origin) r.direction = unitTowards<T>(r.origin, target);
    }
    const Vec3d o = wide(r.origin), d = wide(r.direction);
    const Vec3d n = (wide(tri.b) - wide(tri.a)).cross(wide(tri.c) - wide(tri.a)).normalized();
    const double cosine = n.dot(d);
    if (std::abs(cosine) < 1e-2) continue;
    const double tRef = n.dot(wide(tri.a) - o) / cosine;
    const Vec3d w = barycentric(tri, o + tRef * d);
    const double tol = 64 * kEps<T> * (maxAbs(o) + 20 + std::abs(tRef)) / std::abs(cosine);
    const auto h = raycast(tri, r);
    const bool clearlyInside = w.minCoeff() > margin && tRef > tol;
    const bool clearlyOutside = w.minCoeff() < -margin || tRef < -tol;
    if (clearlyOutside) {
      EXPECT_TRUE(isMiss(h)) << "tRef " << tRef << " barycentric " << w.transpose();
      ++counts.misses;
    } else if (clearlyInside) {
      ASSERT_TRUE(h.has_value()) << "tRef " << tRef << " barycentric " << w.transpose();
      ++counts.hits;
      EXPECT_NEAR(h->t, tRef, tol);
      EXPECT_GE(barycentric(tri, wide(h->point)).minCoeff(), -margin);
      EXPECT_LE(maxAbs(wide(h->normal) - (cosine < 0 ? n : Vec3d(-n))), 16 * kEps<T>);
      EXPECT_LE(h->normal.dot(r.direction), 0);
      EXPECT_FALSE(h->inside);
    }
  }
  EXPECT_GT(counts.hits, 600);
  EXPECT_GT(counts.misses, 600);
}

// linetest and linecast against raycast on random segments (5% of them points): where the ray
// from start towards end hits at t <= length - tol, the segment hits at the same t (within tol)
// with the same inside flag and linetest is true; where it hits beyond length + tol or not at
// all, linecast has nothing and linetest is true only if the start is in the solid (clear cases
// of the oracle, beyond tol from the surface). Points: linetest is the containment test.
template <class T, class Shape>
void checkSegments(const Shape& shape, workloads::Random& rng, const Vec3d& centre, float size,
                   int& agreed) {
  constexpr bool solid = !std::is_same_v<Shape, PlaneT<T>> && !std::is_same_v<Shape, TriangleT<T>>;
  const Vec3<T> start = Vec3<T>(centre.cast<T>()) + randomIn<T>(rng, -3 * size, 3 * size);
  const bool point = rng.uniform(0, 1) < 0.05f;
  const Vec3<T> end =
      point ? start : Vec3<T>(centre.cast<T>() + randomIn<T>(rng, -3 * size, 3 * size));
  const SegmentT<T> s{start, end};
  const double tol = 64 * kEps<T> * (maxAbs(centre) + 4 * size);
  double m0 = 1;
  if constexpr (solid) m0 = measure(shape, wide(start));
  const bool lt = linetest(shape, s);
  const auto lc = linecast(shape, s);
  if (point) {
    EXPECT_FALSE(lc.has_value());
    if (!solid) {
      EXPECT_FALSE(lt);  // a random point is not on a plane or triangle
    } else if (std::abs(m0) > tol) {
      EXPECT_EQ(lt, m0 < 0);
    }
    ++agreed;
    return;
  }
  const T length = s.length();
  const auto rc = raycast(shape, RayT<T>{start, (end - start) / length});
  if (rc && rc->t <= length - tol) {
    ASSERT_TRUE(lc.has_value());
    EXPECT_NEAR(lc->t, rc->t, tol);
    EXPECT_EQ(lc->inside, rc->inside);
    EXPECT_LE(maxAbs(wide(lc->normal) - wide(rc->normal)), 1e-3);
    EXPECT_TRUE(lt);
    ++agreed;
  } else if (!rc || rc->t > length + tol) {
    EXPECT_FALSE(lc.has_value());
    if (!solid) {
      EXPECT_FALSE(lt);
    } else if (std::abs(m0) > tol) {
      EXPECT_EQ(lt, m0 < 0);
    }
    ++agreed;
  }
}

TYPED_TEST(Property, LinetestAgreesWithRaycast) {
  using T = TypeParam;
  workloads::Random rng(106);
  int agreed = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Vec3<T> c = randomIn<T>(rng, -10, 10);
    const float size = rng.uniform(0.5f, 3);
    checkSegments<T>(SphereT<T>{c, T(size)}, rng, wide(c), size, agreed);
    checkSegments<T>(AabbT<T>::fromCenter(c, randomIn<T>(rng, 0.5f * size, size)), rng, wide(c),
                     size, agreed);
    checkSegments<T>(ObbT<T>{c, randomIn<T>(rng, 0.5f * size, size), randomRotation<T>(rng)}, rng,
                     wide(c), size, agreed);
    const Vec3<T> nrm = rng.unitDirection().template cast<T>();
    checkSegments<T>(PlaneT<T>{nrm, -nrm.dot(c)}, rng, wide(c), size, agreed);
    checkSegments<T>(
        TriangleT<T>{c + randomIn<T>(rng, -size, size), c + randomIn<T>(rng, -size, size),
                     c + randomIn<T>(rng, -size, size)},
        rng, wide(c), size, agreed);
  }
  // All but the cases within tol of a boundary (a handful at most) were checked.
  EXPECT_GT(agreed, 5 * n - 20);
}

}  // namespace
}  // namespace simdphys

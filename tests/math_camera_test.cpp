// Tests of include/simdphys/math.hpp's camera side (view and projection, picking) and its vector
// helpers and tolerant comparison, in float and in double. Derivations and tolerances as in
// math_test.cpp.
#include "math_cases.hpp"

namespace simdphys {
namespace {

using namespace test;

// ---------------------------------------------------------------------------------------------
// View and projection

TYPED_TEST(Camera, LookAtFromPlusZTowardsTheOrigin) {
  using T = TypeParam;
  const Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  // forward = (0,0,-1), right = forward x up = (1,0,0), up = right x forward = (0,1,0): the
  // rotation is the identity and the view is a translation by (0,0,-5). All values are exact.
  Mat4<T> expected = Mat4<T>::Identity();
  expected(2, 3) = -5;
  EXPECT_TRUE(closeTo(view, expected, 0));
  EXPECT_TRUE(closeTo(transformPoint(view, Vec3<T>::Zero()), v3<T>(0, 0, -5), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 0, 5)), Vec3<T>::Zero(), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(1, 0, 0)), v3<T>(1, 0, -5), 0));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 1, 0)), v3<T>(0, 1, -5), 0));
}

TYPED_TEST(Camera, LookAtAlongPlusX) {
  using T = TypeParam;
  const Mat4<T> view = lookAt(Vec3<T>::Zero(), v3<T>(1, 0, 0), v3<T>(0, 1, 0));
  // forward = +x, right = x cross y = +z, up = z cross x = +y; all exact.
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(2, 0, 0)), v3<T>(0, 0, -2), 0));  // ahead
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 0, 1)), v3<T>(1, 0, 0), 0));   // right
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0, 1, 0)), v3<T>(0, 1, 0), 0));   // up
}

TYPED_TEST(Camera, LookAtGeneralCamera) {
  using T = TypeParam;
  const Vec3<T> eye = v3<T>(1, 2, 3), target = v3<T>(4, 6, 3);
  // forward = (3,4,0)/5 = (0.6,0.8,0); right = forward x y = (0,0,0.6) -> (0,0,1);
  // up = right x forward = (-0.8, 0.6, 0). The target is 5 ahead.
  const Mat4<T> view = lookAt(eye, target, Vec3<T>::UnitY());
  // Values up to 6 (ulp 4 eps) through a 3-term dot and a translation, with 0.6 and 0.8
  // themselves rounded: a few ulp, 32 eps.
  const double tol = 32 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(view, target), v3<T>(0, 0, -5), tol));
  EXPECT_TRUE(closeTo(transformPoint(view, eye), Vec3<T>::Zero(), tol));
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(1, 2, 4)), v3<T>(1, 0, 0), tol));  // eye + right
  EXPECT_TRUE(closeTo(transformPoint(view, v3<T>(0.2, 2.6, 3)), v3<T>(0, 1, 0), tol));  // + up
  // Rotation part orthonormal with det 1 (entries <= 1, a few roundings: 8 eps).
  const Mat3<T> r = view.template topLeftCorner<3, 3>();
  EXPECT_TRUE(closeTo(r * r.transpose(), Mat3<T>::Identity(), 8 * kEps<T>));
  EXPECT_TRUE(closeTo(r.determinant(), T(1), 8 * kEps<T>));
  // up need not be unit nor perpendicular to the view direction: only its plane matters. Same
  // matrix up to the roundings of normalising a different vector: tol as above.
  EXPECT_TRUE(closeTo(lookAt(eye, target, v3<T>(0, 7, 0)), view, tol));
  EXPECT_TRUE(closeTo(lookAt(eye, target, v3<T>(0.2, 1, 0)), view, tol));
  // Any Eigen expression is accepted.
  EXPECT_TRUE(closeTo(lookAt(eye, eye + v3<T>(3, 4, 0), 2 * Vec3<T>::UnitY()), view, tol));
}

TYPED_TEST(Camera, LookAtRejectsBadInput) {
  using T = TypeParam;
  const Vec3<T> eye = v3<T>(0, 0, 5), o = Vec3<T>::Zero(), y = Vec3<T>::UnitY();
  EXPECT_THROW(lookAt(eye, eye, y), Error);                   // eye == target
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 0, 1)), Error);        // up parallel to view
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 0, -3)), Error);       // up anti-parallel
  EXPECT_THROW(lookAt(eye, o, Vec3<T>::Zero()), Error);       // no up
  EXPECT_THROW(lookAt(v3<T>(kNaN<T>, 0, 5), o, y), Error);    // non-finite eye
  EXPECT_THROW(lookAt(eye, v3<T>(0, kInf<T>, 0), y), Error);  // non-finite target
  EXPECT_THROW(lookAt(eye, o, v3<T>(0, 1, kNaN<T>)), Error);  // non-finite up
  try {
    lookAt(eye, eye, y);
    ADD_FAILURE() << "lookAt(eye, eye, up) did not throw";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "lookAt: eye and target coincide");
  }
}

TYPED_TEST(Camera, PerspectiveHandWorked) {
  using T = TypeParam;
  // fovY = 90 deg: cot(45 deg) = 1. aspect 2, near 1, far 10:
  // m00 = 1/2, m11 = 1, m22 = far/(near-far) = -10/9, m23 = -near far/(far-near) = -10/9,
  // m32 = -1.
  const Mat4<T> p = perspective(kPi<T> / 2, T(2), T(1), T(10));
  Mat4<T> expected = Mat4<T>::Zero();
  expected(0, 0) = 0.5;
  expected(1, 1) = 1;
  expected(2, 2) = T(-10) / 9;
  expected(2, 3) = T(-10) / 9;
  expected(3, 2) = -1;
  // tan(pi/4) within an ulp or two, 10/9 rounded: entries <= 1.2 within 4 eps.
  EXPECT_TRUE(closeTo(p, expected, 4 * kEps<T>));

  // Near plane -> depth 0. z = m22 (-1) + m23 with m23 = 1 * m22: exact cancellation, unless the
  // compiler fuses a multiply-add, which leaves the rounding error of m22 (<= eps): 2 eps.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -1)), v3<T>(0, 0, 0), 2 * kEps<T>));
  // Far plane -> depth 1: z = (10/9) 10 - 10/9 = 10, w = 10. Roundings on values ~11 (ulp 8 eps)
  // divided by 10: 8 eps.
  const double tol = 8 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -10)), v3<T>(0, 0, 1), tol));
  // In between, depth = far (d - near) / (d (far - near)) at distance d = 2: 10/18 = 5/9.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(0, 0, -2)), v3<T>(0, 0, T(5) / 9), tol));
  // The frustum corners: at distance d the half-height is d tan(45 deg) = d and the half-width
  // 2d, so (2,1,-1) is the top-right near corner and (-20,-10,-10) the bottom-left far one.
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(2, 1, -1)), v3<T>(1, 1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(20, 10, -10)), v3<T>(1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(p, v3<T>(-20, -10, -10)), v3<T>(-1, -1, 1), tol));
  // fovY = 60 deg: m11 = cot(30 deg) = sqrt3; within a few ulp of 1.7 (eps each): 8 eps.
  EXPECT_TRUE(closeTo(perspective(kPi<T> / 3, T(1), T(1), T(10))(1, 1), std::sqrt(T(3)), tol));
}

TYPED_TEST(Camera, PerspectiveRejectsBadInput) {
  using T = TypeParam;
  const T fov = T(1);
  for (const T bad : {T(0), T(-0.1), kPi<T>, T(4), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(bad, T(1), T(1), T(10)), Error) << "fovY " << bad;
  for (const T bad : {T(0), T(-1), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(fov, bad, T(1), T(10)), Error) << "aspect " << bad;
  for (const T bad : {T(0), T(-1), kNaN<T>})
    EXPECT_THROW(perspective(fov, T(1), bad, T(10)), Error) << "near " << bad;
  for (const T bad : {T(1), T(0.5), kNaN<T>, kInf<T>})
    EXPECT_THROW(perspective(fov, T(1), T(1), bad), Error) << "far " << bad;
}

TYPED_TEST(Camera, OrthographicHandWorked) {
  using T = TypeParam;
  // Box x in [-2,4], y in [-1,3], view z in [-5,-1] (near 1, far 5):
  // m00 = 2/6, m03 = -(4-2)/6; m11 = 2/4, m13 = -(3-1)/4; m22 = -1/4, m23 = -1/4.
  const Mat4<T> o = orthographic(T(-2), T(4), T(-1), T(3), T(1), T(5));
  Mat4<T> expected = Mat4<T>::Identity();
  expected(0, 0) = T(1) / 3;
  expected(0, 3) = T(-1) / 3;
  expected(1, 1) = 0.5;
  expected(1, 3) = -0.5;
  expected(2, 2) = -0.25;
  expected(2, 3) = -0.25;
  // Entries <= 1 with one or two roundings: 4 eps; mapped points up to 4 through a 2-term sum:
  // 8 eps.
  EXPECT_TRUE(closeTo(o, expected, 4 * kEps<T>));
  const double tol = 8 * kEps<T>;
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(-2, -1, -1)), v3<T>(-1, -1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(4, 3, -5)), v3<T>(1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(-2, 3, -5)), v3<T>(-1, 1, 1), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(4, -1, -1)), v3<T>(1, -1, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(o, v3<T>(1, 1, -3)), v3<T>(0, 0, 0.5), tol));  // centre
  // A negative near plane is allowed (the box reaches behind the camera): z = +5 -> 0, -5 -> 1.
  const Mat4<T> around = orthographic(T(-1), T(1), T(-1), T(1), T(-5), T(5));
  EXPECT_TRUE(closeTo(transformPoint(around, v3<T>(0, 0, 5)), v3<T>(0, 0, 0), tol));
  EXPECT_TRUE(closeTo(transformPoint(around, v3<T>(0, 0, -5)), v3<T>(0, 0, 1), tol));
}

TYPED_TEST(Camera, OrthographicRejectsEmptyRanges) {
  using T = TypeParam;
  const T a = T(-1), b = T(1);
  EXPECT_THROW(orthographic(b, b, a, b, a, b), Error);  // right == left
  EXPECT_THROW(orthographic(b, a, a, b, a, b), Error);  // right < left
  EXPECT_THROW(orthographic(a, b, b, b, a, b), Error);  // top == bottom
  EXPECT_THROW(orthographic(a, b, b, a, a, b), Error);  // top < bottom
  EXPECT_THROW(orthographic(a, b, a, b, b, b), Error);  // far == near
  EXPECT_THROW(orthographic(a, b, a, b, b, a), Error);  // far < near
  EXPECT_THROW(orthographic(kNaN<T>, b, a, b, a, b), Error);
  EXPECT_THROW(orthographic(a, kInf<T>, a, b, a, b), Error);
  EXPECT_THROW(orthographic(a, b, a, b, a, kNaN<T>), Error);
}

// ---------------------------------------------------------------------------------------------
// Picking

// The camera of the picking tests: at (0,0,5) looking at the origin, fovY 90 deg, aspect 4/3,
// near 1, far 10, in an 800 x 600 viewport whose top-left corner is at pixel (100, 50).
template <class T>
struct PickingScene {
  Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  Mat4<T> proj = perspective(kPi<T> / 2, T(4) / 3, T(1), T(10));
  Vec4<T> viewport = v4<T>(100, 50, 800, 600);
  Mat4<T> inverse = (proj * view).inverse();
};

// World values up to ~14 go through the inverse of proj * view (condition ~ far/near = 10) and
// a divide by w: about 10 * 14 * eps of error; 256 eps.
template <class T>
constexpr double kPickTol = 256 * kEps<T>;

TYPED_TEST(Picking, UnprojectHandWorked) {
  using T = TypeParam;
  const PickingScene<T> s;
  const double tol = kPickTol<T>;
  // The viewport centre (100 + 400, 50 + 300) is on the view axis: at depth 0 the near plane
  // (1 ahead of the eye: z = 4), at depth 1 the far plane (10 ahead: z = -5).
  EXPECT_TRUE(closeTo(unproject(v3<T>(500, 350, 0), s.viewport, s.inverse), v3<T>(0, 0, 4), tol));
  EXPECT_TRUE(closeTo(unproject(v3<T>(500, 350, 1), s.viewport, s.inverse), v3<T>(0, 0, -5), tol));
  // The viewport's top-left corner is the near plane's top-left corner: half-height
  // 1 tan(45 deg) = 1, half-width 4/3, so view (-4/3, 1, -1) = world (-4/3, 1, 4).
  EXPECT_TRUE(
      closeTo(unproject(v3<T>(100, 50, 0), s.viewport, s.inverse), v3<T>(-4.0 / 3, 1, 4), tol));
  // The bottom-right corner on the far plane: view (40/3, -10, -10) = world (40/3, -10, -5).
  EXPECT_TRUE(
      closeTo(unproject(v3<T>(900, 650, 1), s.viewport, s.inverse), v3<T>(40.0 / 3, -10, -5), tol));
}

TYPED_TEST(Picking, UnprojectInvertsProjection) {
  using T = TypeParam;
  const PickingScene<T> s;
  const Mat4<T> viewProj = s.proj * s.view;
  for (const Vec3<T>& world : {v3<T>(0.3, -0.2, 1), v3<T>(2, 1, -3), v3<T>(-5, -3, -4)}) {
    const Vec3<T> ndc = transformPoint(viewProj, world);
    // The window mapping of docs/conventions.md: x right from the viewport's left edge, y down
    // from its top edge, depth as is.
    const Vec3<T> window(s.viewport[0] + (ndc.x() + 1) / 2 * s.viewport[2],
                         s.viewport[1] + (1 - ndc.y()) / 2 * s.viewport[3], ndc.z());
    EXPECT_TRUE(closeTo(unproject(window, s.viewport, s.inverse), world, kPickTol<T>));
  }
}

TYPED_TEST(Picking, ScreenRayThroughTheCentrePixelIsTheViewAxis) {
  using T = TypeParam;
  // A 101 x 51 viewport: the centre pixel is (50, 25), its centre at (50.5, 25.5).
  const Vec4<T> viewport = v4<T>(0, 0, 101, 51);
  const Vec3<T> eye = v3<T>(1, 2, 3);
  const Mat4<T> view = lookAt(eye, v3<T>(4, 6, 3), Vec3<T>::UnitY());
  const Mat4<T> proj = perspective(T(1), T(101) / 51, T(0.5), T(50));
  const ScreenRay<T> ray = screenToRay(T(50.5), T(25.5), viewport, view, proj);
  // The view direction is (3,4,0)/5; the origin is half a unit along it from the eye.
  // The inverse of proj * view has a condition of about far/near = 100, so unprojected points
  // carry ~100 eps relative error: ~400 eps on the origin (magnitude ~4) and ~5000 eps on the
  // far point (magnitude ~50), which over the ray's length of ~50 tilts the direction by
  // ~100 eps. 512 eps for both.
  const double tol = 512 * kEps<T>;
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(1.3, 2.4, 3), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0.6, 0.8, 0), tol));
  EXPECT_TRUE(closeTo(ray.direction.norm(), T(1), 4 * kEps<T>));  // normalised: an ulp or two
}

TYPED_TEST(Picking, ScreenRayThroughACorner) {
  using T = TypeParam;
  // Camera at the origin looking down -z, fovY 90 deg, aspect 2, near 1: the window point (0,0)
  // (top-left corner of the 200 x 100 viewport) is the near-plane corner (-2, 1, -1).
  const Mat4<T> proj = perspective(kPi<T> / 2, T(2), T(1), T(100));
  const ScreenRay<T> ray =
      screenToRay(T(0), T(0), v4<T>(0, 0, 200, 100), Mat4<T>::Identity(), proj);
  // Far/near = 100 as above, values up to ~2 at the origin: 512 eps.
  const double tol = 512 * kEps<T>;
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(-2, 1, -1), tol));
  EXPECT_TRUE(closeTo(ray.direction, Vec3<T>(v3<T>(-2, 1, -1) / std::sqrt(T(6))), tol));
}

TYPED_TEST(Picking, ScreenRayOrthographic) {
  using T = TypeParam;
  // Camera at (0,0,5) looking at the origin; the box x in [-4,4], y in [-3,3], near 1, far 9,
  // shown in an 80 x 60 viewport: one pixel is 0.1 world units, every ray points along -z.
  const Mat4<T> view = lookAt(v3<T>(0, 0, 5), Vec3<T>::Zero(), Vec3<T>::UnitY());
  const Mat4<T> proj = orthographic(T(-4), T(4), T(-3), T(3), T(1), T(9));
  const Vec4<T> viewport = v4<T>(0, 0, 80, 60);
  // Values up to ~5 through a well-conditioned inverse: 64 eps.
  const double tol = 64 * kEps<T>;
  // Window (0,0): top-left corner, view (-4, 3, -1) = world (-4, 3, 4).
  ScreenRay<T> ray = screenToRay(T(0), T(0), viewport, view, proj);
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(-4, 3, 4), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0, 0, -1), tol));
  // Window (60, 15): NDC (2*60/80 - 1, 1 - 2*15/60) = (0.5, 0.5), view (2, 1.5, -1).
  ray = screenToRay(T(60), T(15), viewport, view, proj);
  EXPECT_TRUE(closeTo(ray.origin, v3<T>(2, 1.5, 4), tol));
  EXPECT_TRUE(closeTo(ray.direction, v3<T>(0, 0, -1), tol));
}

TYPED_TEST(Picking, RejectsBadInput) {
  using T = TypeParam;
  const PickingScene<T> s;
  const Vec3<T> w = v3<T>(500, 350, 0);
  EXPECT_THROW(unproject(w, v4<T>(0, 0, 0, 600), s.inverse), Error);   // zero width
  EXPECT_THROW(unproject(w, v4<T>(0, 0, 800, -1), s.inverse), Error);  // negative height
  EXPECT_THROW(unproject(w, v4<T>(kNaN<T>, 0, 800, 600), s.inverse), Error);
  EXPECT_THROW(screenToRay(T(1), T(1), v4<T>(0, 0, 800, 0), s.view, s.proj), Error);
  EXPECT_THROW(screenToRay(kNaN<T>, T(1), s.viewport, s.view, s.proj), Error);
  EXPECT_THROW(screenToRay(T(1), T(1), s.viewport, s.view, Mat4<T>::Zero()), Error);  // singular
}

// ---------------------------------------------------------------------------------------------
// Vector helpers

TYPED_TEST(Vectors, ProjectAndRejectHandWorked) {
  using T = TypeParam;
  // Every value here is a small dyadic rational, computed with a dot, a divide and a product
  // that are exact or within an ulp of values <= 4 (2 eps): 4 eps.
  const double tol = 4 * kEps<T>;
  // onto = (2,0,0) (not unit): the x part.
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(2, 0, 0)), v3<T>(3, 0, 0), tol));
  EXPECT_TRUE(closeTo(reject(v3<T>(3, 4, 0), v3<T>(2, 0, 0)), v3<T>(0, 4, 0), tol));
  // onto = (1,1,0): a.b = 7, |b|^2 = 2 -> 3.5 (1,1,0).
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(1, 1, 0)), v3<T>(3.5, 3.5, 0), tol));
  EXPECT_TRUE(closeTo(reject(v3<T>(3, 4, 0), v3<T>(1, 1, 0)), v3<T>(-0.5, 0.5, 0), tol));
  // 2D: (1,2) onto (1,1): 3/2 (1,1); the rest (-1/2, 1/2).
  EXPECT_TRUE(closeTo(project(v2<T>(1, 2), v2<T>(1, 1)), v2<T>(1.5, 1.5), tol));
  EXPECT_TRUE(closeTo(reject(v2<T>(1, 2), v2<T>(1, 1)), v2<T>(-0.5, 0.5), tol));
  // Directions of extreme magnitude: 1e-30 squared underflows in float, 1e30 squared
  // overflows, so a . b / |b|^2 would give NaN; rescaling keeps the exact answer.
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(1e-30, 0, 0)), v3<T>(3, 0, 0), tol));
  EXPECT_TRUE(closeTo(project(v3<T>(3, 4, 0), v3<T>(0, 1e30, 0)), v3<T>(0, 4, 0), tol));
}

TYPED_TEST(Vectors, ProjectPlusRejectIsTheOriginal) {
  using T = TypeParam;
  const std::vector<Vec3<T>> vs = {v3<T>(1, 2, 3), v3<T>(-4, 0.5, 2), v3<T>(0.1, -7, 0.3)};
  for (const Vec3<T>& a : vs) {
    for (const Vec3<T>& b : vs) {
      // Components up to ~7 (ulp 4 eps) after a few roundings each: 32 eps.
      const double tol = 32 * kEps<T>;
      EXPECT_TRUE(closeTo(Vec3<T>(project(a, b) + reject(a, b)), a, tol));
      // The rejection is perpendicular to b: |reject . b| <= tol * |b|_1 (|b|_1 <= 7.4).
      EXPECT_TRUE(closeTo(reject(a, b).dot(b), T(0), tol * 8));
    }
  }
}

TYPED_TEST(Vectors, ReflectHandWorked) {
  using T = TypeParam;
  // Exact small values: 4 eps.
  const double tol = 4 * kEps<T>;
  // Bounce off the floor; the normal (0,2,0) is not unit: (1,-1,0) -> (1,1,0).
  EXPECT_TRUE(closeTo(reflect(v3<T>(1, -1, 0), v3<T>(0, 2, 0)), v3<T>(1, 1, 0), tol));
  // 2D: mirror in the line y = -x (normal (1,1)): (1,0) - 2 (1/2) (1,1) = (0,-1).
  EXPECT_TRUE(closeTo(reflect(v2<T>(1, 0), v2<T>(1, 1)), v2<T>(0, -1), tol));
  // Twice is the identity and the length is kept: values ~3, a few roundings: 16 eps.
  const Vec3<T> v = v3<T>(0.3, -2, 1.7), n = v3<T>(1, 2, -0.5);
  EXPECT_TRUE(closeTo(reflect(reflect(v, n), n), v, 16 * kEps<T>));
  EXPECT_TRUE(closeTo(reflect(v, n).norm(), v.norm(), 16 * kEps<T>));
}

TYPED_TEST(Vectors, ProjectRejectReflectRejectZeroDirections) {
  using T = TypeParam;
  const Vec3<T> a = v3<T>(1, 2, 3);
  EXPECT_THROW(project(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(reject(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(reflect(a, Vec3<T>::Zero()), Error);
  EXPECT_THROW(project(a, v3<T>(kNaN<T>, 1, 0)), Error);
  EXPECT_THROW(reflect(a, v3<T>(0, kInf<T>, 0)), Error);
  EXPECT_THROW(project(v2<T>(1, 2), Vec2<T>::Zero()), Error);
}

TYPED_TEST(Vectors, AngleBetweenHandWorked) {
  using T = TypeParam;
  // atan2 within an ulp, of exact or once-rounded arguments; angles <= pi (ulp 2 eps): 4 eps.
  const double tol = 4 * kEps<T>;
  const Vec3<T> x = Vec3<T>::UnitX();
  EXPECT_TRUE(closeTo(angleBetween(x, Vec3<T>::UnitY()), kPi<T> / 2, tol));
  EXPECT_TRUE(closeTo(angleBetween(x, Vec3<T>(-x)), kPi<T>, tol));
  EXPECT_TRUE(closeTo(angleBetween(x, x), T(0), tol));
  EXPECT_TRUE(closeTo(angleBetween(x, v3<T>(1, 1, 0)), kPi<T> / 4, tol));
  EXPECT_TRUE(closeTo(angleBetween(v2<T>(1, 0), v2<T>(0, -1)), kPi<T> / 2, tol));  // unsigned
  EXPECT_TRUE(closeTo(angleBetween(v2<T>(2, 0), v2<T>(-1, -1)), 3 * kPi<T> / 4, tol));
  // Extreme magnitudes: |a|^2 overflows (1e30) or underflows (1e-30) in float.
  EXPECT_TRUE(closeTo(angleBetween(v3<T>(1e30, 0, 0), v3<T>(1e30, 1e30, 0)), kPi<T> / 4, tol));
  EXPECT_TRUE(closeTo(angleBetween(v3<T>(1e-30, 0, 0), v3<T>(0, 0, 1e-30)), kPi<T> / 2, tol));
}

TYPED_TEST(Vectors, AngleBetweenNearlyParallelVectors) {
  using T = TypeParam;
  // a = (1,0,0) and b = (1,t,0) with t = 1e-4 (as stored in T) are exactly atan(t) apart,
  // 1e-4 - 1e-12/3. a x b = (0,0,t) and a . b = 1 are exact, so atan2 gives the answer within
  // an ulp or two: relative tolerance 4 eps, i.e. 4 eps * 1e-4.
  const T t = T(1e-4);
  const double exact = static_cast<double>(std::atan(static_cast<long double>(t)));
  const double tol = 4 * kEps<T> * exact;
  const Vec3<T> a = Vec3<T>::UnitX(), b = v3<T>(1, t, 0);
  EXPECT_TRUE(closeTo(angleBetween(a, b), T(exact), tol));
  // The same near pi: (1,0,0) and (-1,t,0) are pi - atan(t) apart (an ulp of pi is 2 eps).
  EXPECT_TRUE(closeTo(angleBetween(a, v3<T>(-1, t, 0)), T(std::numbers::pi - exact), 2 * kEps<T>));
  // acos(a . b / |a||b|) fails here: in float |b| = sqrt(1 + 1e-8) rounds to 1 and acos gives 0;
  // in double the rounding of the cosine (~1e-16) is amplified by 1/sin(angle) = 1e4.
  const T viaAcos = std::acos(a.dot(b) / (a.norm() * b.norm()));
  EXPECT_FALSE(closeTo(viaAcos, T(exact), tol));
}

TYPED_TEST(Vectors, AngleBetweenRejectsZeroAndNonFinite) {
  using T = TypeParam;
  EXPECT_THROW(angleBetween(Vec3<T>::Zero(), Vec3<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(Vec3<T>::UnitX(), Vec3<T>::Zero()), Error);
  EXPECT_THROW(angleBetween(Vec2<T>::Zero(), Vec2<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(v3<T>(kNaN<T>, 0, 0), Vec3<T>::UnitX()), Error);
  EXPECT_THROW(angleBetween(Vec3<T>::UnitX(), v3<T>(0, kInf<T>, 0)), Error);
}

// ---------------------------------------------------------------------------------------------
// Tolerant comparison

TYPED_TEST(Compare, ScalarsFollowTheBooksRule) {
  using T = TypeParam;
  const T eps = kEps<T>;
  // Defaults: |a - b| <= eps * max(1, |a|, |b|).
  EXPECT_TRUE(nearlyEqual(T(1), T(1) + eps));       // one ulp of 1
  EXPECT_FALSE(nearlyEqual(T(1), T(1) + 4 * eps));  // four ulp
  // Relative for large values: one ulp of 1000 is 512 eps <= 1000 eps; four are 2048 eps.
  const T k = T(1000);
  EXPECT_TRUE(nearlyEqual(k, std::nextafter(k, kInf<T>)));
  EXPECT_FALSE(nearlyEqual(k, k + 4 * 512 * eps));
  // Absolute near zero.
  EXPECT_TRUE(nearlyEqual(T(0), eps / 2));
  EXPECT_TRUE(nearlyEqual(eps / 4, -eps / 4));
  EXPECT_FALSE(nearlyEqual(T(0), T(1e-3)));
  // Explicit tolerances: 1% of 101 is 1.01 >= |100 - 101|, but < |100 - 102|.
  EXPECT_TRUE(nearlyEqual(T(100), T(101), T(0.01), T(0)));
  EXPECT_FALSE(nearlyEqual(T(100), T(102), T(0.01), T(0)));
  EXPECT_TRUE(nearlyEqual(T(0), T(0.5), T(0), T(0.5)));
  // Special values.
  EXPECT_FALSE(nearlyEqual(kNaN<T>, kNaN<T>));
  EXPECT_FALSE(nearlyEqual(T(1), kNaN<T>));
  EXPECT_TRUE(nearlyEqual(kInf<T>, kInf<T>));
  EXPECT_FALSE(nearlyEqual(kInf<T>, -kInf<T>));
  EXPECT_FALSE(nearlyEqual(std::numeric_limits<T>::max(), kInf<T>));
}

TYPED_TEST(Compare, VectorsCompareByNorm) {
  using T = TypeParam;
  // Norm-based: (1, 1e-9) and (1, 2e-9) differ by 1e-9 against a norm of 1, within relTol 1e-6;
  // compared component by component with a purely relative tolerance they would differ by 50%.
  EXPECT_TRUE(nearlyEqual(v2<T>(1, 1e-9), v2<T>(1, 2e-9), T(1e-6), T(0)));
  EXPECT_FALSE(nearlyEqual(v2<T>(1, 0), v2<T>(1, 1e-3), T(1e-6), T(0)));
  // Defaults as for scalars: 1 ulp of 1 in one component passes, 4 ulp fail.
  EXPECT_TRUE(nearlyEqual(v3<T>(1, 0, 0), Vec3<T>(v3<T>(1, 0, 0) + v3<T>(kEps<T>, 0, 0))));
  EXPECT_FALSE(nearlyEqual(v3<T>(1, 0, 0), Vec3<T>(v3<T>(1, 0, 0) + v3<T>(0, 4 * kEps<T>, 0))));
  // Matrices use the Frobenius norm (sqrt(3) for the 3x3 identity).
  Mat3<T> m = Mat3<T>::Identity();
  m(0, 1) = T(1e-3);
  EXPECT_TRUE(nearlyEqual(m, Mat3<T>::Identity(), T(1e-3)));
  EXPECT_FALSE(nearlyEqual(m, Mat3<T>::Identity(), T(1e-4)));
  EXPECT_FALSE(nearlyEqual(v2<T>(kNaN<T>, 0), v2<T>(kNaN<T>, 0)));
  EXPECT_TRUE(nearlyEqual(v2<T>(kInf<T>, 0), v2<T>(kInf<T>, 0)));
  EXPECT_FALSE(nearlyEqual(v2<T>(kInf<T>, 0), v2<T>(1, 0)));
}

}  // namespace
}  // namespace simdphys

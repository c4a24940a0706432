// Cameras, the OBB-in-frustum test and picking: hand-worked cases where the answer is known.
#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "paths.hpp"
#include "scene_cases.hpp"

namespace simdphys {
namespace {

using test::expectError;
using test::OnEveryPath;

constexpr float kPi = std::numbers::pi_v<float>;

TEST(Cameras, PerspectiveCameraMatchesItsParts) {
  const Vec3f eye(1, 2, 3), target(0, 0, -5);
  const Camera c = Camera::perspective(eye, target, Vec3f::UnitY(), 1.0f, 800, 600, 0.1f, 100);
  EXPECT_EQ(c.view, lookAt(eye, target, Vec3f::UnitY()));
  EXPECT_EQ(c.projection, perspective(1.0f, 800.0f / 600.0f, 0.1f, 100.0f));
  EXPECT_EQ(c.viewport, Vec4f(0, 0, 800, 600));
  // eye() inverts the view: a rotation and a translation, each a few ulp at magnitude 3.
  EXPECT_LT((c.eye() - eye).norm(), 1e-5f);
  // The centre pixel's ray is the view axis (docs/conventions.md); same tolerance.
  const Ray r = c.ray(400, 300);
  EXPECT_LT((r.direction - (target - eye).normalized()).norm(), 1e-5f);
  expectError(
      [] { Camera::perspective(Vec3f::Zero(), Vec3f::UnitZ(), Vec3f::UnitY(), 1, 0, 1, 1, 2); },
      "positive, finite size");
}

TEST(Cameras, OrthographicRaysAreParallel) {
  // Looking down -z from (0, 0, 10), 2 units above and below the axis over 100 x 100 pixels: pixel
  // (75, 25) is at x = +1, y = +1 (right and up of the centre), and every ray points along -z.
  const Camera c =
      Camera::orthographic({0, 0, 10}, Vec3f::Zero(), Vec3f::UnitY(), 2, 100, 100, 1, 50);
  const Ray r = c.ray(75, 25);
  // Tolerance: the unprojection inverts a 4x4 in float (a few ulp of 10).
  EXPECT_LT((r.direction - Vec3f(0, 0, -1)).norm(), 1e-5f);
  EXPECT_LT((r.origin - Vec3f(1, 1, 9)).norm(), 1e-5f);
}

TEST(Cameras, PrimaryRaysAreThePixelRays) {
  const Camera c = Camera::perspective({0, 60, -140}, Vec3f::Zero(), Vec3f::UnitY(), kPi / 3, 32,
                                       24, 0.1f, 1000);
  const RayStream rays = c.primaryRays();
  ASSERT_EQ(rays.size(), 32u * 24u);
  for (int j = 0; j < 24; ++j)
    for (int i = 0; i < 32; ++i) {  // the same computation in the same order: to the bit
      const Ray expected = c.ray(i + 0.5f, j + 0.5f), got = rays[j * 32 + i];
      EXPECT_EQ(got.origin, expected.origin);
      EXPECT_EQ(got.direction, expected.direction);
    }
  // Row 0 is the top: its rays point further up than the last row's.
  EXPECT_GT(rays[0].direction.y(), rays[32 * 23].direction.y());
}

TEST(Cameras, OrbitCameraTurnsAroundItsTarget) {
  const Vec3f target(1, 2, 3);
  OrbitCamera orbit(target, 10);
  // Yaw 0, pitch 0: on +z of the target. A quarter turn of yaw about +y takes +z to +x (the
  // right-hand rule, docs/conventions.md). Tolerance: cos(pi/2) in float is -4.4e-8; times 10.
  EXPECT_LT((orbit.eye() - Vec3f(1, 2, 13)).norm(), 1e-5f);
  orbit.rotate(kPi / 2, 0);
  EXPECT_LT((orbit.eye() - Vec3f(11, 2, 3)).norm(), 1e-5f);
  // Pitch is clamped short of the pole, where lookAt's up would be parallel to the view.
  orbit.rotate(0, 10);
  EXPECT_EQ(orbit.pitch(), OrbitCamera::kPitchLimit);
  EXPECT_NO_THROW(orbit.view());
  orbit.rotate(0, -OrbitCamera::kPitchLimit);
  orbit.zoom(0.5f);
  EXPECT_LT((orbit.eye() - Vec3f(6, 2, 3)).norm(), 1e-5f);
  // Seen from +x, the view's right is -z and up is +y: panning moves the target that way.
  orbit.pan(2, 1);
  EXPECT_LT((orbit.target() - Vec3f(1, 3, 1)).norm(), 1e-5f);
  // The view of an orbit camera looks at its target: it lands on the -z axis.
  const Vec3f inView = transformPoint(orbit.view(), orbit.target());
  EXPECT_LT(inView.head<2>().norm(), 1e-5f);
  EXPECT_NEAR(inView.z(), -5.0f, 1e-5f);
  expectError([&] { orbit.zoom(0); }, "positive");
}

// The box frustum x, y in [-1, 1], depth 1..11 along -z (exact planes, as in cull_test.cpp).
Frustum boxFrustum() {
  return Frustumd::fromMatrix(orthographic(-1.0, 1.0, -1.0, 1.0, 1.0, 11.0)).cast<float>();
}

TEST(Cameras, ObbInFrustum) {
  const Frustum f = boxFrustum();
  // A cube of half side 0.5 centred 0.6 left of the left plane x = -1: axis-aligned it reaches
  // x = -1.1, outside; turned 45 degrees about z its reach along x is 0.5 sqrt(2) = 0.707, so it
  // reaches x = -0.893 and is in.
  const Obb aligned{{-1.6f, 0, -5}, Vec3f::Constant(0.5f), Mat3f::Identity()};
  const Obb turned{{-1.6f, 0, -5}, Vec3f::Constant(0.5f), rotationZ(kPi / 4)};
  EXPECT_FALSE(intersectsObb(f, aligned));
  EXPECT_TRUE(intersectsObb(f, turned));
  EXPECT_EQ(intersectsObb(f, aligned), f.intersectsBox(aligned.center, aligned.halfExtents));
  // A long thin box lying beyond the far plane but turned so that it pokes through it.
  const Obb pole{{0, 0, -13}, {0.1f, 0.1f, 3}, rotationX(kPi / 3)};  // reach along z: 1.5 + 0.087
  EXPECT_FALSE(intersectsObb(f, pole));
  const Obb poleIn{{0, 0, -12}, {0.1f, 0.1f, 3}, rotationX(kPi / 3)};
  EXPECT_TRUE(intersectsObb(f, poleIn));
}

class Picking : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Picking);

// Window position of a world point, by the formulas of docs/conventions.md, in double.
Vec2f toPixel(const Camera& c, const Vec3f& p) {
  const Vec4d clip =
      (c.projection.cast<double>() * c.view.cast<double>()) * p.cast<double>().homogeneous();
  const Vec2d ndc = clip.head<2>() / clip.w();
  return Vec2d(c.viewport[0] + (ndc.x() + 1) / 2 * c.viewport[2],
               c.viewport[1] + (1 - ndc.y()) / 2 * c.viewport[3])
      .cast<float>();
}

TEST_P(Picking, ReturnsTheModelUnderThePixel) {
  test::Meshes meshes;
  Scene scene;
  auto at = [](float x, float y, float z) {
    return transform(Vec3f::Ones(), Mat3f::Identity(), Vec3f(x, y, z));
  };
  const auto ball = scene.add({Sphere{Vec3f::Zero(), 1}, at(0, 0, 0)});
  const auto crate = scene.add({meshes.box, at(3, 0, 0)});
  const auto hidden = scene.add({meshes.ball, at(0, 0, -6)});  // behind the ball
  const auto ground =
      scene.add({meshes.terrain, transform(Vec3f(20, 1, 20), Mat3f::Identity(), Vec3f(0, -3, 0))});
  const auto child = scene.add({Aabb{Vec3f::Constant(-0.3f), Vec3f::Constant(0.3f)}, at(0, 2, 0),
                                crate});  // above the crate: world (3, 2, 0)
  scene.update();
  for (const Camera& cam :
       {Camera::perspective({0, 1, 10}, {0, 0, 0}, Vec3f::UnitY(), 1.0f, 640, 480, 0.1f, 100),
        Camera::orthographic({0, 1, 10}, {0, 0, 0}, Vec3f::UnitY(), 5, 640, 480, 0.1f, 100)}) {
    // Each model's centre projects to a pixel; nothing nearer covers it there.
    const struct {
      Vec3f point;
      Handle model;
    } cases[] = {{{0, 0, 0}, ball}, {{3, 0, 0}, crate}, {{3, 2, 0}, child}, {{-6, -3, 2}, ground}};
    for (const auto& c : cases) {
      const Vec2f px = toPixel(cam, c.point);
      EXPECT_EQ(scene.pick(cam, px.x(), px.y()).model, scene.index(c.model))
          << "at " << c.point.transpose();
    }
    // The hidden ball is behind the first on every pixel it covers: never picked.
    const Vec2f px = toPixel(cam, {0, 0, -6});
    EXPECT_EQ(scene.pick(cam, px.x(), px.y()).model, scene.index(ball));
    // The top-left corner sees the sky.
    EXPECT_FALSE(scene.pick(cam, 0.5f, 0.5f).hit());
  }
  (void)hidden;
}

}  // namespace
}  // namespace simdphys

// Frustum extraction and culling: every path returns exactly the reference's indices.
#include <gtest/gtest.h>

#include <numbers>

#include "paths.hpp"
#include "testing/cull_reference.hpp"
#include "workloads.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;

std::vector<std::uint32_t> referenceCull(const Frustum& f, const SphereStream& s) {
  std::vector<std::uint32_t> v;
  reference::cullSpheres(f, s.field(fields::Sphere::x).view(), s.field(fields::Sphere::y).view(),
                         s.field(fields::Sphere::z).view(), s.field(fields::Sphere::r).view(), v);
  return v;
}
std::vector<std::uint32_t> referenceCull(const Frustum& f, const BoundsStream& b) {
  std::vector<std::uint32_t> v;
  reference::cullBoxes(f, b.field(fields::Bounds::cx).view(), b.field(fields::Bounds::cy).view(),
                       b.field(fields::Bounds::cz).view(), b.field(fields::Bounds::ex).view(),
                       b.field(fields::Bounds::ey).view(), b.field(fields::Bounds::ez).view(), v);
  return v;
}

// An orthographic box frustum x, y in [-1, 1], depth 1..11 along -z: planes with exact
// coefficients, so objects can sit exactly on them.
Frustum boxFrustum() {
  Mat4d proj = orthographic(-1.0, 1.0, -1.0, 1.0, 1.0, 11.0);
  return Frustumd::fromMatrix(proj).cast<float>();
}

TEST(Frustum, FromMatrixGivesTheBoxPlanes) {
  Frustum f = boxFrustum();
  // Unit inward normals: the left plane x = -1 has n = (1,0,0), d = 1; near z = -1 has
  // n = (0,0,-1), d = -1. The matrix entries are exact in binary (2/(r-l) = 1, 1/(f-n) = 0.1
  // is not, so the depth planes are compared to 1 ulp).
  EXPECT_EQ(f.planes[Frustum::kLeft].normal, Vec3f(1, 0, 0));
  EXPECT_EQ(f.planes[Frustum::kLeft].d, 1.0f);
  EXPECT_EQ(f.planes[Frustum::kTop].normal, Vec3f(0, -1, 0));
  EXPECT_FLOAT_EQ(f.planes[Frustum::kNear].normal.z(), -1.0f);
  EXPECT_FLOAT_EQ(f.planes[Frustum::kNear].d, -1.0f);
  EXPECT_FLOAT_EQ(f.planes[Frustum::kFar].normal.z(), 1.0f);
  EXPECT_FLOAT_EQ(f.planes[Frustum::kFar].d, 11.0f);
}

TEST(Frustum, RejectsDegenerateMatrices) {
  EXPECT_THROW(Frustum::fromMatrix(Mat4f::Zero()), Error);
  Mat4f m = Mat4f::Identity();
  m(0, 0) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(Frustum::fromMatrix(m), Error);
}

class Cull : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(Cull);

// W6: 1,000,000 spheres and boxes; the exact figures of the workload specification, and the
// same indices as the scalar reference, on every path. The workload and the reference depend on
// no path: made once, every path run in this process.
TEST(CullW6, ReferenceFiguresOnEveryPath) {
  const workloads::CullWorkload w = workloads::makeCullWorkload();
  const std::vector<std::uint32_t> spheres = referenceCull(w.frustum, w.spheres),
                                   boxes = referenceCull(w.frustum, w.boxes);
  test::forEveryPath([&] {
    std::vector<std::uint32_t> visible;
    EXPECT_EQ(cull(w.frustum, w.spheres, visible), workloads::kCullSpheresVisible);
    EXPECT_EQ(visible, spheres);
    EXPECT_EQ(cull(w.frustum, w.boxes, visible), workloads::kCullBoxesVisible);
    EXPECT_EQ(visible, boxes);
  });
}

// Objects exactly touching, straddling and just missing the planes of the box frustum.
TEST_P(Cull, ObjectsOnThePlanes) {
  Frustum f = boxFrustum();
  SphereStream s;
  BoundsStream b;
  const float r = 0.25f;
  std::vector<std::uint32_t> want;
  // Along x: centres from -1.5 to 1.5 in steps of 1/8 (exact), at depth z = -5.
  for (int i = 0; i <= 24; ++i) {
    float x = -1.5f + i / 8.0f;
    s.push({{x, 0, -5}, r});
    b.push({x, 0, -5}, Vec3f::Constant(r));
    // Touching counts: visible while the distance outside is at most r (|x| - 1 <= 0.25).
    if (std::abs(x) <= 1.25f) want.push_back(std::uint32_t(i));
  }
  // A sphere that contains the whole frustum, and a point on the far plane's outside.
  s.push({{0, 0, -6}, 100});
  b.push({0, 0, -6}, Vec3f::Constant(100));
  want.push_back(25);
  s.push({{0, 0, -11.5f}, 0});
  b.push({0, 0, -11.5f}, Vec3f::Zero());
  std::vector<std::uint32_t> visible;
  cull(f, s, visible);
  EXPECT_EQ(visible, want);
  cull(f, b, visible);
  EXPECT_EQ(visible, want);
}

// Seen edge-on: a frustum whose side planes pass exactly through a row of sphere centres.
TEST_P(Cull, EdgeOnFrustumAndPaddingLanes) {
  Mat4d view = lookAt(Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0));
  Mat4d proj = perspective(std::numbers::pi / 2, 1.0, 0.5, 100.0);
  Frustum f = Frustumd::fromMatrix(proj * view).cast<float>();
  workloads::Random rnd(61);
  SphereStream s;
  BoundsStream b;
  for (int i = 0; i < 37; ++i) {  // 37: the last vector is mostly padding on every width
    float t = rnd.uniform(1, 50);
    // On the 45-degree side planes y = +-x (and z = +-x) with radius 0 or tiny.
    Vec3f c(t, (i % 2 ? t : -t), (i % 3 ? 0.0f : t));
    float radius = i % 4 == 0 ? 0.0f : 1e-3f;
    s.push({c, radius});
    b.push(c, Vec3f::Constant(radius));
  }
  std::vector<std::uint32_t> visible;
  cull(f, s, visible);
  EXPECT_EQ(visible, referenceCull(f, s));
  for (std::uint32_t i : visible) EXPECT_LT(i, 37u);
  cull(f, b, visible);
  EXPECT_EQ(visible, referenceCull(f, b));
}

}  // namespace
}  // namespace simdphys

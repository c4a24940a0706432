// Paths and streams: dispatch, alignment, padding, validation.
#include <gtest/gtest.h>

#include "expect_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "paths.hpp"
#include "simdphys/geometry3d.hpp"

namespace simdphys {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(Paths, ReferenceIsLastAndBestSimdIsDefault) {
  std::vector<std::string> paths = availablePaths();
  ASSERT_FALSE(paths.empty());
  EXPECT_EQ(paths.back(), "reference");
  // Highway always compiles at least the baseline target, so some SIMD path exists on x86.
  EXPECT_GE(paths.size(), 2u);
}

TEST(Paths, SettingEachPathMakesItActive) {
  std::string before = activePath();
  for (const std::string& p : availablePaths()) {
    setPath(p);
    EXPECT_EQ(activePath(), p);
    EXPECT_EQ(referencePathActive(), p == "reference");
  }
  setPath(before);
}

TEST(Paths, UnknownPathIsAClearErrorAndChangesNothing) {
  std::string before = activePath();
  try {
    setPath("avx9000");
    FAIL() << "setPath accepted an unknown path";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("avx9000"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("available"), std::string::npos);
  }
  EXPECT_EQ(activePath(), before);
}

TEST(Paths, ScopedPathRestores) {
  std::string before = activePath();
  {
    ScopedPath guard("reference");
    EXPECT_TRUE(referencePathActive());
  }
  EXPECT_EQ(activePath(), before);
}

TEST(Streams, AlignedAndPaddedWithInertValues) {
  BoxStream boxes;
  for (int i = 0; i < 17; ++i) boxes.push({Vec3f::Constant(float(i)), Vec3f::Constant(i + 1.0f)});
  EXPECT_EQ(boxes.size(), 17u);
  EXPECT_EQ(boxes.padded(), 32u);  // next multiple of kStreamPad = 16
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(boxes.field(fields::Box::minX).data()) % kStreamAlign,
            0u);
  for (std::size_t i = 17; i < boxes.padded(); ++i) {
    EXPECT_EQ(boxes.field(fields::Box::minX)[i], kInf);
    EXPECT_EQ(boxes.field(fields::Box::maxZ)[i], -kInf);
  }
  SphereStream spheres;
  spheres.push({Vec3f::Zero(), 1});
  EXPECT_EQ(spheres.padded(), 16u);
  EXPECT_EQ(spheres.field(fields::Sphere::r)[15], -kInf);
}

TEST(Streams, RoundTripsValues) {
  BoxStream boxes;
  Aabb b{{-1, -2, -3}, {4, 5, 6}};
  boxes.push(b);
  EXPECT_EQ(boxes[0].min, b.min);
  EXPECT_EQ(boxes[0].max, b.max);
  Aabb c{{0, 0, 0}, {0, 0, 0}};  // a point is a valid (flat) box
  boxes.set(0, c);
  EXPECT_EQ(boxes[0].max, c.max);
}

// An owner writing a stream in place, as a class deriving from its StreamSet does (the scene's
// model-space rays): live elements through writable(), whole vectors through overwrite().
class OwnedSpheres : public SphereStream {
 public:
  void writeLive(std::size_t n, float value) {
    resize(n);
    for (std::size_t f = 0; f < kFields; ++f) {
      EXPECT_EQ(writable(f).size(), n);
      for (float& x : writable(f)) x = value;
    }
  }
  void writeWholeVectors(std::size_t n, float value) {
    overwrite(n, [&](const std::array<float*, kFields>& p) {
      for (float* field : p) std::fill(field, field + paddedSize(n), value);
    });
  }
};

void expectLiveThenPadding(const OwnedSpheres& s, float value) {
  for (std::size_t f = 0; f < OwnedSpheres::kFields; ++f)
    for (std::size_t i = 0; i < s.padded(); ++i)
      EXPECT_EQ(s.field(f)[i], i < s.size() ? value : fields::Sphere::kPad[f])
          << "field " << f << ", element " << i;
}

TEST(Streams, OwnerWritesLeaveThePaddingInert) {
  OwnedSpheres s;
  s.writeLive(17, 7.0f);
  expectLiveThenPadding(s, 7.0f);
  s.writeWholeVectors(20, kNaN);  // a kernel storing whole vectors, padding included
  ASSERT_EQ(s.size(), 20u);
  for (std::size_t f = 0; f < OwnedSpheres::kFields; ++f)
    for (std::size_t i = 20; i < s.padded(); ++i) EXPECT_EQ(s.field(f)[i], fields::Sphere::kPad[f]);
  s.writeLive(3, -2.0f);  // shrinking turns live elements back into padding
  expectLiveThenPadding(s, -2.0f);
}

TEST(Streams, PointStreamOverwriteRestoresThePadding) {
  PointStream points;
  points.overwrite(5, [](float* x, float* y, float* z) {
    for (std::size_t i = 0; i < paddedSize(5); ++i) x[i] = y[i] = z[i] = kNaN;
  });
  for (std::size_t i = 5; i < points.padded(); ++i)
    EXPECT_TRUE(points.field(fields::Point::x)[i] == 0 && points.field(fields::Point::y)[i] == 0 &&
                points.field(fields::Point::z)[i] == 0)
        << i;
}

using test::expectError;

TEST(Streams, RejectsBadBoxesSayingWhere) {
  BoxStream boxes;
  boxes.push({Vec3f::Zero(), Vec3f::Ones()});
  expectError([&] { boxes.push({{0, kNaN, 0}, Vec3f::Ones()}); }, "element 1: min.y is nan");
  expectError([&] { boxes.push({Vec3f::Zero(), {1, 1, kInf}}); }, "element 1: max.z is inf");
  expectError([&] { boxes.push({{0, 0, 2}, {1, 1, 1}}); }, "min.z (2) > max.z (1)");
  expectError([&] { boxes.set(0, {{2, 0, 0}, {1, 1, 1}}); }, "BoxStream::set: element 0");
  expectError([&] { boxes.set(5, {Vec3f::Zero(), Vec3f::Ones()}); }, "out of range");
  EXPECT_EQ(boxes.size(), 1u);  // nothing was added by the failed pushes
}

TEST(Streams, RejectsBadSpheresAndBounds) {
  SphereStream spheres;
  expectError([&] { spheres.push({{kInf, 0, 0}, 1}); }, "center.x is inf");
  expectError([&] { spheres.push({Vec3f::Zero(), -1}); }, "radius is -1");
  expectError([&] { spheres.push({Vec3f::Zero(), kNaN}); }, "radius is nan");
  BoundsStream bounds;
  expectError([&] { bounds.push(Vec3f::Zero(), {1, -1, 1}); }, "halfExtents.y is negative");
  expectError([&] { bounds.push({0, 0, kNaN}, Vec3f::Ones()); }, "center.z is nan");
  EXPECT_EQ(spheres.size() + bounds.size(), 0u);
}

}  // namespace
}  // namespace simdphys

// Ray packets (RayStreamOptions) on every path: every traversal mode of the stream API returns,
// ray for ray, what single-ray raycast returns and what brute force over the triangles returns,
// bit for bit (every path tests each triangle with the scalar watertight test's arithmetic, and
// the closest-hit rule does not depend on the order triangles are met, so no tolerance is
// needed). Coherent sets (cameras, tiles), mixed-direction packets, rays aimed at shared edges and
// vertices, lanes without rays and rays with tMax = -inf.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "expect_error.hpp"
#include "mesh_oracles.hpp"
#include "paths.hpp"
#include "rays.hpp"
#include "testing/kernels.hpp"

namespace simdphys {
namespace {

using test::OnEveryPath;
using Mode = RayStreamOptions::Mode;
constexpr float kInf = std::numeric_limits<float>::infinity();

void expectSame(const ElementHit& found, const ElementHit& expected, const std::string& what) {
  EXPECT_EQ(found.index, expected.index) << what;
  if (expected.hit()) {
    EXPECT_EQ(found.t, expected.t) << what;  // exact: same arithmetic
  }
}

std::string describe(const RayStreamOptions& o) {
  const char* mode = o.mode == Mode::kAuto     ? "auto"
                     : o.mode == Mode::kSingle ? "single"
                                               : "packets";
  return std::string(mode) + " size " + std::to_string(o.packetSize) + " image width " +
         std::to_string(o.imageWidth);
}

// Every mode, with packets of rows and (imageWidth > 0) of tiles, against single rays and brute
// force, on every path (brute force, which depends on no path, is computed once). Returns how many
// rays hit.
std::size_t checkModes(const Mesh& mesh, const std::vector<Ray>& rays,
                       const std::vector<float>& tMax, std::uint32_t imageWidth) {
  RayStream stream;
  std::vector<ElementHit> expected(rays.size());
  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    stream.push(rays[i], tMax[i]);
    expected[i] = test::bruteRaycast(mesh, rays[i], tMax[i]);
    hits += expected[i].hit();
  }
  std::vector<RayStreamOptions> modes = {{Mode::kSingle, 0, 0},
                                         {Mode::kAuto, 0, 0},
                                         {Mode::kAuto, 8, 0},
                                         {Mode::kPackets, 16, 0},
                                         {Mode::kPackets, 8, 0}};
  if (imageWidth != 0)
    for (std::uint32_t size : {8u, 16u})
      modes.push_back({Mode::kPackets, size, imageWidth}),
          modes.push_back({Mode::kAuto, size, imageWidth});
  test::forEveryPath([&] {
    const MeshBvh bvh(mesh);
    for (std::size_t i = 0; i < rays.size(); ++i)
      expectSame(bvh.raycast(rays[i], tMax[i]), expected[i], "single ray " + std::to_string(i));
    for (const RayStreamOptions& options : modes) {
      std::vector<ElementHit> found(rays.size());
      bvh.raycast(stream, found, options);
      for (std::size_t i = 0; i < rays.size(); ++i)
        expectSame(found[i], expected[i], describe(options) + ", ray " + std::to_string(i));
    }
  });
  return hits;
}

// W2's camera over a G = 33 heightfield: coherent tiles. 62 x 45 leaves partial tiles at the
// right and bottom edges (lanes without rays) and a tail of rays in the row packets.
TEST(MeshPackets, HeightfieldCameraEqualsSingleRaysAndBruteForceOnEveryPath) {
  const Mesh mesh = workloads::makeHeightfield(33);
  for (auto [w, h] : {std::pair{64u, 48u}, std::pair{62u, 45u}}) {
    const RayStream camera = workloads::makeCoherentRays(w, h);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < camera.size(); ++i) rays.push_back(camera[i]);
    const std::size_t hits = checkModes(mesh, rays, std::vector<float>(rays.size(), kInf), w);
    EXPECT_GT(hits, rays.size() / 2);  // the camera sees mostly terrain
    EXPECT_LT(hits, rays.size());      // and some sky
  }
}

// Random rays in packets: every packet mixes directions, dominant axes (several shear frames in
// one leaf test) and zero direction components (the comparison form of the slab test); finite
// tMax values, 0 among them, cut hits off per lane. kAuto traces them as single rays, and there are
// enough of them (over 4,096) that it first sorts them by where they enter the tree.
TEST(MeshPackets, MixedDirectionPacketsEqualSingleRaysAndBruteForceOnEveryPath) {
  const Mesh soup = test::randomSoup(51, 3000, 40, 4);
  const std::vector<Ray> rays = test::randomRays(52, 4403, 50);  // a tail of 3 in packets of 8, 16
  std::vector<float> tMax(rays.size(), kInf);
  for (std::size_t i = 0; i < rays.size(); i += 3) tMax[i] = float(i % 60);
  const std::size_t hits = checkModes(soup, rays, tMax, 0);
  EXPECT_GT(hits, rays.size() / 10);  // both outcomes, or the comparison proves little
}

// Rays from one point in every direction, on a 64 x 32 longitude-latitude grid: neighbours are
// coherent, but tiles straddle octants and dominant axes, so packets stay together across
// several shear frames.
TEST(MeshPackets, CoherentRaysAcrossOctantsEqualSingleRaysAndBruteForceOnEveryPath) {
  const Mesh soup = test::randomSoup(53, 4000, 30, 5);
  std::vector<Ray> rays;
  constexpr std::uint32_t kWidth = 64, kHeight = 32;
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const double lat = 3.141592653589793 * ((y + 0.5) / kHeight - 0.5);
      const double lon = 2 * 3.141592653589793 * (x + 0.5) / kWidth;
      rays.push_back({{0.5f, -0.25f, 0.125f},
                      Vec3f(float(std::cos(lat) * std::cos(lon)), float(std::sin(lat)),
                            float(std::cos(lat) * std::sin(lon)))});
    }
  const std::size_t hits = checkModes(soup, rays, std::vector<float>(rays.size(), kInf), kWidth);
  EXPECT_GT(hits, rays.size() / 10);
  EXPECT_LT(hits, rays.size());
}

// Watertightness in packets: rays aimed exactly at the vertices of a G = 33 heightfield and at
// points on its shared edges, from above, must hit. Vertical rays form coherent packets (one
// direction); oblique ones, from scattered points, diverge.
TEST(MeshPackets, RaysAtSharedVerticesAndEdgesNeverMissOnEveryPath) {
  constexpr std::uint32_t g = 33;
  const Mesh mesh = workloads::makeHeightfield(g);
  workloads::Random r(54);
  std::vector<Ray> vertical, oblique;
  for (std::uint32_t j = 1; j + 1 < g; ++j)
    for (std::uint32_t i = 1; i + 1 < g; ++i) {
      const Vec3f v = mesh.vertices[j * g + i];
      const Vec3f right = mesh.vertices[j * g + i + 1],
                  diagonal = mesh.vertices[(j + 1) * g + i + 1];
      for (const Vec3f& target : {v, Vec3f((v + right) / 2), Vec3f((v + diagonal) / 2)}) {
        vertical.push_back({{target.x(), 50, target.z()}, {0, -1, 0}});
        const Vec3f from(target.x() + r.uniform(-10, 10), 50, target.z() + r.uniform(-10, 10));
        oblique.push_back({from, target - from});  // not unit: t is in units of it
      }
    }
  for (const auto* rays : {&vertical, &oblique}) {
    const std::size_t hits =
        checkModes(mesh, *rays, std::vector<float>(rays->size(), kInf), 3 * (g - 2));
    EXPECT_EQ(hits, rays->size());  // every one, by the surface's shape (no code's answer)
  }
}

class MeshPacketsOnPath : public OnEveryPath {};
SIMDPHYS_ON_EVERY_PATH(MeshPacketsOnPath);

// The packet kernel itself, with lanes a stream cannot hold: rays with tMax = -inf (the streams'
// padding value) hit nothing and leave the others' answers as they are.
TEST_P(MeshPacketsOnPath, LanesWithMinusInfinityTMaxHitNothing) {
  if (referencePathActive()) GTEST_SKIP() << "the reference path has no packet kernel";
  const Mesh mesh = workloads::makeHeightfield(33);
  const MeshBvh bvh(mesh);
  const RayStream camera = workloads::makeCoherentRays(16, 8);
  std::vector<float> origin[3], direction[3], tMax;
  for (std::size_t i = 0; i < camera.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      origin[k].push_back(camera.origin(k)[i]), direction[k].push_back(camera.direction(k)[i]);
    tMax.push_back(i % 3 == 1 ? -kInf : kInf);
  }
  const simd::RaysView view{
      {origin[0].data(), origin[1].data(), origin[2].data(), direction[0].data(),
       direction[1].data(), direction[2].data(), tMax.data()},
      camera.size(),
      camera.size()};
  std::vector<std::uint32_t> index(camera.size());
  for (std::uint32_t i = 0; i < index.size(); ++i) index[i] = i;
  const simd::MeshView meshView{bvh.bvh().nodes().data(), bvh.bvh().nodes().size(),
                                bvh.blocks().data()};
  for (int width : {8, 16}) {
    std::vector<ElementHit> found(camera.size());
    simd::meshClosestHitPackets(meshView, view, index.data(), index.size() / width, width,
                                found.data());
    std::size_t hits = 0;
    for (std::size_t i = 0; i < camera.size(); ++i) {
      const ElementHit expected = tMax[i] < 0 ? ElementHit{} : test::bruteRaycast(mesh, camera[i]);
      expectSame(found[i], expected,
                 "width " + std::to_string(width) + ", ray " + std::to_string(i));
      hits += expected.hit();
    }
    // Both outcomes (the top rows see sky), or the comparison proves little.
    EXPECT_GT(hits, camera.size() / 4);
  }
}

// A tree with no triangles: every mode answers every ray with a miss, also with enough single rays
// (over 4,096) for kAuto to order them, and an empty stream is no error.
TEST_P(MeshPacketsOnPath, EmptyMeshMissesEveryRay) {
  const MeshBvh bvh(Mesh{});
  const std::vector<Ray> rays = test::randomRays(54, 5000, 10);
  RayStream stream;
  for (const Ray& r : rays) stream.push(r);
  for (const RayStreamOptions& options :
       {RayStreamOptions{Mode::kSingle, 0, 0}, RayStreamOptions{Mode::kAuto, 0, 0},
        RayStreamOptions{Mode::kPackets, 8, 0}}) {
    std::vector<ElementHit> found(rays.size(),
                                  ElementHit{0, 0});  // not a miss: must be overwritten
    bvh.raycast(stream, found, options);
    for (std::size_t i = 0; i < rays.size(); ++i)
      expectSame(found[i], ElementHit{}, describe(options) + ", ray " + std::to_string(i));
    std::vector<ElementHit> none;
    EXPECT_NO_THROW(bvh.raycast(RayStream{}, none, options));
  }
}

TEST(MeshPacketErrors, BadPacketSizeIsRejected) {
  const MeshBvh bvh(workloads::makeHeightfield(5));
  RayStream s;
  s.push({{0, 1, 0}, {0, -1, 0}});
  std::vector<ElementHit> out(1);
  test::expectError(
      [&] {
        bvh.raycast(s, out, {Mode::kPackets, 4, 0});
      },
      "MeshBvh::raycast: packetSize 4 is not 0, 8 or 16");
}

}  // namespace
}  // namespace simdphys

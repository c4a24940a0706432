// A picture to look at: workload W2's heightfield (513 x 513 vertices) with boxes, spheres, a
// small tower with parented parts and houses loaded from an OBJ file, seen by W2's camera.
// Every pixel's primary ray goes through the scene (Scene::raycast on a RayStream, which hands
// the terrain's rays to MeshBvh's stream raycast); a second stream of rays towards the sun
// darkens the points in shadow. Hits are shaded by their normal. Writes a PNG and prints rays
// per second.
//
//   simdphys_render [output.png] [width height]
#include <omp.h>
#include <simdphys/scene/scene.hpp>
#include <simdphys/simdphys.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "rays.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace {

using namespace simdphys;

Mat4f place(float x, float z, float lift, float scale, float yaw = 0) {
  const float y = float(workloads::heightfieldHeight(x, z)) + lift * scale;
  return transform(Vec3f::Constant(scale), rotationY(yaw), Vec3f(x, y, z));
}

// The terrain, then objects standing on it in front of the camera.
Scene buildScene() {
  Scene scene;
  scene.add({std::make_shared<const MeshBvh>(workloads::makeHeightfield())});
  const auto cube =
      std::make_shared<const MeshBvh>(boxMesh({Vec3f::Constant(-0.5f), Vec3f::Constant(0.5f)}));
  const auto ball = std::make_shared<const MeshBvh>(sphereMesh(Vec3f::Zero(), 1, 16, 32));
  const auto house = std::make_shared<const MeshBvh>(loadObj(SIMDPHYS_RENDER_DIR "/house.obj"));
  for (int k = 0; k < 5; ++k) {
    const float x = -48 + 24 * k;
    scene.add({cube, place(x, -40, 0.4f, 7, 0.3f * k)});
    scene.add({Sphere{Vec3f::Zero(), 1}, place(x + 10, -20, 0.8f, 4)});
  }
  scene.add({ball, place(-20, 10, 0.9f, 9)});
  scene.add(
      {Obb{Vec3f::Zero(), {1, 0.5f, 2}, axisAngle(Vec3f(1, 1, 0), 0.6f)}, place(25, 5, 1, 5)});
  for (int k = 0; k < 4; ++k) scene.add({house, place(-45 + 30 * k, 25, 0, 6, 0.5f * k)});
  // A tower: a tall box, a ball on its top (a child: its transform is in the tower's frame) and
  // a slab tilted on the ball (a grandchild).
  const auto tower =
      scene.add({cube, transform(Vec3f(6, 30, 6), Mat3f::Identity(),
                                 Vec3f(0, float(workloads::heightfieldHeight(0, -5)) + 15, -5))});
  const auto top = scene.add(
      {Sphere{Vec3f::Zero(), 1},
       transform(Vec3f(1.0f / 6, 1.0f / 30, 1.0f / 6) * 5, Mat3f::Identity(), Vec3f(0, 0.5f, 0)),
       tower});
  scene.add({Aabb{{-2, -0.1f, -0.5f}, {2, 0.1f, 0.5f}},
             transform(Vec3f::Ones(), rotationZ(0.5f), Vec3f(0, 1.2f, 0)), top});
  scene.update();
  return scene;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The best of a few runs of `cast` over `n` rays, in million rays per second.
template <class Cast>
double megaRaysPerSecond(std::size_t n, Cast cast) {
  double best = 1e30;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    cast();
    best = std::min(best, seconds(start));
  }
  return double(n) / best / 1e6;
}

std::uint8_t channel(float v) { return std::uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "render.png";
  const int width = argc > 3 ? std::atoi(argv[2]) : int(workloads::kCameraWidth);
  const int height = argc > 3 ? std::atoi(argv[3]) : int(workloads::kCameraHeight);
  try {
    const Scene scene = buildScene();
    // W2's camera: at (0, 60, -140) looking at the origin, 60 degrees vertical field of view.
    const Camera camera =
        Camera::perspective({0, 60, -140}, Vec3f::Zero(), Vec3f::UnitY(),
                            std::numbers::pi_v<float> / 3, float(width), float(height), 0.1f, 1000);
    const RayStream rays = camera.primaryRays();
    std::vector<ModelHit> hits(rays.size());
    const double sceneRate = megaRaysPerSecond(rays.size(), [&] { scene.raycast(rays, hits); });
    const auto& terrain = std::get<std::shared_ptr<const MeshBvh>>(scene.model(0).shape);
    std::vector<ElementHit> terrainHits(rays.size());
    const double terrainRate =
        megaRaysPerSecond(rays.size(), [&] { terrain->raycast(rays, terrainHits); });

    // Shadow rays from every hit towards the sun, started a little off the surface.
    const Vec3f sun = Vec3f(-0.5f, 0.8f, -0.35f).normalized();
    RayStream shadowRays;
    std::vector<std::size_t> shadowOf;
    for (std::size_t i = 0; i < hits.size(); ++i)
      if (hits[i].hit() && hits[i].normal.dot(sun) > 0) {
        shadowRays.push({hits[i].point + 1e-2f * hits[i].normal, sun});
        shadowOf.push_back(i);
      }
    std::vector<ModelHit> blockers(shadowRays.size());
    scene.raycast(shadowRays, blockers);
    std::vector<std::uint8_t> lit(hits.size(), 0);
    for (std::size_t k = 0; k < shadowOf.size(); ++k) lit[shadowOf[k]] = !blockers[k].hit();

    std::vector<std::uint8_t> image(std::size_t(width) * height * 3);
    std::size_t hitCount = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
      Vec3f colour;
      if (hits[i].hit()) {
        ++hitCount;
        // The normal as a colour, warmed for objects and greened for the terrain, lit by the sun.
        const Vec3f n = hits[i].normal;
        const Vec3f base =
            hits[i].model == 0 ? Vec3f(0.45f, 0.62f, 0.35f) : Vec3f(0.85f, 0.55f, 0.4f);
        const Vec3f normalTint = 0.5f * (n + Vec3f::Ones());
        const float diffuse = lit[i] ? std::max(0.0f, n.dot(sun)) : 0.0f;
        colour = (0.6f * base + 0.4f * normalTint) * (0.3f + 0.7f * diffuse);
      } else {
        const float up = std::max(0.0f, rays[i].direction.y());
        colour = Vec3f(0.55f, 0.7f, 0.9f) * (1 - up) + Vec3f(0.25f, 0.45f, 0.8f) * up;
      }
      for (int c = 0; c < 3; ++c) image[3 * i + c] = channel(colour[c]);
    }
    if (!stbi_write_png(out.c_str(), width, height, 3, image.data(), width * 3)) {
      std::fprintf(stderr, "error: cannot write %s\n", out.c_str());
      return 1;
    }
    std::printf("render: %dx%d, %zu models, %zu of %zu primary rays hit; path %s, %d thread(s)\n",
                width, height, scene.size(), hitCount, rays.size(), activePath().c_str(),
                omp_get_max_threads());
    std::printf(
        "render: primary rays through the scene: %.2f Mrays/s; the terrain's MeshBvh "
        "alone: %.2f Mrays/s\n",
        sceneRate, terrainRate);
    std::printf("render: wrote %s\n", out.c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

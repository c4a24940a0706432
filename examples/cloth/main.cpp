// A picture of workload W3 at its end: the 128 x 128 cloth, hung from two corners, stepped 300
// frames (5 s) by a World at simdphys's default cloth settings (XPBD, 10 substeps, tethers)
// onto the sphere. The final positions become a triangle mesh (two triangles per grid quad) in
// a Scene with the sphere and a floor; each pixel casts one primary ray through it, and a floor
// hit one ray towards the sun for the cloth's shadow. The cloth is shaded two-sided with a
// checker over its grid (i, j), so the folds show. Writes a PNG and prints the simulation's
// time and stretch.
//
//   simdphys_cloth_picture [output.png] [width height]
#include <simdphys/scene/scene.hpp>
#include <simdphys/simdphys.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "../picture.hpp"
#include "cloth.hpp"

namespace {

using namespace simdphys;

// The grid's quads as triangles: quad (i, j) is triangles 2 q and 2 q + 1, q = j (n - 1) + i.
Mesh clothMesh(std::span<const Vec3f> positions, std::uint32_t n) {
  Mesh mesh{{positions.begin(), positions.end()}, {}};
  for (std::uint32_t j = 0; j + 1 < n; ++j)
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      const std::uint32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  return mesh;
}

// Squares of 8 x 8 grid cells: the cloth's rows and columns stay readable through its folds.
bool checker(std::uint32_t triangle, std::uint32_t n) {
  const std::uint32_t quad = triangle / 2, i = quad % (n - 1), j = quad / (n - 1);
  return (i / 8 + j / 8) % 2 == 0;
}

// A hit's colour: the material, a little of the normal's direction (the folds' orientation), a
// sky light from above and a light at the eye (Lambert against the ray), so the cloth's
// underside, which the sun does not reach from this view, still shows its folds. Normals face
// the ray: the cloth's two sides are shaded alike.
Vec3f shade(const ModelHit& hit, const Vec3f& direction, std::uint32_t n) {
  Vec3f base(1.0f, 1.0f, 0.96f);  // the floor, seen at a grazing angle
  if (hit.model == 0)
    base = checker(hit.triangle, n) ? Vec3f(0.85f, 0.3f, 0.25f) : Vec3f(0.95f, 0.85f, 0.7f);
  if (hit.model == 1) base = Vec3f(0.55f, 0.68f, 0.9f);
  const float eyeLight = -hit.normal.dot(direction.normalized());
  const float skyLight = 0.5f + 0.5f * hit.normal.y();
  const Vec3f tint = hit.model == 0 ? 0.5f * (hit.normal + Vec3f::Ones()) : base;
  return (0.85f * base + 0.15f * tint) * (0.1f + 0.3f * skyLight + 0.6f * eyeLight);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "cloth_drape.png";
  const int width = argc > 3 ? std::atoi(argv[2]) : 800;
  const int height = argc > 3 ? std::atoi(argv[3]) : 600;
  try {
    // W3 at simdphys's defaults: one World step a frame on one thread, the cloth's own 10
    // substeps.
    const std::size_t n = workloads::kClothSizes[0];
    const workloads::ClothWorkload w3 = workloads::makeClothWorkload(n);
    World world(WorldSettings{workloads::kClothFrameTime, 1, 1});
    world.obstacles().add(workloads::kClothSphere);
    const Handle cloth = world.addCloth(Cloth::grid(workloads::clothGrid(w3)));
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < workloads::kClothFrames; ++frame) world.step();
    const double msPerFrame =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count() /
        workloads::kClothFrames;
    const std::vector<Vec3f> positions = world.cloth(cloth).positions();
    const workloads::ClothStretch stretch = workloads::clothStretch(w3, positions);

    // The scene: the cloth (model 0), the sphere (1) and a floor slab under the cloth's hem (2).
    Scene scene;
    scene.add({std::make_shared<const MeshBvh>(clothMesh(positions, std::uint32_t(n)))});
    scene.add({workloads::kClothSphere});
    const float floorY = world.cloth(cloth).bounds().min.y() - 0.3f;
    scene.add({Aabb{{-12, floorY - 0.2f, -12}, {12, floorY, 12}}});
    scene.update();

    // From behind the pinned edge and below it: the cloth hangs from its two corners as a
    // hammock, the sphere holds up its middle, and the rest falls in folds beyond it (seen from
    // above, the cloth hides the sphere).
    const Camera camera = Camera::perspective({1.0f, 0.0f, -8.5f}, {0, 0.6f, -0.2f}, Vec3f::UnitY(),
                                              std::numbers::pi_v<float> * 5 / 18, float(width),
                                              float(height), 0.1f, 100);
    // The sun, above and behind the eye, casts the cloth's shadow on the floor.
    const Vec3f sun = Vec3f(-0.3f, 0.75f, -0.6f).normalized();
    const bool written =
        picture::write(out, scene, camera, width, height, [&](const ModelHit& hit, const Ray& ray) {
          Vec3f colour = shade(hit, ray.direction, std::uint32_t(n));
          if (hit.model == 2 && scene.raycast({hit.point + 1e-3f * hit.normal, sun}).hit())
            colour *= 0.6f;
          return colour;
        });
    if (!written) return 1;
    std::printf(
        "cloth picture: W3 n = %zu, %d frames at %.2f ms a frame (path %s), mean structural "
        "stretch %.3f%%; wrote %dx%d %s\n",
        n, workloads::kClothFrames, msPerFrame, activePath().c_str(), 100 * stretch.mean, width,
        height, out.c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

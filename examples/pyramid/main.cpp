// A picture of workload W5 at its end: the pyramid of base 20 (2,870 unit boxes) stepped 600
// frames (10 s) by a World at simdphys's default rigid-body settings (soft step, 5 substeps;
// sleeping off, as W5 has it). Each box's final pose becomes an OBB in a Scene with the ground;
// each pixel casts one primary ray through it, and a ground or box hit one ray towards the sun
// for shadows. A box is coloured by how far it moved from its start, white (not at all) to red
// (the largest displacement of any box), so the picture shows where the pyramid settled. Writes a
// PNG and prints the simulation's time and W5's measures.
//
//   simdphys_pyramid_picture [output.png] [width height] [base]
#include <simdphys/scene/scene.hpp>
#include <simdphys/simdphys.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "../picture.hpp"
#include "pyramid.hpp"

using namespace simdphys;

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "pyramid_final.png";
  const int width = argc > 3 ? std::atoi(argv[2]) : 800;
  const int height = argc > 3 ? std::atoi(argv[3]) : 600;
  const int base = argc > 4 ? std::atoi(argv[4]) : workloads::kPyramidBases[1];
  try {
    // W5 at simdphys's defaults: one World step a frame on one thread.
    World world(WorldSettings{workloads::kPyramidFrameTime, 1, 1});
    RigidSettings settings;
    settings.sleeping = false;
    world.bodies().setSettings(settings);
    world.obstacles().add(workloads::kPyramidGround);
    const std::vector<Vec3f> start = workloads::pyramidCenters(base);
    std::vector<Handle> boxes;
    for (const Vec3f& p : start) {
      BodyDef d;
      d.position = p, d.friction = workloads::kPyramidFriction;
      boxes.push_back(world.bodies().add(d));
    }
    float deepest = 0;
    const auto begin = std::chrono::steady_clock::now();
    for (int frame = 0; frame < workloads::kPyramidFrames; ++frame) {
      world.step();
      deepest = std::max(deepest, world.bodies().deepestPenetration());
    }
    const double msPerFrame =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
            .count() /
        workloads::kPyramidFrames;
    std::vector<Vec3f> end;
    for (const Handle h : boxes) end.push_back(world.bodies().position(h));
    const workloads::PyramidMeasures m = workloads::measurePyramid(start, end);

    // The scene: the boxes (models 0 .. n-1), then the ground (n).
    Scene scene;
    std::vector<Obb> shapes;
    for (const Handle h : boxes) shapes.push_back(world.bodies().box(h));
    for (const Obb& box : shapes) scene.add({box});
    scene.add({workloads::kPyramidGround});
    scene.update();

    // From a corner, a little above the apex's height: three faces of the pyramid's steps.
    const float b = float(base);
    const Camera camera = Camera::perspective({1.25f * b, 0.85f * b, 1.6f * b}, {0, 0.32f * b, 0},
                                              Vec3f::UnitY(), std::numbers::pi_v<float> * 2 / 9,
                                              float(width), float(height), 0.1f, 10 * b);
    const Vec3f sun = Vec3f(-0.45f, 0.8f, 0.35f).normalized();
    const double scale = m.maxDisplacement > 0 ? m.maxDisplacement : 1;
    const bool written =
        picture::write(out, scene, camera, width, height, [&](const ModelHit& hit, const Ray&) {
          Vec3f albedo(0.55f, 0.6f, 0.55f);  // the ground
          if (hit.model < boxes.size()) {
            const float moved = float((end[hit.model] - start[hit.model]).norm() / scale);
            albedo = Vec3f(0.95f, 0.93f, 0.88f) * (1 - moved) + Vec3f(0.85f, 0.2f, 0.15f) * moved;
            // Darker within 2 cm of an edge (two coordinates at the surface): the boxes' outlines.
            const Obb& box = shapes[hit.model];
            const Vec3f local = box.axes.transpose() * (hit.point - box.center);
            const Vec3f fromSurface = (box.halfExtents - local.cwiseAbs()).cwiseAbs();
            if ((fromSurface.array() < 0.02f).count() >= 2) albedo *= 0.6f;
          }
          const bool lit = !scene.raycast({hit.point + 1e-3f * hit.normal, sun}).hit();
          const float sunLight = lit ? std::max(0.0f, hit.normal.dot(sun)) : 0.0f;
          const float skyLight = 0.5f + 0.5f * hit.normal.y();
          return Vec3f(albedo * (0.15f + 0.25f * skyLight + 0.6f * sunLight));
        });
    if (!written) return 1;
    std::printf(
        "pyramid picture: W5 B = %d (%zu boxes), %d frames at %.2f ms a frame (path %s), largest "
        "displacement %.4f m, deepest penetration %.4f m, %s; wrote %dx%d %s\n",
        base, boxes.size(), workloads::kPyramidFrames, msPerFrame, activePath().c_str(),
        m.maxDisplacement, deepest, m.standing ? "standing" : "fallen", width, height, out.c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}

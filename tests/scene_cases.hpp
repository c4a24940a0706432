// Scenes the scene suites share: random models of every shape kind with rigid transforms and
// uniform scales (so a test can rebuild each model in world space on its own), and helpers.
#pragma once

#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "simdphys/scene/scene.hpp"

namespace simdphys::test {

// A model's placement as parameters: world = T(translation) R(axis, angle) S(scale), uniform.
struct Placement {
  Vec3f translation;
  Vec3f axis;
  float angle;
  float scale;
  Mat4f matrix() const {
    return transform(Vec3f::Constant(scale), axisAngle(axis, angle), translation);
  }
};

inline Placement randomPlacement(std::mt19937& rng, float spread) {
  std::uniform_real_distribution<float> pos(-spread, spread), unit(-1, 1), scale(0.5f, 2.0f);
  std::uniform_real_distribution<float> angle(0, 2 * std::numbers::pi_v<float>);
  Vec3f axis;
  do axis = {unit(rng), unit(rng), unit(rng)};
  while (axis.norm() < 0.1f);
  return {{pos(rng), pos(rng), pos(rng)}, axis, angle(rng), scale(rng)};
}

// A small bumpy heightfield over [-1, 1]^2, a box and a sphere as meshes, shared by instances.
struct Meshes {
  std::shared_ptr<const MeshBvh> terrain, box, ball;
  Meshes()
      : terrain(std::make_shared<MeshBvh>(heightfieldMesh(
            9, 9, -1, 1, -1, 1, [](double x, double z) { return 0.2 * std::sin(3 * x) * z; }))),
        box(std::make_shared<MeshBvh>(boxMesh({{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}}))),
        ball(std::make_shared<MeshBvh>(sphereMesh(Vec3f::Zero(), 0.7f, 6, 8))) {}
};

// Model i's shape cycles through the kinds: the three meshes, a sphere, an AABB, an OBB.
inline ModelShape shapeKind(const Meshes& meshes, int i) {
  switch (i % 6) {
    case 0:
      return meshes.terrain;
    case 1:
      return meshes.box;
    case 2:
      return meshes.ball;
    case 3:
      return Sphere{{0.1f, 0, 0}, 0.6f};
    case 4:
      return Aabb{{-0.3f, -0.6f, -0.2f}, {0.4f, 0.5f, 0.3f}};
    default:
      return Obb{{0, 0.1f, 0}, {0.5f, 0.3f, 0.2f}, axisAngle(Vec3f(1, 2, 3), 0.7f)};
  }
}

struct RandomScene {
  Meshes meshes;
  std::vector<Placement> placements;
  Scene scene;
  RandomScene(int models, float spread, unsigned seed) {
    std::mt19937 rng(seed);
    for (int i = 0; i < models; ++i) {
      placements.push_back(randomPlacement(rng, spread));
      scene.add({shapeKind(meshes, i), placements.back().matrix()});
    }
    scene.update();
  }
};

// A unit direction from a random point of the sphere of directions.
inline Vec3f randomDirection(std::mt19937& rng) {
  std::normal_distribution<float> g;
  Vec3f d;
  do d = {g(rng), g(rng), g(rng)};
  while (d.norm() < 1e-3f);
  return d.normalized();
}

}  // namespace simdphys::test

#include "particles.hpp"

#include <cmath>
#include <memory>

#include "simdphys/math.hpp"
#include "workloads.hpp"

namespace simdphys::workloads {

Obb particleGround() { return {{0, -1, 0}, {20, 1, 20}}; }

Obb particleRamp() { return {{0, 2, 0}, {6, 0.25f, 6}, rotationZ(0.35).cast<float>()}; }

void addParticleField(World& world) {
  for (int i = 0; i < 16; ++i)
    for (int k = 0; k < 16; ++k) {
      const float x = -9.375f + 1.25f * float(i), z = -9.375f + 1.25f * float(k);
      switch ((i + k) % 3) {
        case 0:
          world.obstacles().add(Sphere{{x, 0.4f, z}, 0.4f});
          break;
        case 1:
          world.obstacles().add(Aabb{{x - 0.3f, 0, z - 0.3f}, {x + 0.3f, 1.2f, z + 0.3f}});
          break;
        default:
          world.obstacles().add(
              Obb{{x, 0.5f, z}, {0.35f, 0.5f, 0.2f}, rotationY(0.3 * (i + 2 * k)).cast<float>()});
          break;
      }
    }
}

void addParticleTerrain(World& world) {
  const Mesh terrain = heightfieldMesh(65, 65, -10, 10, -10, 10, [](double x, double z) {
    return 0.3 + 0.25 * std::sin(0.9 * x) * std::cos(0.7 * z);
  });
  world.obstacles().add(std::make_shared<const MeshBvh>(terrain));
}

ParticleWorkload makeParticleWorkload(std::size_t n) {
  ParticleSettings settings;
  settings.gravity = {0, -9.82f, 0};
  settings.restitution = 0.7f;
  settings.damping = 0.95f;
  settings.friction = 0;
  ParticleWorkload w{World(WorldSettings{.timeStep = 1.0f / 60.0f}), {}};
  w.world.obstacles().add(particleGround());
  w.world.obstacles().add(particleRamp());
  w.particles = w.world.addParticles(settings);
  ParticleSystem& system = w.world.particles(w.particles);
  system.reserve(n);
  Random r(4);
  for (std::size_t i = 0; i < n; ++i) {
    const float x = r.uniform(-10, 10);
    const float y = r.uniform(5, 25);
    const float z = r.uniform(-10, 10);
    system.add({x, y, z});
  }
  return w;
}

}  // namespace simdphys::workloads

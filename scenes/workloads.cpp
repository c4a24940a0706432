#include "workloads.hpp"

#include <cmath>
#include <numbers>

namespace simdphys::scenes {

std::uint64_t Random::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

float Random::u01() { return float(next() >> 40) * 0x1p-24f; }

float Random::uniform(float a, float b) {
  float scaled = (b - a) * u01();
  return a + scaled;
}

Vec3f Random::unitDirection() {
  for (;;) {
    float x = uniform(-1, 1), y = uniform(-1, 1), z = uniform(-1, 1);
    float l2 = x * x + y * y + z * z;
    if (l2 > 1 || l2 < 1e-6f) continue;
    float l = std::sqrt(l2);
    return {x / l, y / l, z / l};
  }
}

namespace {
Aabb randomBox(Random& r, float halfMin, float halfMax) {
  Vec3f c, h;
  for (int a = 0; a < 3; ++a) c[a] = r.uniform(-100, 100);
  for (int a = 0; a < 3; ++a) h[a] = r.uniform(halfMin, halfMax);
  return {c - h, c + h};
}
}  // namespace

AabbWorkload makeAabbWorkload(std::size_t boxes, std::size_t queries) {
  Random r(1);
  AabbWorkload w;
  w.boxes.reserve(boxes);
  for (std::size_t i = 0; i < boxes; ++i) w.boxes.push(randomBox(r, 0.1f, 1.5f));
  for (std::size_t q = 0; q < queries; ++q) w.queries.push_back(randomBox(r, 1, 8));
  return w;
}

std::uint64_t pairChecksum(std::span<const Pair> pairs, std::size_t n) {
  std::uint64_t sum = 0;
  for (const Pair& p : pairs) sum += std::uint64_t(p.a) * n + p.b;
  return sum;
}

CullWorkload makeCullWorkload(std::size_t n) {
  Random r(6);
  CullWorkload w;
  w.spheres.reserve(n);
  w.boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3f c;
    for (int a = 0; a < 3; ++a) c[a] = r.uniform(-500, 500);
    float radius = r.uniform(0.5f, 5);
    w.spheres.push({c, radius});
    w.boxes.push(c, Vec3f::Constant(radius));
  }
  Mat4d view = lookAt(Vec3d(0, 0, 0), Vec3d(0, 0, 1), Vec3d(0, 1, 0));
  Mat4d proj = perspective(std::numbers::pi / 3, 16.0 / 9.0, 0.1, 1000.0);
  w.viewProjection = proj * view;
  w.frustum = Frustumd::fromMatrix(w.viewProjection).cast<float>();
  return w;
}

}  // namespace simdphys::scenes

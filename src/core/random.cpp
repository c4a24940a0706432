#include "simdphys/random.hpp"

#include <cmath>

namespace simdphys {

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

}  // namespace simdphys

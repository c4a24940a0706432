// The random numbers of the standard workloads (docs/workloads.md) and of scene files' emitters:
// SplitMix64 and the float draws built on it, the same on every machine and compiler (the library
// is compiled without floating-point contraction, so each draw rounds as specified).
#pragma once

#include <cstdint>

#include "simdphys/math.hpp"

namespace simdphys {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  float u01();                      // [0, 1), 24 bits
  float uniform(float a, float b);  // a + (b - a) * u01(), the product rounded before the addition
  Vec3f unitDirection();            // rejection-sampled in the unit ball, then normalised

 private:
  std::uint64_t state_;
};

}  // namespace simdphys

// Test support, not public API: a cloth stepped in double precision by the scalar reference, the
// truth that the float paths' error is measured against (tests, W3 benchmark).
#pragma once

#include <vector>

#include "simdphys/world.hpp"

namespace simdphys::test {

// A cloth's state in double, over its slots (the float streams' layout).
class ClothD {
 public:
  explicit ClothD(const Cloth& cloth);
  // One world step (its substeps) of the cloth as World::step() takes it, in double.
  void step(const Cloth& cloth, const World& world);
  std::vector<Vec3d> positions(const Cloth& cloth) const;

 private:
  std::vector<std::vector<double>> s_;
};

// The largest and the root-mean-square distance between two sets of positions, in double.
struct PositionError {
  double max = 0, rms = 0;
};
PositionError positionError(const std::vector<Vec3f>& a, const std::vector<Vec3d>& b);

}  // namespace simdphys::test

// Test support, not public API: a world's rigid bodies stepped in double precision by the scalar
// reference, the truth that the float paths' error is measured against (tests, W5 benchmark).
#pragma once

#include <memory>
#include <vector>

#include "simdphys/world.hpp"

namespace simdphys::test {

class BodiesD {
 public:
  explicit BodiesD(const RigidBodies& bodies);
  ~BodiesD();
  // One world step (its substeps) of the bodies as World::step() takes it, in double.
  void step(const World& world);
  std::vector<Vec3d> positions() const;
  double deepestPenetration() const { return deepest_; }

 private:
  struct State;
  std::unique_ptr<State> state_;
  double deepest_ = 0;
};

}  // namespace simdphys::test

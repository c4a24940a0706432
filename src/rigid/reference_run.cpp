// testing/rigid.hpp: rigid bodies stepped by the double-precision reference.
#include "src/reference/rigid/step-inl.hpp"
#include "src/rigid/step.hpp"
#include "testing/rigid.hpp"

namespace simdphys::test {

struct BodiesD::State {
  std::vector<detail::BodyT<double>> bodies;
  std::vector<std::uint32_t> slots;
  detail::ContactCacheT<double> cache, next;
  detail::BroadphaseCache broadphase;
};

BodiesD::BodiesD(const RigidBodies& bodies)
    : state_(new State{RigidBodies::Internals::load<double>(bodies),
                       RigidBodies::Internals::slots(bodies),
                       {},
                       {},
                       {}}) {}

BodiesD::~BodiesD() = default;

void BodiesD::step(const World& world) {
  const WorldSettings& w = world.settings();
  const double dt = double(w.timeStep / float(w.substeps));
  for (int sub = 0; sub < w.substeps; ++sub) {
    deepest_ =
        detail::stepState(state_->bodies, state_->slots, state_->cache, state_->next,
                          state_->broadphase, world.obstacles(), world.bodies().settings(), dt)
            .deepest;
    std::swap(state_->cache, state_->next);
  }
}

std::vector<Vec3d> BodiesD::positions() const {
  std::vector<Vec3d> out;
  for (const auto& b : state_->bodies) out.push_back(b.x);
  return out;
}

}  // namespace simdphys::test

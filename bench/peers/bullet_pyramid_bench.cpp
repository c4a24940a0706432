// Peer: Bullet's rigid bodies (Debian's libbullet-dev 3.24, single precision, one thread) on W5,
// the pyramid of workloads/pyramid.hpp: 600 frames per run, one frame an iteration.
//
// Set up as Bullet's own rigid-body demos set up a stack (examples/BasicDemo, BasicExample.cpp):
// btDiscreteDynamicsWorld over btDefaultCollisionConfiguration, its btCollisionDispatcher,
// btDbvtBroadphase and btSequentialImpulseConstraintSolver, every solver setting as
// btContactSolverInfo constructs it (10 iterations, warm starting, split impulse, erp 0.2).
// - Boxes: one btBoxShape(0.5, 0.5, 0.5) shared by all, mass 1 with its calculateLocalInertia,
//   created in W5's order (pyramidCenters), no motion state (the world transform is the state),
//   no damping, deactivation disabled (DISABLE_DEACTIVATION: W5 has no sleeping).
// - Collision margin: btBoxShape's default, 0.04, which a box takes inside its half extents
//   (its implicit dimensions are 0.46 plus the margin), so the box's surface is W5's; box-box
//   pairs go to btBoxBoxCollisionAlgorithm, which measures the full extents.
// - Ground: a static body (mass 0) with btBoxShape(100, 0.5, 100) at (0, -0.5, 0).
// - Friction: W5 asks for 0.6 on every contact whatever the engine's rule for combining two.
//   Bullet's rule (btManifoldResult::calculateCombinedFriction) is the product of the two
//   objects' frictions, so every object, ground included, is given sqrt(0.6) and every contact
//   has 0.6. Restitution 0 (the product is 0 too).
// - Stepping: stepSimulation(1/60, 1, 1/60), exactly one internal step a frame (checked: a run
//   whose step count differs is marked failed); the step is timed, nothing else.
//
// Counters: pyramidCounters (bench_common.hpp), the deepest penetration being Bullet's own:
// after each step, the largest -getDistance() over the contact points of every persistent
// manifold of the dispatcher (read outside the timed step).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include "bench/bench_common.hpp"
#include "pyramid.hpp"

#include "bench/peers/bullet.hpp"

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;

// W5 in a Bullet world.
class BulletPyramid {
 public:
  explicit BulletPyramid(const std::vector<Vec3f>& centers)
      : dispatcher_(&config_),
        world_(&dispatcher_, &broadphase_, &solver_, &config_),
        boxShape_(
            btVector3(workloads::kPyramidHalf, workloads::kPyramidHalf, workloads::kPyramidHalf)),
        groundShape_(toBullet(workloads::kPyramidGround.halfExtents)) {
    world_.setGravity(toBullet(workloads::kPyramidGravity));
    const btScalar friction = std::sqrt(workloads::kPyramidFriction);  // product: 0.6

    btTransform at;
    at.setIdentity();
    at.setOrigin(toBullet(workloads::kPyramidGround.center));
    ground_ = std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape_));
    ground_->setWorldTransform(at);
    ground_->setFriction(friction);
    ground_->setRestitution(workloads::kPyramidRestitution);
    world_.addRigidBody(ground_.get());

    btVector3 inertia(0, 0, 0);
    boxShape_.calculateLocalInertia(workloads::kPyramidMass, inertia);
    boxes_.reserve(centers.size());
    for (const Vec3f& c : centers) {
      btRigidBody::btRigidBodyConstructionInfo info(workloads::kPyramidMass, nullptr, &boxShape_,
                                                    inertia);
      info.m_friction = friction;
      info.m_restitution = workloads::kPyramidRestitution;
      at.setOrigin(toBullet(c));
      info.m_startWorldTransform = at;
      auto body = std::make_unique<btRigidBody>(info);
      body->setActivationState(DISABLE_DEACTIVATION);
      world_.addRigidBody(body.get());
      boxes_.push_back(std::move(body));
    }
  }
  BulletPyramid(const BulletPyramid&) = delete;
  BulletPyramid& operator=(const BulletPyramid&) = delete;
  ~BulletPyramid() {
    for (auto it = boxes_.rbegin(); it != boxes_.rend(); ++it) world_.removeRigidBody(it->get());
    world_.removeRigidBody(ground_.get());
  }

  // One frame; returns the number of internal steps Bullet took (1).
  int step() {
    return world_.stepSimulation(workloads::kPyramidFrameTime, 1, workloads::kPyramidFrameTime);
  }
  // The deepest penetration of the contacts Bullet holds now (0 when none penetrates).
  double deepestContact() {
    double deepest = 0;
    for (int i = 0; i < dispatcher_.getNumManifolds(); ++i) {
      const btPersistentManifold* m = dispatcher_.getManifoldByIndexInternal(i);
      for (int j = 0; j < m->getNumContacts(); ++j)
        deepest = std::max(deepest, -double(m->getContactPoint(j).getDistance()));
    }
    return deepest;
  }
  void positions(std::vector<Vec3f>& out) const {
    out.resize(boxes_.size());
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      const btVector3& p = boxes_[i]->getWorldTransform().getOrigin();
      out[i] = {p.x(), p.y(), p.z()};
    }
  }

 private:
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  btBoxShape boxShape_;
  btBoxShape groundShape_;
  std::unique_ptr<btRigidBody> ground_;
  std::vector<std::unique_ptr<btRigidBody>> boxes_;
};

// One run of W5 at base `base`, one frame an iteration.
void pyramidRun(benchmark::State& state, int base) {
  const std::vector<Vec3f> start = workloads::pyramidCenters(base);
  BulletPyramid pyramid(start);
  double seconds = 0, deepest = 0;
  int frames = 0, steps = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    steps += pyramid.step();
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    state.PauseTiming();
    ++frames;
    deepest = std::max(deepest, pyramid.deepestContact());
    state.ResumeTiming();
  }
  std::vector<Vec3f> end;
  pyramid.positions(end);
  pyramidCounters(state, start, end, frames, seconds, deepest);
  if (steps != frames) state.SkipWithError("Bullet did not take exactly one step a frame");
}

void registerBulletPyramid() {
  for (int base : workloads::kPyramidBases)
    registerOnce(
        "pyramid", "bullet_sequential_impulse", "peer", std::size_t(base),
        [base](benchmark::State& state) { pyramidRun(state, base); }, workloads::kPyramidFrames);
}

const bool kRegistered = (registerBulletPyramid(), true);

}  // namespace
}  // namespace simdphys::bench

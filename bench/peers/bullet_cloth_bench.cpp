// Peer: Bullet's btSoftBody (Debian's libbullet-dev 3.24, single precision, one thread) on W3, the
// cloth of workloads/cloth.hpp: 300 frames per run, one iteration a frame.
//
// Set up as Bullet's own SoftDemo sets up its cloth (examples/SoftDemo/SoftDemo.cpp, Init_Cloth):
// a btSoftRigidDynamicsWorld over btSoftBodyRigidBodyCollisionConfiguration, its dispatcher, a
// broadphase (btDbvtBroadphase here; the demo's btAxisSweep3 makes no difference to two objects)
// and btSequentialImpulseConstraintSolver; the world's own btSoftBodyWorldInfo (the constructor
// gives it the broadphase and dispatcher and initialises its sparse SDF) with W3's gravity. The
// soft body: one node per W3 particle (mass 1), the two corners pinned with setMass(node, 0), and
// one link per W3 spring (appendLink with the default material, linear stiffness 1) given W3's
// rest length; no faces (W3 has none to give: its collisions are the nodes'). Collisions: Bullet's
// default flags, SDF_RS (nodes against the rigid body's sparse signed distance field, as the
// demo's cloth uses), with every other setting as btSoftBody constructs it (margin 0.25, kinetic
// contact hardness kKHR 0.1, friction kDF 0.2, no damping). The sphere: a static btRigidBody with
// btSphereShape(0.5). Each frame: stepSimulation(1/60, 1, 1/60), then the SDF's garbage
// collection, as the demo does after every step; both timed.
// Settings: position iterations (m_cfg.piterations) as constructed (1), 10 and 30.
//
// Counters: ms_per_frame and spring_updates_per_second (springs x position iterations x frames
// / s) over the frames stepped; W3's stretch figures at the end; the deepest penetration into the
// true sphere (radius 0.5) over every frame (while finite); finite (1 when every position stayed
// finite); exploded (1 when, at the end of some frame, a position was non-finite or the 99th
// percentile of the structural stretch passed 1: over 1% of the springs at more than twice their
// rest length, a torn net rather than a cloth; the maximum alone does not tell, since the springs
// at the pins stretch that far in runs that otherwise hold) and the first such frame. A run stops
// stepping Bullet at its first non-finite position (the frames left are not stepped, and not in
// ms_per_frame).
#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "cloth.hpp"

#include "bench/peers/bullet.hpp"

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kTorn = 1;  // the 99th percentile stretch past which the cloth has exploded

// W3 in a Bullet world: the cloth as a soft body and the sphere as a static rigid body.
class BulletCloth {
 public:
  BulletCloth(const workloads::ClothWorkload& w, int positionIterations)
      : dispatcher_(&config_),
        world_(&dispatcher_, &broadphase_, &solver_, &config_),
        sphereShape_(workloads::kClothSphere.radius) {
    world_.setGravity(toBullet(workloads::kClothGravity));
    btSoftBodyWorldInfo& info = world_.getWorldInfo();
    info.m_gravity = toBullet(workloads::kClothGravity);

    btTransform at;
    at.setIdentity();
    at.setOrigin(toBullet(workloads::kClothSphere.center));
    sphere_ = std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &sphereShape_));
    sphere_->setWorldTransform(at);
    world_.addRigidBody(sphere_.get());

    std::vector<btVector3> x;
    for (const Vec3f& p : w.positions) x.push_back(toBullet(p));
    const std::vector<btScalar> mass(x.size(), 1);
    cloth_ = std::make_unique<btSoftBody>(&info, int(x.size()), x.data(), mass.data());
    for (std::size_t i = 0; i < w.invMass.size(); ++i)
      if (w.invMass[i] == 0) cloth_->setMass(int(i), 0);
    for (const workloads::ClothSpring& s : w.springs) {
      cloth_->appendLink(int(s.a), int(s.b));
      cloth_->m_links[cloth_->m_links.size() - 1].m_rl = s.rest;
    }
    cloth_->m_bUpdateRtCst = true;  // the link constants follow the rest lengths set above
    if (positionIterations > 0) cloth_->m_cfg.piterations = positionIterations;
    world_.addSoftBody(cloth_.get());
  }
  BulletCloth(const BulletCloth&) = delete;
  BulletCloth& operator=(const BulletCloth&) = delete;
  ~BulletCloth() {
    world_.removeSoftBody(cloth_.get());
    world_.removeRigidBody(sphere_.get());
  }

  void step() {
    world_.stepSimulation(workloads::kClothFrameTime, 1, workloads::kClothFrameTime);
    world_.getWorldInfo().m_sparsesdf.GarbageCollect();
  }
  int positionIterations() const { return cloth_->m_cfg.piterations; }
  void positions(std::vector<Vec3f>& out) const {
    out.resize(std::size_t(cloth_->m_nodes.size()));
    for (int i = 0; i < cloth_->m_nodes.size(); ++i) {
      const btVector3& p = cloth_->m_nodes[i].m_x;
      out[std::size_t(i)] = {p.x(), p.y(), p.z()};
    }
  }

 private:
  btSoftBodyRigidBodyCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btSoftRigidDynamicsWorld world_;
  btSphereShape sphereShape_;
  std::unique_ptr<btRigidBody> sphere_;
  std::unique_ptr<btSoftBody> cloth_;
};

const workloads::ClothWorkload& clothWorkload(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<workloads::ClothWorkload>> cache;
  auto& w = cache[n];
  if (!w) w = std::make_unique<workloads::ClothWorkload>(workloads::makeClothWorkload(n));
  return *w;
}

// One run of W3, one frame an iteration; `positionIterations` 0 keeps Bullet's default.
void clothRun(benchmark::State& state, std::size_t n, int positionIterations) {
  const workloads::ClothWorkload& w = clothWorkload(n);
  BulletCloth cloth(w, positionIterations);
  std::vector<Vec3f> x;
  double seconds = 0, deepest = 0;
  int stepped = 0, explodedAt = -1;
  bool finite = true;
  for (auto _ : state) {
    if (!finite) continue;  // Bullet is not stepped past a non-finite position
    const auto start = Clock::now();
    cloth.step();
    seconds += std::chrono::duration<double>(Clock::now() - start).count();
    state.PauseTiming();
    ++stepped;
    cloth.positions(x);
    finite = workloads::allFinite(x);
    if (finite)
      deepest = std::max(deepest, workloads::spherePenetration(workloads::kClothSphere, x));
    if (explodedAt < 0 && (!finite || workloads::clothStretch(w, x).p99 > kTorn))
      explodedAt = stepped;
    state.ResumeTiming();
  }
  const double iterations = cloth.positionIterations();
  state.counters["frames"] = stepped;
  state.counters["position_iterations"] = iterations;
  state.counters["ms_per_frame"] = seconds * 1e3 / stepped;
  state.counters["spring_updates_per_second"] =
      double(w.springs.size()) * iterations * stepped / seconds;
  clothCounters(state, w, x, deepest, finite);
  state.counters["exploded"] = explodedAt >= 0 ? 1 : 0;
  state.counters["exploded_frame"] = explodedAt;
  state.SetItemsProcessed(std::int64_t(w.springs.size()) * std::int64_t(iterations) * stepped);
}

void registerBulletCloth() {
  for (std::size_t n : workloads::kClothSizes)
    for (int iterations : {0, 10, 30}) {
      const std::string method = iterations == 0
                                     ? "bullet_softbody_default"
                                     : "bullet_softbody_" + std::to_string(iterations) + "it";
      registerOnce(
          "cloth", method, "peer", n,
          [n, iterations](benchmark::State& state) { clothRun(state, n, iterations); },
          workloads::kClothFrames);
    }
}

const bool kRegistered = (registerBulletCloth(), true);

}  // namespace
}  // namespace simdphys::bench

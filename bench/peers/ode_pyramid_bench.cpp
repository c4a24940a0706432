// Peer: the Open Dynamics Engine (Debian's libode-dev 0.16.2, built in double precision, dDOUBLE;
// one thread: the world's default, self-threaded, implementation) on W5, the pyramid of
// workloads/pyramid.hpp: 600 frames per run, one frame an iteration.
//
// Two setups, both with every W5 figure and ERP 0.2 (ODE's default), stepped by dWorldQuickStep
// with 20 iterations (ODE's default) and its default over-relaxation (1.3):
// - ode_quickstep: the world as dWorldCreate makes it: CFM 1e-10 (this double build's default;
//   1e-5 in single precision), contact surface layer 0, contact max correcting velocity infinite.
// - ode_quickstep_stacking: the world as ODE's box-stacking demo (ode/demo/demo_boxstack.cpp)
//   sets it, following the remarks of ode/objects.h for resting contact: CFM 1e-5; contact
//   surface layer 0.001 ("increasing this to some small value (e.g. 0.001) can help prevent
//   jittering problems due to contacts being repeatedly made and broken"); contact max
//   correcting velocity 0.1 ("reducing this value can help prevent popping of deeply embedded
//   objects"). The layer lets every resting contact sink into it by design, so the top of a
//   B-layer pyramid sits about B mm low (11 mm at B = 10: nearly all of max_displacement there).
// Measured here, both stand at B = 10 and 20; the default setup has the smaller displacement and
// the shorter step at both, the stacking one the shallower contacts at B = 10 only.
// Common to both:
// - World: W5's gravity; no damping; auto-disable off (W5 has no sleeping); QuickStep's random
//   constraint order restarted from the seed of a fresh process (dRandSetSeed(0)) every run, so
//   a run's figures do not depend on the runs before it.
// - Space: dHashSpace (the demo's), holding the boxes and the ground.
// - Boxes: dCreateBox 1 x 1 x 1 on a body of mass 1 (dMassSetBoxTotal), created in W5's order
//   (pyramidCenters). Ground: a static box geom (no body), 200 x 1 x 200 centred at (0, -0.5, 0).
// - Contacts: dCollide with at most 4 contacts a pair (the demo asks for 8; ODE's box-box test,
//   dBoxBox, then culls a face-on-face contact of up to 8 points to the 4 best spread, which is
//   what a resting face needs and what Bullet's persistent manifolds keep; 8 changed little in a
//   check at B = 10). Each a contact joint with mu 0.6 (ODE takes the contact's mu as given: no
//   combining rule) in both friction directions, dContactApprox1 (the friction pyramid: the limit
//   follows the normal force), no bounce (restitution 0), soft ERP and CFM not set per contact,
//   so the world's apply.
//
// Counters: pyramidCounters (bench_common.hpp), the deepest penetration being ODE's own: the
// largest depth of the contacts dCollide generates, over every frame (kept in the near callback,
// inside the timed step: one max per contact); the setup's CFM and surface layer as ODE reports
// them, its iterations and contacts a pair.
#include <algorithm>
#include <chrono>
#include <vector>

#include "bench/bench_common.hpp"
#include "pyramid.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wshadow"
#include <ode/ode.h>
#pragma GCC diagnostic pop

namespace simdphys::bench {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxContacts = 4;  // a pair's contacts
constexpr int kIterations = 20;  // QuickStep's, ODE's default
constexpr dReal kErp = 0.2;      // ODE's default

// A world setup: ODE's defaults left as they are, or the box-stacking demo's.
struct Setup {
  const char* name;
  bool stacking;
};
constexpr Setup kSetups[] = {{"ode_quickstep", false}, {"ode_quickstep_stacking", true}};
constexpr dReal kStackingCfm = 1e-5;
constexpr dReal kStackingSurfaceLayer = 0.001;
constexpr dReal kStackingMaxCorrectingVelocity = 0.1;

// W5 in an ODE world.
class OdePyramid {
 public:
  OdePyramid(const std::vector<Vec3f>& centers, bool stacking) {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    // QuickStep shuffles its constraints with ODE's global random generator; starting every run
    // from the seed a fresh process has makes a run's figures independent of the runs before it.
    dRandSetSeed(0);
    world_ = dWorldCreate();
    const Vec3f& g = workloads::kPyramidGravity;
    dWorldSetGravity(world_, g.x(), g.y(), g.z());
    dWorldSetERP(world_, kErp);
    if (stacking) {
      dWorldSetCFM(world_, kStackingCfm);
      dWorldSetContactSurfaceLayer(world_, kStackingSurfaceLayer);
      dWorldSetContactMaxCorrectingVel(world_, kStackingMaxCorrectingVelocity);
    }
    dWorldSetQuickStepNumIterations(world_, kIterations);
    dWorldSetAutoDisableFlag(world_, 0);
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);

    const Obb& ground = workloads::kPyramidGround;
    ground_ = dCreateBox(space_, 2 * ground.halfExtents.x(), 2 * ground.halfExtents.y(),
                         2 * ground.halfExtents.z());
    dGeomSetPosition(ground_, ground.center.x(), ground.center.y(), ground.center.z());

    const dReal side = 2 * workloads::kPyramidHalf;
    dMass mass;
    dMassSetBoxTotal(&mass, workloads::kPyramidMass, side, side, side);
    bodies_.reserve(centers.size());
    for (const Vec3f& c : centers) {
      const dBodyID body = dBodyCreate(world_);
      dBodySetMass(body, &mass);
      dBodySetPosition(body, c.x(), c.y(), c.z());
      dBodySetAutoDisableFlag(body, 0);
      dGeomSetBody(dCreateBox(space_, side, side, side), body);
      bodies_.push_back(body);
    }
  }
  OdePyramid(const OdePyramid&) = delete;
  OdePyramid& operator=(const OdePyramid&) = delete;
  ~OdePyramid() {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);  // destroys its geoms too (cleanup mode on by default)
    dWorldDestroy(world_);  // and the bodies
    dCloseODE();
  }

  // One frame: the contacts, one quick step, the contacts' joints emptied.
  void step() {
    dSpaceCollide(space_, this, &OdePyramid::nearCallback);
    dWorldQuickStep(world_, workloads::kPyramidFrameTime);
    dJointGroupEmpty(contacts_);
  }
  double deepest() const { return deepest_; }
  double cfm() const { return dWorldGetCFM(world_); }
  double surfaceLayer() const { return dWorldGetContactSurfaceLayer(world_); }
  void positions(std::vector<Vec3f>& out) const {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const dReal* p = dBodyGetPosition(bodies_[i]);
      out[i] = {float(p[0]), float(p[1]), float(p[2])};
    }
  }

 private:
  static void nearCallback(void* data, dGeomID a, dGeomID b) {
    static_cast<OdePyramid*>(data)->collide(a, b);
  }
  void collide(dGeomID a, dGeomID b) {
    dContact contact[kMaxContacts] = {};
    const int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
    const dBodyID bodyA = dGeomGetBody(a), bodyB = dGeomGetBody(b);
    for (int i = 0; i < n; ++i) {
      dContact& c = contact[i];
      c.surface.mode = dContactApprox1;
      c.surface.mu = workloads::kPyramidFriction;
      deepest_ = std::max(deepest_, double(c.geom.depth));
      dJointAttach(dJointCreateContact(world_, contacts_, &c), bodyA, bodyB);
    }
  }

  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  dGeomID ground_ = nullptr;
  std::vector<dBodyID> bodies_;
  double deepest_ = 0;
};

// One run of W5 at base `base`, one frame an iteration.
void pyramidRun(benchmark::State& state, int base, bool stacking) {
  const std::vector<Vec3f> start = workloads::pyramidCenters(base);
  OdePyramid pyramid(start, stacking);
  double seconds = 0;
  int frames = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    pyramid.step();
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    ++frames;
  }
  std::vector<Vec3f> end;
  pyramid.positions(end);
  pyramidCounters(state, start, end, frames, seconds, pyramid.deepest());
  state.counters["quickstep_iterations"] = kIterations;
  state.counters["max_contacts"] = kMaxContacts;
  state.counters["cfm"] = pyramid.cfm();
  state.counters["surface_layer"] = pyramid.surfaceLayer();
}

void registerOdePyramid() {
  for (const Setup& setup : kSetups)
    for (int base : workloads::kPyramidBases)
      registerOnce(
          "pyramid", setup.name, "peer", std::size_t(base),
          [base, setup](benchmark::State& state) { pyramidRun(state, base, setup.stacking); },
          workloads::kPyramidFrames);
}

const bool kRegistered = (registerOdePyramid(), true);

}  // namespace
}  // namespace simdphys::bench

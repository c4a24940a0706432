// Rigid bodies (book chapter 15 and its appendix): spheres, boxes and convex hulls with mass and
// inertia in
// structure-of-arrays streams, stepped by a World (world.hpp) against each other and against the
// world's static obstacles (obstacles.hpp: planes, spheres, boxes, triangle meshes).
//
// A step of dt, as Box2D v3 and Box3D solve it (Catto, "Solver2D", 2024): contacts are found once
// (broadphase over the bodies' bounds grown by the speculative distance, then the manifolds of
// rigid/manifold.hpp, or last step's where a pair of bodies has barely moved: reuseManifolds;
// matched with last step's by feature to warm start their impulses), then
// each of `substeps` substeps of h integrates velocities (gravity, forces, damping, and the
// gyroscopic term implicitly, so a free spinning box keeps its angular momentum), warm starts,
// solves the contacts, integrates positions, and, for the soft step, relaxes; restitution is
// applied once at the end. Contacts are solved with accumulated impulses clamped at zero, and
// friction along two tangents clamped by the Coulomb cone's square (|f_i| <= mu * normal).
//
// Three contact models (ContactModel), each measured on W5 (docs/rigid.md):
//  - kSoftStep: soft contacts (a spring of contactHertz and contactDampingRatio, push-out capped
//    at maxPushSpeed) with a relax pass without the push-out (Box2D v3's default).
//  - kBaumgarte: rigid contacts with a velocity bias of baumgarte / h times the penetration past
//    linearSlop (the appendix's Baumgarte stabilisation with slop).
//  - kProjection: rigid contacts without bias, then the book's linear projection: bodies moved
//    apart along the normal by projection * (depth - slop), shared by inverse mass.
// Speculative contacts (within speculativeDistance) are solved in every model: a body is stopped
// at the surface it would reach within the substep instead of passing it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/rigid/hull.hpp"
#include "simdphys/stream_fields.hpp"

namespace simdphys {

namespace detail {
// A manifold's accumulated impulses kept from one step to the next for warm starting (the
// appendix's arbiters), found by key (the pair's handle slots, which stay while bodies live)
// and each point by its feature id. `sub` names one of a pair's several manifolds (a body against
// a mesh has one per group of its triangles), else 0.
template <class T>
struct CachedManifoldT {
  std::uint64_t key;
  std::uint32_t sub;
  int count;
  std::uint32_t id[4];
  T impulse[4][3];  // normal, tangent 1, tangent 2
};

// A pair of bodies' manifold as it was found, reused while the pair's relative pose stays near
// the pose it was found at (Jolt's body pair cache): that pose (B's centre and orientation in A's
// frame), the normal in A's frame, and each point's id and surface points in their own body's
// frame.
template <class T>
struct PairGeometryT {
  std::uint64_t key;
  T position[3], rotation[4];  // rotation: x, y, z, w
  T normal[3];
  int count;
  std::uint32_t id[4];
  T onA[4][3], onB[4][3];
};

// The broadphase's pairs kept from step to step (Box2D's fat boxes): each body's box grown by a
// tenth of its size, and the pairs of the grown boxes, A the body of the lower slot, in key order.
// While every body's box stays inside its grown one (and the bodies keep their slots), the
// pairs whose boxes overlap are among these, so a still pile skips the broadphase. The pairs
// found are the same either way: a cache of no state (not saved in snapshots).
struct BroadphaseCache {
  std::vector<Aabb> grown;
  std::vector<std::uint32_t> slots;  // each body's handle slot when the pairs were found
  std::vector<std::pair<std::uint64_t, Pair>> pairs;
};

// What a step leaves the next: the manifolds' impulses by (key, sub), and the pairs of bodies'
// manifolds by key.
template <class T>
struct ContactCacheT {
  std::vector<CachedManifoldT<T>> manifolds;
  std::vector<PairGeometryT<T>> pairs;
};
}  // namespace detail

enum class BodyShape : std::uint8_t { kSphere, kBox, kHull };
enum class ContactModel : std::uint8_t { kSoftStep, kBaumgarte, kProjection };
const char* toString(ContactModel model);

// What a body is made of when it is added.
struct BodyDef {
  BodyShape shape = BodyShape::kBox;
  Vec3f halfExtents{0.5f, 0.5f, 0.5f};  // a box's, m, each > 0
  float radius = 0.5f;                  // a sphere's, m, > 0
  // A hull's shape, shared by every body made of it. The body's position is the shape's centre of
  // mass and its orientation the shape's principal frame (rigid/hull.hpp).
  std::shared_ptr<const HullShape> hull;
  Vec3f position = Vec3f::Zero();
  Quatf orientation = Quatf::Identity();  // unit within 1e-3 (normalised on entry)
  Vec3f velocity = Vec3f::Zero();         // m/s
  Vec3f angularVelocity = Vec3f::Zero();  // rad/s, world frame
  float mass = 1.0f;                      // kg, > 0; ignored by a kinematic body
  // A kinematic body moves by its velocity alone: infinite mass, no gravity, pushed by nothing.
  bool kinematic = false;
  float friction = 0.6f;     // >= 0; a contact uses sqrt(fA fB) (Box2D's rule)
  float restitution = 0.0f;  // in [0, 1]; a contact uses the larger of the two
};

struct RigidSettings {
  ContactModel model = ContactModel::kSoftStep;
  Vec3f gravity{0.0f, -9.82f, 0.0f};
  // Per world step, in [1, 64]. Five (Box2D v3 and Box3D take four): at four, the 60 Hz contacts
  // below are at a quarter of the substep rate, where a box of 100 on a box of 1 jitters; at five
  // it rests, and W5's pyramids hold within Jolt's figures (docs/rigid.md).
  int substeps = 5;
  int iterations = 1;  // contact passes a substep (and relax passes, soft step), in [1, 256]
  // Soft step: the contact spring's frequency (Hz, capped at a quarter of the substep rate) and
  // damping ratio, and the fastest speed it pushes bodies apart at (m/s); static contacts are
  // twice as stiff. Box2D v3 uses 30 Hz; at 30 Hz a column of 20 unit boxes buckles (a soft
  // contact is a spring of the point's effective mass times (2 pi hertz)^2, too weak for the
  // column's weight: docs/rigid.md), at 60 it stands, and W5's pyramid sinks half as far.
  float contactHertz = 60.0f, contactDampingRatio = 10.0f, maxPushSpeed = 3.0f;
  float baumgarte = 0.2f;     // kBaumgarte: the fraction of the penetration removed a step, (0, 1]
  float projection = 0.45f;   // kProjection: the fraction moved apart a step (the book's), (0, 1]
  float linearSlop = 0.005f;  // m: penetration left uncorrected, so contacts persist
  float speculativeDistance = 0.02f;  // m: contacts are made this far before bodies touch
  float restitutionThreshold = 1.0f;  // m/s: slower impacts do not bounce
  float linearDamping = 0.0f, angularDamping = 0.0f;  // 1/s, >= 0
  bool warmStarting = true;
  // A pair of bodies whose relative pose has moved less than 10 um and 0.1 degree since its
  // manifold was found keeps that manifold, its points carried with the bodies and their
  // separations measured again (Jolt's body pair cache, with tighter bounds: docs/rigid.md): a
  // resting pile skips most box-box tests.
  bool reuseManifolds = true;
  // Sleeping (Box2D's): an island (bodies joined by contacts) whose bodies have all moved slower
  // than sleepSpeed (m/s, the angular speed times the body's reach counted too) for timeToSleep
  // (s) sleeps: it is neither solved nor moved, costs no contacts among its bodies, and wakes
  // when an awake body touches it, or when a body of it is set, pushed or removed.
  bool sleeping = true;
  float sleepSpeed = 0.05f, timeToSleep = 0.5f;
};

// Throws Error naming `where` and the field if a setting is out of range or not finite.
void validate(const RigidSettings& settings, const std::string& where);

// The rigid bodies of a world: dense streams (fields::Body), each body named by the handle add()
// returns for as long as it lives.
class RigidBodies : public StreamSet<fields::Body> {
 public:
  explicit RigidBodies(const RigidSettings& settings = {});

  const RigidSettings& settings() const { return settings_; }
  void setSettings(const RigidSettings& settings);  // throws Error, changing nothing, if invalid

  // Adds a body at index size(). Throws Error naming the body and the field if a value is not
  // finite or out of range, a dynamic body's mass is not > 0, a size is not > 0, or the
  // orientation is not a unit quaternion; nothing is added then.
  Handle add(const BodyDef& def);
  // Removes a body; the last one moves into its index. Throws Error if the handle is stale.
  void remove(Handle body);
  bool contains(Handle body) const { return handles_.contains(body); }
  std::uint32_t index(Handle body) const;
  Handle handle(std::uint32_t index) const { return handles_.handle(index); }

  Vec3f position(Handle body) const;
  Quatf orientation(Handle body) const;
  Vec3f velocity(Handle body) const;
  Vec3f angularVelocity(Handle body) const;
  bool kinematic(Handle body) const;
  bool asleep(Handle body) const;
  std::size_t awakeCount() const;
  // The body's shape where it is now.
  Obb box(Handle body) const;                                // throws Error if it is not a box
  Sphere sphere(Handle body) const;                          // throws Error if it is not a sphere
  std::shared_ptr<const HullShape> hull(Handle body) const;  // throws Error if not a hull
  // Each throws Error naming the call and the body if the handle is stale or the value invalid,
  // and changes nothing then.
  void setPosition(Handle body, const Vec3f& position);
  void setOrientation(Handle body, const Quatf& orientation);
  void setVelocity(Handle body, const Vec3f& velocity);
  void setAngularVelocity(Handle body, const Vec3f& angularVelocity);
  // An impulse (N s) at a point of the world: changes the velocities now.
  void applyImpulse(Handle body, const Vec3f& impulse, const Vec3f& point);
  // Held on the body in every step from now on (N, N m); zero removes them.
  void setForce(Handle body, const Vec3f& force);
  void setTorque(Handle body, const Vec3f& torque);

  // The streams (fields::Body), size() live elements each, read in place (no copy).
  std::span<const float> stream(std::size_t f) const { return field(f).view(); }

  // Positions, orientations and velocities (fields x .. wz) to write in place, as numpy views do
  // (docs/python.md): every body is woken, so a moved body is stepped. Check what was written with
  // checkFields() before stepping. Throws Error for other fields.
  std::span<float> writableField(std::size_t f);
  // Throws Error naming `where`, the body and the field if a position, orientation or velocity is
  // not finite or out of range, or an orientation is not a unit quaternion (within 1e-3; add()'s
  // rule); changes nothing.
  void checkFields(const std::string& where) const;

  // What the last step's contacts measured: the deepest penetration of any contact point when
  // the contacts were found (m, >= 0), and the manifolds and points made.
  float deepestPenetration() const { return deepest_; }
  std::size_t manifoldCount() const { return manifolds_; }
  std::size_t contactPointCount() const { return points_; }
  // The graph colours the last step's manifolds took (at most 24), and those no colour took
  // (solved one at a time).
  std::size_t colourCount() const { return colours_; }
  std::size_t overflowCount() const { return overflow_; }
  // The wall time the last step spent in the contact passes (warm start, solve, relax,
  // restitution): the share of a step the wide kernels take.
  double contactPassSeconds() const { return passSeconds_; }

  struct Internals;  // src/rigid/: the step's access to the streams and the contact cache

 private:
  friend struct Internals;
  friend struct detail::Snapshot;
  std::uint32_t require(Handle body, const char* where) const;
  Vec3f loadVec(std::size_t field, std::size_t i) const;
  void storeVec(std::size_t field, std::size_t i, const Vec3f& v);
  // Wakes body i's island, if asleep.
  void wake(std::uint32_t i);
  // A 3-vector field of a live body set to a finite, in-range value, waking it; else Error.
  void setVec(Handle body, const char* where, std::size_t field, const char* name,
              const Vec3f& value);

  RigidSettings settings_;
  HandleTable handles_;
  // The hull shapes bodies were made of, each once, named by the body's `hull` field; kept for
  // the life of the RigidBodies (a game has few shapes, shared by many bodies).
  std::vector<std::shared_ptr<const HullShape>> hulls_;
  detail::ContactCacheT<float> cache_;
  detail::BroadphaseCache broadphase_;
  float deepest_ = 0;
  std::size_t manifolds_ = 0, points_ = 0, colours_ = 0, overflow_ = 0;
  double passSeconds_ = 0;
};

}  // namespace simdphys

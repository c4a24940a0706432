// Springs and cloth (book chapter 16, the appendix's soft bodies): particles joined by springs,
// stepped by a World (world.hpp) against its static obstacles. A Cloth owns a fixed set of
// particles (indices stay as built) and the springs between them, in one of two layouts:
//  - a general spring network: springs coloured into batches that share no particle, each batch
//    solved lane-wide with per-particle indexed loads and stores;
//  - a grid (Cloth::grid): structural, shear and bend springs as shifted copies of the particle
//    grid, read with contiguous loads. It steps bit for bit as the network of the same springs
//    in the same batches (springs(), batchOf()) does.
//
// Two models, chosen per cloth (ClothSettings::model), each step of length dt split in substeps
// of h = dt / substeps; a particle of inverse mass w = 0 is pinned (never moved by a step):
//  - kXpbd: extended position-based dynamics with small steps (Macklin et al. 2019): predict
//    x' = x + h (v + h g), one Gauss-Seidel pass over the springs as distance constraints of
//    compliance 1 / stiffness (and Rayleigh damping), the tethers, the obstacles, then
//    v = (x' - x) / h. Unconditionally stable: stiffness kRigid is a rigid rod.
//  - kMassSpring: the book's Hooke springs with damping, F = (k (l - l0) + c dv.n) n, integrated
//    by semi-implicit Euler. Explicit integration is stable only for h below about
//    2 sqrt(m / k): the step raises the substeps to the bound for the stiffest spring, or, past
//    kMaxSubsteps, refuses with an Error that says so.
// Tethers (long-range attachments, as in Jolt's soft bodies and NvCloth): each free particle is
// kept within its straight rest distance of the pinned particle nearest along the rigid springs
// (soft springs may stretch, so they carry no tether), which bounds the stretch that a few
// substeps leave in a heavy cloth.
// Collision: each particle is kept `margin` outside every obstacle of the world (obstacles.hpp):
// planes, spheres, AABBs and OBBs, and two-sided triangle meshes (through each mesh's own BVH).
// The tests follow the path of the substep (a box's slabs, a mesh's raycast), so a fast particle
// does not pass through a thin box or a mesh; Coulomb friction acts at every contact. A cloth does
// not collide with itself or with other cloths.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys {

enum class ClothModel : std::uint8_t { kXpbd, kMassSpring };
const char* toString(ClothModel model);

// A stiffness that makes a spring a rigid rod (XPBD only: compliance 0).
inline constexpr float kRigid = std::numeric_limits<float>::infinity();

struct ClothSettings {
  ClothModel model = ClothModel::kXpbd;
  Vec3f gravity{0.0f, -9.82f, 0.0f};
  int substeps = 10;      // per world step, in [1, kMaxSubsteps]
  float damping = 0.0f;   // 1/s, >= 0: velocities lose this fraction a second (v *= 1 - damping h)
  float margin = 0.01f;   // m, in (0, 1]: the distance kept from obstacles' surfaces
  float friction = 0.3f;  // >= 0: Coulomb's coefficient against obstacles
  bool tethers = true;    // long-range attachments to the nearest pinned particle
  // Penalty springs (the appendix's contacts as springs; mass-spring model only): N/m, >= 0. A
  // particle within `margin` of a plane, sphere or box is pushed out by penalty * depth along
  // the surface's normal, and kept out of the true surface by the path test. 0: off, contacts
  // hold the particle `margin` off the surface.
  float penalty = 0.0f;
  static constexpr int kMaxSubsteps = 1000;
};

// Throws Error naming `where` and the field if a setting is out of range or not finite.
void validate(const ClothSettings& settings, const std::string& where);

// A spring between particles a and b: rest length (m, >= 0), stiffness (N/m, > 0, or kRigid)
// and damping (N s/m, >= 0) along the spring.
struct Spring {
  std::uint32_t a = 0, b = 0;
  float rest = 0.0f;
  float stiffness = kRigid;
  float damping = 0.0f;
};

// Stiffness and damping of one kind of a grid's springs.
struct SpringKindSettings {
  float stiffness = kRigid;
  float damping = 0.0f;
};

// A grid cloth: nx * nz particles, (i, j) at index j * nx + i, each joined to its neighbours by
// structural (i+1, j), (i, j+1), shear (i+1, j+1) and (i+1, j)-(i, j+1), and bend (i+2, j),
// (i, j+2) springs, at rest at the distance between the given positions.
struct ClothGrid {
  std::size_t nx = 0, nz = 0;  // >= 2 each
  std::vector<Vec3f> positions;
  std::vector<float> invMass;  // >= 0; 0 pins
  SpringKindSettings structural, shear, bend;
};

class Cloth {
 public:
  // A spring network over the particles. Each spring's batch is its colour: by default the
  // lowest that none of its particles' earlier springs has (greedy, in the order given); or the
  // batches given, one per spring, which must share no particle within a batch. Throws Error
  // naming the spring or particle if an index is out of range, a spring joins a particle to
  // itself, a value is negative, not finite or out of range, or given batches share a particle.
  Cloth(std::span<const Vec3f> positions, std::span<const float> invMass,
        std::span<const Spring> springs, const ClothSettings& settings = {},
        std::span<const std::uint32_t> batches = {});
  // A grid cloth (see ClothGrid); throws Error as above.
  static Cloth grid(const ClothGrid& grid, const ClothSettings& settings = {});

  const ClothSettings& settings() const { return settings_; }
  void setSettings(const ClothSettings& settings);  // throws Error, changing nothing, if invalid

  std::size_t size() const { return count_; }
  bool isGrid() const { return stride_ != 0; }
  // A grid's particles along x and along z (ClothGrid's nx and nz); 0 for a network.
  std::size_t gridColumns() const { return nx_; }
  std::size_t gridRows() const { return nz_; }
  Vec3f position(std::uint32_t particle) const;
  Vec3f velocity(std::uint32_t particle) const;
  float invMass(std::uint32_t particle) const;
  std::vector<Vec3f> positions() const;
  // Throws Error naming the particle if it is out of range or the value invalid.
  void setPosition(std::uint32_t particle, const Vec3f& position);
  void setVelocity(std::uint32_t particle, const Vec3f& velocity);

  // The springs in the order they are solved, batch after batch, and each one's batch.
  std::span<const Spring> springs() const { return springs_; }
  std::span<const std::uint32_t> batchOf() const { return batchOf_; }
  std::size_t batchCount() const { return batchBegin_.size() - 1; }

  // The particles' bounds, refitted by every step (and every set), for ray casts and culling.
  const Aabb& bounds() const { return bounds_; }
  // Picking: the particle nearest the ray's origin among those within `radius` of the ray (at
  // t in [0, maxT]), if any.
  std::optional<std::uint32_t> pick(const Ray& ray, float radius,
                                    float maxT = kMaxCoordinate) const;

  struct Internals;  // src/cloth/: the streams and layouts the step reads

 private:
  Cloth() = default;
  void build(std::span<const Vec3f> positions, std::span<const float> invMass,
             std::span<const std::uint32_t> batches);
  std::uint32_t slot(std::uint32_t particle, const char* where) const;
  void refit();

  friend struct Internals;
  friend struct detail::Snapshot;
  ClothSettings settings_;
  std::size_t count_ = 0;
  // Slot of particle (i, j) in a grid: j * stride_ + i (stride_ a multiple of kStreamPad, 0 for a
  // network, whose particle i is slot i).
  std::size_t stride_ = 0, nx_ = 0, nz_ = 0, slots_ = 0;
  // Streams over slots (padding slots: w = 0, never moved): x, y, z, vx, vy, vz, the substep's
  // start px, py, pz, inverse mass w, forces fx, fy, fz (mass-spring), anchors ax, ay, az
  // (core::ClothStreams).
  AlignedVector<float> s_[16];
  std::vector<Spring> springs_;  // in slot indices, batch after batch
  std::vector<std::uint32_t> batchOf_, batchBegin_;
  // Springs as SoA streams for the network kernels: a, b, then rest, compliance, stiffness,
  // damping as floats.
  AlignedVector<std::uint32_t> sa_, sb_;
  AlignedVector<float> sRest_, sCompliance_, sStiffness_, sDamping_;
  // Grid: per family (x+1, z+1, shear x+1 z+1, shear x-1 z+1, bend x+2, bend z+2) the rest length
  // of the spring from each slot (-1: none), and each kind's settings.
  AlignedVector<float> gridRest_[6];
  SpringKindSettings kinds_[3];
  // Tethers: per slot the anchor slot and the rest distance (-1: none).
  AlignedVector<std::uint32_t> anchor_;
  AlignedVector<float> tether_;
  AlignedVector<float> quads_;  // the network kernel's scratch: (x, y, z, w) a slot
  // The explicit model's stability bound (src/cloth/step.cpp): Gershgorin bounds of the largest
  // squared frequency and damping rate, infinite with a rigid spring.
  double rate2_ = 0, dampRate_ = 0, maxInvMass_ = 0;
  bool damped_ = false;  // some spring has damping
  Aabb bounds_;
};

}  // namespace simdphys

// Particles (book chapter 14): point masses in a structure-of-arrays stream, moved by one of four
// integrators under gravity, a force per particle and drag, and kept out of the world's static
// obstacles (obstacles.hpp) by a collision solved against the path each particle travels in a step,
// so none tunnels at any speed. A ParticleSystem lives in a World (world.hpp), which steps it.
//
// Per step of length dt, for a particle of inverse mass w > 0 (w = 0 pins it: it never moves, is
// never pushed and costs nothing but its lane), with the system's settings:
//   a = gravity + w * (force - drag * v)            (force: setForce, held until changed)
//   v <- damping * v                                 (the book's per-step velocity damping)
//   ExplicitEuler:     x' = x + v dt,                v' = v + a dt
//   SemiImplicitEuler: v' = v + a dt,                x' = x + v' dt
//   VelocityVerlet:    x' = x + v dt + a dt^2 / 2,   v' = v + (a + a') dt / 2, a' = a here
//   PositionVerlet:    x' = x + v dt + a dt^2,       v' = (x' - x) / dt
// PositionVerlet is the book's Verlet, x' = x + (x - p) + a dt^2, with the previous position p
// kept as the velocity v = (x - p) / dt, the mean over the last step, so that every system's
// streams hold velocities. In exact arithmetic it moves as SemiImplicitEuler does from the same
// state; it is second order when v is that mean (v(t - dt / 2)), as Verlet's start needs.
// With substeps, dt is the world's step over the substeps and damping its substeps-th root.
// Then the segment x -> x' is tested against every obstacle; the first surface it enters stops
// it there (see world.md: restitution, Coulomb friction, the skin, the bounce limit).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/stream_fields.hpp"

namespace simdphys {

namespace detail {
struct ParticleStreams;  // src/particles/step.hpp: the step's access to the streams
}

enum class Integrator : std::uint8_t {
  kExplicitEuler,      // first order; energy grows on oscillators
  kSemiImplicitEuler,  // first order, symplectic (the book's "Euler")
  kVelocityVerlet,     // second order, symplectic; exact for constant forces
  kPositionVerlet,     // the book's Verlet: second order in positions, symplectic
};

const char* toString(Integrator integrator);

struct ParticleSettings {
  Integrator integrator = Integrator::kVelocityVerlet;
  Vec3f gravity{0.0f, -9.82f, 0.0f};
  float damping = 1.0f;      // velocity factor per world step, in (0, 1]; the book uses 0.95
  float drag = 0.0f;         // linear drag coefficient (N s / m), >= 0
  float restitution = 0.5f;  // in [0, 1]: the normal speed kept by a bounce
  float friction = 0.0f;     // >= 0: Coulomb's coefficient against obstacles
  // Normal speeds below this bounce with no restitution, so resting particles rest (Box2D's
  // restitution threshold); m/s, >= 0.
  float restitutionThreshold = 1.0f;
  // Contacts leave a particle this far outside the surface it hit (m, > 0): the book's 0.003,
  // smaller so that resting particles touch the surface each step.
  float skin = 1e-3f;
  // Surfaces met in one step beyond this many leave the particle at the last contact, its
  // remaining motion dropped (counted in the profile): > 0.
  int maxBounces = 4;
};

// Throws Error naming `where` and the field if a setting is out of its range or not finite.
void validate(const ParticleSettings& settings, const std::string& where);

// The particles of one system: dense streams (x, y, z, vx, vy, vz, inverse mass, force), each
// element named by the handle add() returns for as long as it lives.
class ParticleSystem : public StreamSet<fields::Particle> {
 public:
  explicit ParticleSystem(const ParticleSettings& settings = {});

  const ParticleSettings& settings() const { return settings_; }
  // Throws Error (and changes nothing) if `settings` is invalid.
  void setSettings(const ParticleSettings& settings);

  // Adds a particle at index size(). Throws Error naming the call and the particle if a value is
  // not finite or out of range (math.hpp), or invMass < 0.
  Handle add(const Vec3f& position, const Vec3f& velocity = Vec3f::Zero(), float invMass = 1.0f);
  // Removes a particle; the last one moves into its index. Throws Error if the handle is stale.
  void remove(Handle particle);
  bool contains(Handle particle) const { return handles_.contains(particle); }
  std::uint32_t index(Handle particle) const;
  Handle handle(std::uint32_t index) const;

  Vec3f position(Handle particle) const;
  Vec3f velocity(Handle particle) const;
  // The force on the particle in every step from now on (N); zero removes it.
  void setForce(Handle particle, const Vec3f& force);
  void setPosition(Handle particle, const Vec3f& position);
  void setVelocity(Handle particle, const Vec3f& velocity);

  // The streams, size() live elements each, read in place (no copy).
  std::span<const float> x() const { return field(fields::Particle::x).view(); }
  std::span<const float> y() const { return field(fields::Particle::y).view(); }
  std::span<const float> z() const { return field(fields::Particle::z).view(); }
  std::span<const float> vx() const { return field(fields::Particle::vx).view(); }
  std::span<const float> vy() const { return field(fields::Particle::vy).view(); }
  std::span<const float> vz() const { return field(fields::Particle::vz).view(); }
  std::span<const float> invMass() const { return field(fields::Particle::invMass).view(); }

  // Positions and velocities (fields x .. vz) to write in place, as numpy views do
  // (docs/python.md): the next step no longer assumes that every particle is outside the
  // obstacles. Check what was written with checkFields() before stepping. Throws Error for other
  // fields (inverse mass and forces go through their setters).
  std::span<float> writableField(std::size_t f);
  // Throws Error naming `where`, the particle and the field if a position or velocity is not
  // finite or out of range (math.hpp); changes nothing.
  void checkFields(const std::string& where) const;

  // True once a non-zero force was set: the step reads the force fields only then.
  bool hasForces() const { return hasForces_; }

 private:
  friend struct detail::ParticleStreams;
  friend struct detail::Snapshot;
  std::uint32_t require(Handle particle, const char* where) const;
  void storeVec(std::size_t field, std::size_t i, const Vec3f& v);
  Vec3f loadVec(std::size_t field, std::size_t i) const;

  ParticleSettings settings_;
  HandleTable handles_;
  bool hasForces_ = false;
  // The Obstacles::version() that the last step left every particle outside of (none strictly
  // inside an obstacle), 0 if unknown: a step then need not look for particles inside first.
  std::uint64_t outsideOf_ = 0;
};

}  // namespace simdphys

// The world: it owns the static obstacles (obstacles.hpp), the particle systems
// (particles.hpp), cloths (cloth.hpp) and rigid bodies (rigid.hpp), and steps them at a fixed rate
// through a pipeline of stages. A stage whose streams are empty costs nothing: a world of particles
// runs no broadphase, no narrowphase and no solver.
//
// Steps are deterministic: a stage's elements are split into fixed partitions, run in parallel
// with OpenMP, and nothing depends on which thread ran which partition, so the state after a step
// is bitwise the same at any thread count (on a given path).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "simdphys/cloth.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/obstacles.hpp"
#include "simdphys/particles.hpp"
#include "simdphys/rigid.hpp"

namespace simdphys {

struct WorldSettings {
  float timeStep = 1.0f / 60.0f;  // s, > 0: one step()
  int substeps = 1;               // >= 1: each step runs the stages this many times, dt / substeps
  // OpenMP threads for the parallel stages; 0 uses OpenMP's default. Results do not depend on it.
  int threads = 0;
};

// Throws Error naming `where` and the field if a setting is out of range.
void validate(const WorldSettings& settings, const char* where);

// What one stage did in the last step: wall time and the elements it processed (summed over the
// substeps).
struct StageProfile {
  double seconds = 0;
  std::size_t elements = 0;
};

// The last step, stage by stage (Box2D's b2Profile, Jolt's profile samples), and what the
// particles met.
struct StepProfile {
  StageProfile particles;           // forces, integration and obstacle collision, fused in one pass
  StageProfile cloth;               // every cloth's substeps; elements: spring updates
  StageProfile bodies;              // contacts and solver; elements: body steps
  double seconds = 0;               // the whole step
  std::uint64_t contacts = 0;       // surfaces met (bounces, slides, rests)
  std::uint64_t pushedOut = 0;      // particles found inside an obstacle and pushed out
  std::uint64_t bounceLimited = 0;  // particles stopped at ParticleSettings::maxBounces
  std::uint64_t outOfRange = 0;     // particles not moved: the step would take them past ±1e18
};

class World {
 public:
  // Throws Error if the settings are invalid.
  explicit World(const WorldSettings& settings = {});

  const WorldSettings& settings() const { return settings_; }
  void setSettings(const WorldSettings& settings);

  Obstacles& obstacles() { return obstacles_; }
  const Obstacles& obstacles() const { return obstacles_; }

  // Particle systems, each with its own settings and streams. Throws Error if settings are
  // invalid.
  Handle addParticles(const ParticleSettings& settings = {});
  void removeParticles(Handle system);
  ParticleSystem& particles(Handle system);
  const ParticleSystem& particles(Handle system) const;
  std::size_t particleSystemCount() const { return systems_.size(); }
  // The system at index i < particleSystemCount() (systems in the order they were added, the last
  // moved into a removed one's place).
  Handle particleSystemHandle(std::size_t i) const {
    return systemHandles_.handle(std::uint32_t(i));
  }

  // Cloths, each with its own particles, springs and settings (cloth.hpp).
  Handle addCloth(Cloth cloth);
  void removeCloth(Handle cloth);
  Cloth& cloth(Handle cloth);
  const Cloth& cloth(Handle cloth) const;
  std::size_t clothCount() const { return cloths_.size(); }
  Handle clothHandle(std::size_t i) const { return clothHandles_.handle(std::uint32_t(i)); }

  // The rigid bodies, with their own settings (rigid.hpp).
  RigidBodies& bodies() { return bodies_; }
  const RigidBodies& bodies() const { return bodies_; }

  // Advances the world by settings().timeStep. On an error nothing has moved.
  void step();
  const StepProfile& profile() const { return profile_; }

 private:
  WorldSettings settings_;
  friend struct detail::Snapshot;
  Obstacles obstacles_;
  std::vector<ParticleSystem> systems_;
  HandleTable systemHandles_;
  std::vector<Cloth> cloths_;
  HandleTable clothHandles_;
  RigidBodies bodies_;
  StepProfile profile_;
};

}  // namespace simdphys

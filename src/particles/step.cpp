// Stepping a particle system on the active path (step.hpp).
#include "src/particles/step.hpp"

#include <omp.h>

#include "simd/kernels.hpp"
#include "src/core/on_path.hpp"
#include "src/reference/particles/step-inl.hpp"
#include "src/world/obstacle_rows.hpp"

namespace simdphys::detail {

namespace F = fields;

static_assert(
    std::uint32_t(Integrator::kExplicitEuler) == core::ParticleStepParams::kExplicitEuler &&
    std::uint32_t(Integrator::kSemiImplicitEuler) == core::ParticleStepParams::kSemiImplicitEuler &&
    std::uint32_t(Integrator::kVelocityVerlet) == core::ParticleStepParams::kVelocityVerlet &&
    std::uint32_t(Integrator::kPositionVerlet) == core::ParticleStepParams::kPositionVerlet);

core::View<F::Particle, float> ParticleStreams::view(ParticleSystem& s) {
  core::View<F::Particle, float> v{{}, s.size(), s.padded()};
  for (std::size_t f = 0; f < F::Particle::kCount; ++f) v.field[f] = s.paddedData(f);
  return v;
}

reference::ObstacleSetT<float> obstacleSet(const Obstacles& o) {
  return reference::ObstacleSetT<float>(o.shapes(), o.tree(), o.bounded(), o.boxes(), o.planes());
}

core::ParticleStepParams stepParams(const ParticleSystem& system, float dt, float damping) {
  const ParticleSettings& s = system.settings();
  core::ParticleStepParams params{};
  params.integrator = std::uint32_t(s.integrator);
  for (int k = 0; k < 3; ++k) params.gravity[k] = s.gravity[k];
  params.dt = dt, params.damping = damping, params.drag = s.drag;
  params.restitution = s.restitution, params.friction = s.friction;
  params.threshold = s.restitutionThreshold, params.skin = s.skin;
  params.limit = kMaxCoordinate;
  params.maxBounces = s.maxBounces;
  params.forces = system.hasForces() || s.drag != 0;
  return params;
}

namespace {

// Particles per partition: a multiple of every lane count, large enough that a partition's
// scheduling costs little against its work, small enough that 100,000 particles split evenly.
constexpr std::size_t kPartition = 4096;

core::ParticleCounts referenceRange(const core::View<F::Particle, float>& v, std::size_t begin,
                                    std::size_t end, const reference::ObstacleSetT<float>& shapes,
                                    const core::ParticleStepParams& params) {
  const reference::ParticleStep<float> p = reference::particleStep<float>(params);
  core::ParticleCounts counts;
  const auto load = [&](std::size_t f, std::size_t i) {
    return Vec3f(v[f][i], v[f + 1][i], v[f + 2][i]);
  };
  for (std::size_t i = begin; i < end; ++i) {
    Vec3f x = load(F::Particle::x, i), vel = load(F::Particle::vx, i);
    reference::stepParticle<float>(p, shapes, x, vel, v[F::Particle::invMass][i],
                                   load(F::Particle::fx, i), counts);
    for (int k = 0; k < 3; ++k) v[F::Particle::x + k][i] = x[k], v[F::Particle::vx + k][i] = vel[k];
  }
  return counts;
}

}  // namespace

core::ParticleCounts stepParticles(ParticleSystem& system, const Obstacles& obstacles,
                                   std::span<const core::ObstacleRow> rows, float dt, float damping,
                                   int threads) {
  core::ParticleStepParams params = stepParams(system, dt, damping);
  std::uint64_t& outsideOf = ParticleStreams::outsideOf(system);
  params.pushOutFirst = outsideOf != obstacles.version();

  const core::View<F::Particle, float> v = ParticleStreams::view(system);
  const reference::ObstacleSetT<float> set = obstacleSet(obstacles);
  const std::size_t parts = (v.count + kPartition - 1) / kPartition;
  std::vector<core::ParticleCounts> counts(parts);
  // The path is read once, before the threads start. plainLoopsActive: the benchmarks' and
  // tests' second baseline.
  const bool reference = referencePathActive();
  const auto& kernel = plainLoopsActive() ? simd::stepParticlesAutovec : simd::stepParticles;
  const std::optional<core::ObstacleQueries> queries = obstacleQueries(obstacles);
  const auto run = [&](std::size_t part) {
    const std::size_t begin = part * kPartition, end = std::min(v.count, begin + kPartition);
    counts[part] = reference ? referenceRange(v, begin, end, set, params)
                             : kernel(v, begin, end, rows.data(), rows.size(),
                                      queries ? &*queries : nullptr, params);
  };
  if (parts > 1) {
    const int t = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(t)
    for (std::size_t part = 0; part < parts; ++part) run(part);
  } else if (parts == 1) {
    run(0);
  }
  core::ParticleCounts total;
  for (const core::ParticleCounts& c : counts) total += c;
  // A particle pushed at the end may have been pushed into an obstacle tested before.
  outsideOf = total.endPushed == 0 ? obstacles.version() : 0;
  return total;
}

}  // namespace simdphys::detail

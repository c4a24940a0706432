// ParticleSystem (particles.hpp): its settings, its particles as dense streams behind handles.
#include <cmath>
#include <string>

#include "simdphys/particles.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

namespace F = fields;

const char* toString(Integrator integrator) {
  switch (integrator) {
    case Integrator::kExplicitEuler:
      return "explicit Euler";
    case Integrator::kSemiImplicitEuler:
      return "semi-implicit Euler";
    case Integrator::kVelocityVerlet:
      return "velocity Verlet";
    case Integrator::kPositionVerlet:
      return "position Verlet";
  }
  return "unknown integrator";
}

void validate(const ParticleSettings& s, const std::string& where) {
  using detail::require;
  const auto i = static_cast<unsigned>(s.integrator);
  require(i <= unsigned(Integrator::kPositionVerlet), i, where, "integrator", "not an Integrator");
  detail::requireFiniteField(s.gravity, where, "gravity");
  require(s.damping > 0 && s.damping <= 1, s.damping, where, "damping", "must be in (0, 1]");
  require(s.drag >= 0 && std::isfinite(s.drag), s.drag, where, "drag", "must be finite and >= 0");
  require(s.restitution >= 0 && s.restitution <= 1, s.restitution, where, "restitution",
          "must be in [0, 1]");
  require(s.friction >= 0 && std::isfinite(s.friction), s.friction, where, "friction",
          "must be finite and >= 0");
  require(s.restitutionThreshold >= 0 && std::isfinite(s.restitutionThreshold),
          s.restitutionThreshold, where, "restitutionThreshold", "must be finite and >= 0");
  require(s.skin > 0 && s.skin <= 1, s.skin, where, "skin", "must be in (0, 1] m");
  require(s.maxBounces > 0 && s.maxBounces <= 64, s.maxBounces, where, "maxBounces",
          "must be in [1, 64]");
}

ParticleSystem::ParticleSystem(const ParticleSettings& settings) {
  validate(settings, "ParticleSystem");
  settings_ = settings;
}

void ParticleSystem::setSettings(const ParticleSettings& settings) {
  validate(settings, "ParticleSystem::setSettings");
  settings_ = settings;
}

std::uint32_t ParticleSystem::require(Handle h, const char* where) const {
  return handles_.index(h, where, "particle");
}

std::uint32_t ParticleSystem::index(Handle h) const { return require(h, "ParticleSystem::index"); }

Handle ParticleSystem::handle(std::uint32_t i) const {
  detail::requireIndex(i, size(), "ParticleSystem::handle");
  return handles_.handle(i);
}

void ParticleSystem::storeVec(std::size_t f, std::size_t i, const Vec3f& v) {
  for (int k = 0; k < 3; ++k) writable(f + k)[i] = v[k];
}

Vec3f ParticleSystem::loadVec(std::size_t f, std::size_t i) const {
  return {value(f, i), value(f + 1, i), value(f + 2, i)};
}

Handle ParticleSystem::add(const Vec3f& position, const Vec3f& velocity, float invMass) {
  const std::string where = detail::at("ParticleSystem::add", size());
  detail::requireFiniteField(position, where, "position");
  detail::requireFiniteField(velocity, where, "velocity");
  detail::require(invMass >= 0 && invMass <= kMaxCoordinate, invMass, where, "invMass",
                  "must be in [0, 1e18] (0 pins the particle)");
  std::array<float, F::Particle::kCount> values{};
  for (int k = 0; k < 3; ++k) values[F::Particle::x + k] = position[k];
  for (int k = 0; k < 3; ++k) values[F::Particle::vx + k] = velocity[k];
  values[F::Particle::invMass] = invMass;
  append(values);
  outsideOf_ = 0;
  return handles_.add();
}

void ParticleSystem::remove(Handle h) {
  eraseSwap(handles_.remove(h, "ParticleSystem::remove", "particle"));
}

std::span<float> ParticleSystem::writableField(std::size_t f) {
  if (f > F::Particle::vz)
    throw Error("ParticleSystem::writableField: field " + std::to_string(f) +
                " is not a position or velocity");
  outsideOf_ = 0;  // a written position may lie inside an obstacle
  return writable(f);
}

void ParticleSystem::checkFields(const std::string& where) const {
  static constexpr const char* kNames[] = {"x", "y", "z", "vx", "vy", "vz"};  // fields x .. vz
  requireInRange(kNames, where, "particle");
}

Vec3f ParticleSystem::position(Handle h) const {
  return loadVec(F::Particle::x, require(h, "ParticleSystem::position"));
}

Vec3f ParticleSystem::velocity(Handle h) const {
  return loadVec(F::Particle::vx, require(h, "ParticleSystem::velocity"));
}

void ParticleSystem::setPosition(Handle h, const Vec3f& position) {
  const std::uint32_t i = require(h, "ParticleSystem::setPosition");
  detail::requireFiniteField(position, detail::at("ParticleSystem::setPosition", i), "position");
  storeVec(F::Particle::x, i, position);
  outsideOf_ = 0;
}

void ParticleSystem::setVelocity(Handle h, const Vec3f& velocity) {
  const std::uint32_t i = require(h, "ParticleSystem::setVelocity");
  detail::requireFiniteField(velocity, detail::at("ParticleSystem::setVelocity", i), "velocity");
  storeVec(F::Particle::vx, i, velocity);
}

void ParticleSystem::setForce(Handle h, const Vec3f& force) {
  const std::uint32_t i = require(h, "ParticleSystem::setForce");
  detail::requireFiniteField(force, detail::at("ParticleSystem::setForce", i), "force");
  storeVec(F::Particle::fx, i, force);
  if (!force.isZero(0)) hasForces_ = true;
}

}  // namespace simdphys

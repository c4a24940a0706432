// SpringBodyBuilder (spring_bodies.hpp): joints and spring bodies as springs of a Cloth. Each call
// checks all of its input before it adds anything, so an Error leaves the builder unchanged.
#include "simdphys/spring_bodies.hpp"

#include <cmath>
#include <span>
#include <vector>

#include "src/reference/validate-inl.hpp"

namespace simdphys {

namespace {

using detail::require;

void requireParticle(std::uint32_t i, std::size_t count, const char* where, const char* field) {
  require(i < count, i, where, field, "is not a particle index");
}

void requireInvMass(float w, const char* where, const char* field) {
  detail::requireInRange(w, where, field);
  require(w >= 0, w, where, field, "must be >= 0");
}

// A spring's stiffness (> 0 and in range, or kRigid) and damping (>= 0 and in range).
void requireSpringValues(float stiffness, float damping, const char* where) {
  require(stiffness == kRigid || (stiffness > 0 && detail::inSupportedRange(stiffness)), stiffness,
          where, "stiffness", "must be > 0 and finite (or kRigid)");
  detail::requireInRange(damping, where, "damping");
  require(damping >= 0, damping, where, "damping", "must be >= 0");
}

// The two ends of a spring: particles, not the same one.
void requireEnds(std::uint32_t a, std::uint32_t b, std::size_t count, const char* where,
                 const char* fieldA = "a", const char* fieldB = "b") {
  requireParticle(a, count, where, fieldA);
  requireParticle(b, count, where, fieldB);
  require(a != b, b, where, fieldB, "joins the particle to itself");
}

// |q - p|, taken in double and rounded once.
float restLength(const Vec3f& p, const Vec3f& q) {
  return float((q.cast<double>() - p.cast<double>()).norm());
}

// A spring from a to b at rest at their distance, checked as `where`: its index.
std::uint32_t addChecked(std::vector<Spring>& springs, std::span<const Vec3f> x, std::uint32_t a,
                         std::uint32_t b, float stiffness, float damping, const char* where) {
  requireEnds(a, b, x.size(), where);
  requireSpringValues(stiffness, damping, where);
  const float rest = restLength(x[a], x[b]);
  detail::requireInRange(rest, where, "the distance from a to b");
  springs.push_back({a, b, rest, stiffness, damping});
  return std::uint32_t(springs.size() - 1);
}

}  // namespace

std::uint32_t SpringBodyBuilder::addParticle(const Vec3f& position, float invMass) {
  constexpr const char* where = "SpringBodyBuilder::addParticle";
  detail::requireFiniteField(position, where, "position");
  requireInvMass(invMass, where, "invMass");
  positions_.push_back(position);
  invMass_.push_back(invMass);
  return std::uint32_t(positions_.size() - 1);
}

void SpringBodyBuilder::setInvMass(std::uint32_t particle, float invMass) {
  constexpr const char* where = "SpringBodyBuilder::setInvMass";
  requireParticle(particle, size(), where, "particle");
  requireInvMass(invMass, where, "invMass");
  invMass_[particle] = invMass;
}

std::uint32_t SpringBodyBuilder::addSpring(std::uint32_t a, std::uint32_t b, float stiffness,
                                           float damping) {
  return addChecked(springs_, positions_, a, b, stiffness, damping, "SpringBodyBuilder::addSpring");
}

std::uint32_t SpringBodyBuilder::distanceJoint(std::uint32_t a, std::uint32_t b, float stiffness,
                                               float damping) {
  return addChecked(springs_, positions_, a, b, stiffness, damping,
                    "SpringBodyBuilder::distanceJoint");
}

std::uint32_t SpringBodyBuilder::ballJoint(std::uint32_t a, std::uint32_t b, float stiffness,
                                           float damping) {
  constexpr const char* where = "SpringBodyBuilder::ballJoint";
  requireEnds(a, b, size(), where);
  requireSpringValues(stiffness, damping, where);
  springs_.push_back({a, b, 0.0f, stiffness, damping});
  return std::uint32_t(springs_.size() - 1);
}

std::uint32_t SpringBodyBuilder::hinge(std::uint32_t a0, std::uint32_t b0, std::uint32_t a1,
                                       std::uint32_t b1, float stiffness, float damping) {
  constexpr const char* where = "SpringBodyBuilder::hinge";
  requireEnds(a0, b0, size(), where, "a0", "b0");
  requireEnds(a1, b1, size(), where, "a1", "b1");
  // One pivot is a ball joint, not a hinge: each body needs two.
  require(a1 != a0, a1, where, "a1", "is a0: a hinge needs two pivots on each body");
  require(b1 != b0, b1, where, "b1", "is b0: a hinge needs two pivots on each body");
  requireSpringValues(stiffness, damping, where);
  const std::uint32_t first = ballJoint(a0, b0, stiffness, damping);
  ballJoint(a1, b1, stiffness, damping);
  return first;
}

std::uint32_t SpringBodyBuilder::chain(const Vec3f& start, const Vec3f& end, int links,
                                       float invMassPerParticle, float stiffness, float damping) {
  constexpr const char* where = "SpringBodyBuilder::chain";
  detail::requireFiniteField(start, where, "start");
  detail::requireFiniteField(end, where, "end");
  require(links >= 1, links, where, "links", "must be >= 1");
  requireInvMass(invMassPerParticle, where, "invMassPerParticle");
  requireSpringValues(stiffness, damping, where);
  const Vec3d from = start.cast<double>(), step = (end.cast<double>() - from) / double(links);
  detail::requireInRange(step.norm(), where, "the length of a link");
  const auto first = std::uint32_t(size());
  for (int i = 0; i <= links; ++i) {
    positions_.push_back((from + double(i) * step).cast<float>());
    invMass_.push_back(invMassPerParticle);
    const auto p = first + std::uint32_t(i);
    if (i > 0)
      springs_.push_back(
          {p - 1, p, restLength(positions_[p - 1], positions_[p]), stiffness, damping});
  }
  return first;
}

std::uint32_t SpringBodyBuilder::jellyCube(const Vec3f& centre, float edge,
                                           float invMassPerParticle, float stiffness,
                                           float damping) {
  constexpr const char* where = "SpringBodyBuilder::jellyCube";
  detail::requireFiniteField(centre, where, "centre");
  detail::requireInRange(edge, where, "edge");
  require(edge > 0, edge, where, "edge", "must be > 0");
  detail::requireReachInRange(centre, Vec3f::Constant(edge / 2), where, "centre +- edge / 2");
  requireInvMass(invMassPerParticle, where, "invMassPerParticle");
  requireSpringValues(stiffness, damping, where);
  detail::requireInRange(double(edge) * std::sqrt(3.0), where, "the body diagonal edge sqrt(3)");
  const auto first = std::uint32_t(size());
  for (int c = 0; c < 8; ++c) {
    const Vec3f corner(float(2 * (c & 1) - 1), float((c & 2) - 1), float((c & 4) / 2 - 1));
    positions_.push_back(centre + corner * (edge / 2));
    invMass_.push_back(invMassPerParticle);
  }
  for (std::uint32_t p = first; p < first + 8; ++p)
    for (std::uint32_t q = p + 1; q < first + 8; ++q)
      springs_.push_back({p, q, restLength(positions_[p], positions_[q]), stiffness, damping});
  return first;
}

Cloth SpringBodyBuilder::build(const ClothSettings& settings) const {
  return Cloth(positions_, invMass_, springs_, settings);
}

}  // namespace simdphys

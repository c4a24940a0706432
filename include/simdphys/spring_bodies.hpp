// Spring bodies and joints (book chapter 16's joints, the appendix's jelly cube): a builder that
// collects particles and the springs between them and builds a Cloth (cloth.hpp), the one type of
// every spring network, for a World to step. Every joint here is a distance constraint or two,
// solved by the cloth's model like any other spring:
//  - a distance joint holds two particles at the distance they are built at: a rigid rod with
//    kRigid (XPBD only), a Hooke spring with a stiffness (N/m);
//  - a ball joint holds two particles together (rest length 0): two particle bodies, each made
//    rigid by its own springs, that share the pivot turn freely about it (a soft ball joint, of
//    a stiffness, lets the pivots part by force / stiffness);
//  - a hinge is two ball joints: two bodies joined at two pivots turn only about the axis through
//    them (the book's hinge from distance joints);
//  - a chain is a line of particles, each joined to the next;
//  - the jelly cube is the appendix's soft body: 8 corner particles with a spring between every
//    pair (28: 12 edges, 12 face diagonals, 4 body diagonals), a rigid box with kRigid.
// A Cloth's tethers (ClothSettings::tethers, on by default) keep each particle within its rest
// distance along the springs from the nearest pin, so they stop a soft joint on such a path from
// stretching: turn them off for soft joints that hang from pins.
// Rest lengths are the distances between the particles' positions when the spring is added
// (taken in double, rounded once). Every method checks its input and throws Error naming the call
// and the value, leaving the builder unchanged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/cloth.hpp"
#include "simdphys/core.hpp"

namespace simdphys {

class SpringBodyBuilder {
 public:
  // A particle at `position` of inverse mass `invMass` (1/kg, >= 0; 0 pins it): its index.
  std::uint32_t addParticle(const Vec3f& position, float invMass);
  // Changes a particle's inverse mass (0 pins it, e.g. the first particle of a chain).
  void setInvMass(std::uint32_t particle, float invMass);

  // A spring from a to b (a != b) at rest at their current distance, of stiffness N/m (> 0, or
  // kRigid) and damping N s/m (>= 0) along it: its index in springs().
  std::uint32_t addSpring(std::uint32_t a, std::uint32_t b, float stiffness = kRigid,
                          float damping = 0.0f);
  // The book's distance joint: the same spring, rigid with kRigid, soft with a stiffness.
  std::uint32_t distanceJoint(std::uint32_t a, std::uint32_t b, float stiffness = kRigid,
                              float damping = 0.0f);
  // A ball joint: a spring of rest length 0 that holds a and b together (particles built apart
  // are pulled together by the first steps), rigid with kRigid. Its index in springs().
  std::uint32_t ballJoint(std::uint32_t a, std::uint32_t b, float stiffness = kRigid,
                          float damping = 0.0f);
  // A hinge: ball joints a0-b0 and a1-b1 (a0 and a1 on one body, b0 and b1 on the other, the
  // pivots apart), so the bodies turn only about the axis through the pivots. The first joint's
  // index; the second's follows it.
  std::uint32_t hinge(std::uint32_t a0, std::uint32_t b0, std::uint32_t a1, std::uint32_t b1,
                      float stiffness = kRigid, float damping = 0.0f);

  // A chain of links >= 1 equal links from start to end: links + 1 particles evenly spaced, each
  // of inverse mass invMassPerParticle, joined in order by springs of the given stiffness and
  // damping. Its first particle's index; the others follow it in order.
  std::uint32_t chain(const Vec3f& start, const Vec3f& end, int links, float invMassPerParticle,
                      float stiffness = kRigid, float damping = 0.0f);
  // The jelly cube: an axis-aligned cube of the given edge (m, > 0) about centre, its corners
  // particles of inverse mass invMassPerParticle, corner first + (i + 2 j + 4 k) at
  // centre + edge / 2 (2i - 1, 2j - 1, 2k - 1), and a spring of the given stiffness and damping
  // between every pair of corners, in order (0, 1), (0, 2) ... (6, 7). Its first corner's index.
  std::uint32_t jellyCube(const Vec3f& centre, float edge, float invMassPerParticle,
                          float stiffness = kRigid, float damping = 0.0f);

  std::size_t size() const { return positions_.size(); }
  std::span<const Vec3f> positions() const { return positions_; }
  std::span<const float> invMasses() const { return invMass_; }
  std::span<const Spring> springs() const { return springs_; }

  // The particles and springs as a Cloth (a general network, springs coloured in the order
  // added) with the given settings; throws Error if the settings are invalid.
  Cloth build(const ClothSettings& settings = {}) const;

 private:
  std::vector<Vec3f> positions_;
  std::vector<float> invMass_;
  std::vector<Spring> springs_;
};

}  // namespace simdphys

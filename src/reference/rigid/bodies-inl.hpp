// The rigid-body step's vocabulary on Eigen, templated on the scalar: float for the reference
// path, double for the truth the fast paths are measured against (rigid.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "simdphys/rigid.hpp"
#include "simdphys/rigid/manifold.hpp"

namespace simdphys::detail {

// A body as the step reads and writes it.
template <class T>
struct BodyT {
  Vec3<T> x, v, w;  // position, velocity, angular velocity (world)
  Quat<T> q;
  T invMass;
  Vec3<T> invInertia;  // about the body's own axes
  BodyShape shape;
  Vec3<T> half;  // box half extents; half.x() is a sphere's radius; a hull's shape's extents
  const HullShape* hull = nullptr;  // a hull's shape
  T friction, restitution;
  Vec3<T> force, torque;
  T sleepTime;
  std::uint32_t island;  // while asleep, its island's id + 1; 0 awake

  ObbT<T> box() const { return {x, half, q.toRotationMatrix()}; }
  SphereT<T> sphere() const { return {x, half.x()}; }
  PlacedHullT<T> placedHull() const { return {hull, x, q.toRotationMatrix()}; }
};

// A body as the solver moves it within a step (Box2D v3's b2BodyState): velocities, and the
// motion since the step's start as a translation and a rotation, so contact separations are
// updated from the step's anchors without recomputing manifolds.
template <class T>
struct SolverBodyT {
  Vec3<T> v = Vec3<T>::Zero(), w = Vec3<T>::Zero();
  Vec3<T> dp = Vec3<T>::Zero();
  Quat<T> dq = Quat<T>::Identity();
  T invMass = 0;
  Mat3<T> invInertia = Mat3<T>::Zero();  // world frame, fixed for the step
};

template <class T>
struct ContactPointConstraintT {
  Vec3<T> rA = Vec3<T>::Zero(), rB = Vec3<T>::Zero();  // anchors from the bodies' centres
  T baseSeparation = 0;                                // at the step's start
  T normalMass = 0, tangentMass[2] = {0, 0};
  T normalImpulse = 0, tangentImpulse[2] = {0, 0}, maxNormalImpulse = 0;
  T relativeVelocity = 0;  // normal velocity at the step's start, for restitution
  std::uint32_t id = 0;
};

// A manifold as the solver holds it: bodies a and b (b is the static dummy for an obstacle).
template <class T>
struct ContactConstraintT {
  std::uint32_t a, b;
  std::uint64_t key;  // the pair's, for warm starting
  std::uint32_t sub;  // which of the pair's manifolds (a mesh's: its lowest triangle id), else 0
  Vec3<T> normal, tangent[2];
  T friction, restitution;
  bool isStatic;  // against an obstacle (solved with stiffer softness, after the others)
  int count;
  std::array<ContactPointConstraintT<T>, 4> points;
};

// Two unit vectors completing the normal to a right-handed basis, a function of the normal
// alone, so a resting contact's tangents (and warm-started friction) stay put between steps.
template <class T>
void tangentsOf(const Vec3<T>& n, Vec3<T> t[2]) {
  t[0] = std::abs(n.x()) > std::abs(n.y()) ? Vec3<T>(n.z(), 0, -n.x()) : Vec3<T>(0, n.z(), -n.y());
  t[0].normalize();
  t[1] = n.cross(t[0]);
}

}  // namespace simdphys::detail

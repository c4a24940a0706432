// The contact solver of rigid.hpp on Eigen, one contact at a time in the order given: the scalar
// reference the wide kernel is tested against, in float, and the truth in double.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "src/reference/rigid/bodies-inl.hpp"

namespace simdphys::detail {

// Box2D v3's soft constraint coefficients (b2MakeSoft) for a spring of `hertz` and damping ratio
// zeta over a substep h.
template <class T>
struct Softness {
  T biasRate = 0, massScale = 1, impulseScale = 0;
  Softness() = default;
  Softness(T hertz, T zeta, T h) {
    const T omega = T(2 * 3.14159265358979323846) * hertz;
    const T a1 = 2 * zeta + h * omega, a2 = h * omega * a1, a3 = 1 / (1 + a2);
    biasRate = omega / a1, massScale = a2 * a3, impulseScale = a3;
  }
};

template <class T>
struct SolveParams {
  ContactModel model;
  T h, invH;
  Softness<T> soft, staticSoft;
  T maxPush, baumgarte, slop;
};

template <class T>
void applyImpulse(SolverBodyT<T>& a, SolverBodyT<T>& b, const Vec3<T>& rA, const Vec3<T>& rB,
                  const Vec3<T>& P) {
  a.v -= a.invMass * P, a.w -= a.invInertia * rA.cross(P);
  b.v += b.invMass * P, b.w += b.invInertia * rB.cross(P);
}

template <class T>
Vec3<T> relativeVelocity(const SolverBodyT<T>& a, const SolverBodyT<T>& b, const Vec3<T>& rA,
                         const Vec3<T>& rB) {
  return b.v + b.w.cross(rB) - a.v - a.w.cross(rA);
}

// The effective mass along direction d at anchors rA, rB.
template <class T>
T effectiveMass(const SolverBodyT<T>& a, const SolverBodyT<T>& b, const Vec3<T>& rA,
                const Vec3<T>& rB, const Vec3<T>& d) {
  const Vec3<T> ra = rA.cross(d), rb = rB.cross(d);
  const T k = a.invMass + b.invMass + ra.dot(a.invInertia * ra) + rb.dot(b.invInertia * rb);
  return k > 0 ? 1 / k : 0;
}

// Tangents, masses and restitution's reference velocities from the step's start.
template <class T>
void prepareContacts(std::vector<ContactConstraintT<T>>& contacts,
                     const std::vector<SolverBodyT<T>>& bodies) {
  for (ContactConstraintT<T>& c : contacts) {
    const SolverBodyT<T>&a = bodies[c.a], &b = bodies[c.b];
    tangentsOf(c.normal, c.tangent);
    for (int i = 0; i < c.count; ++i) {
      ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
      p.normalMass = effectiveMass(a, b, p.rA, p.rB, c.normal);
      for (int k = 0; k < 2; ++k) p.tangentMass[k] = effectiveMass(a, b, p.rA, p.rB, c.tangent[k]);
      p.relativeVelocity = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
      p.maxNormalImpulse = 0;
    }
  }
}

template <class T>
void warmStart(std::vector<ContactConstraintT<T>>& contacts, std::vector<SolverBodyT<T>>& bodies) {
  for (const ContactConstraintT<T>& c : contacts)
    for (int i = 0; i < c.count; ++i) {
      const ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
      const Vec3<T> P = p.normalImpulse * c.normal + p.tangentImpulse[0] * c.tangent[0] +
                        p.tangentImpulse[1] * c.tangent[1];
      applyImpulse(bodies[c.a], bodies[c.b], p.rA, p.rB, P);
    }
}

// The separations of a contact's points now, from the bodies' motion since the step's start.
// A point's anchor r has turned to dq r, and n.(dq r - r) = (dq^-1 n - n).r: the normal is turned
// back once a contact rather than each anchor once a point (the kernels' order of operations).
template <class T>
struct Separation {
  Vec3<T> nA, nB;  // dq^-1 n - n of each body
  T along;         // n.(dpB - dpA)
  Separation(const SolverBodyT<T>& a, const SolverBodyT<T>& b, const Vec3<T>& n)
      : nA(a.dq.conjugate() * n - n), nB(b.dq.conjugate() * n - n), along((b.dp - a.dp).dot(n)) {}
  T operator()(const ContactPointConstraintT<T>& p) const {
    return p.baseSeparation + (along + (nB.dot(p.rB) - nA.dot(p.rA)));
  }
};

// One pass over the contacts: friction, then normal impulses (biased by the model when useBias),
// Jolt's order: the non-penetration impulses come last, so they hold what friction disturbs. On
// W5 at B = 20 the pyramid then sags 0.0058 where normal-first let it creep 0.0126.
template <class T>
void solveContacts(std::vector<ContactConstraintT<T>>& contacts,
                   std::vector<SolverBodyT<T>>& bodies, const SolveParams<T>& s, bool useBias,
                   bool reverse) {
  for (ContactConstraintT<T>& c : contacts) {
    SolverBodyT<T>&a = bodies[c.a], &b = bodies[c.b];
    const Softness<T>& soft = c.isStatic ? s.staticSoft : s.soft;
    for (int k = 0; k < c.count; ++k) {
      ContactPointConstraintT<T>& p = c.points[std::size_t(reverse ? c.count - 1 - k : k)];
      // Both directions from the same velocity, then the total clamped to the Coulomb cone
      // (|f| <= mu * normal, Jolt's), not each direction to its own limit: that square would
      // let friction reach sqrt(2) mu * normal on a diagonal slide.
      const T limit = c.friction * p.normalImpulse;
      const Vec3<T> dv = relativeVelocity(a, b, p.rA, p.rB);
      T total[2];
      for (int j = 0; j < 2; ++j)
        total[j] = p.tangentImpulse[j] - p.tangentMass[j] * dv.dot(c.tangent[j]);
      const T squared = total[0] * total[0] + total[1] * total[1];
      if (squared > limit * limit) {
        const T scale = limit / std::sqrt(squared);
        total[0] *= scale, total[1] *= scale;
      }
      const Vec3<T> impulse = (total[0] - p.tangentImpulse[0]) * c.tangent[0] +
                              (total[1] - p.tangentImpulse[1]) * c.tangent[1];
      p.tangentImpulse[0] = total[0], p.tangentImpulse[1] = total[1];
      applyImpulse(a, b, p.rA, p.rB, impulse);
    }
    const Separation<T> separation(a, b, c.normal);
    for (int k = 0; k < c.count; ++k) {
      ContactPointConstraintT<T>& p = c.points[std::size_t(reverse ? c.count - 1 - k : k)];
      const T sep = separation(p);
      T bias = 0, massScale = 1, impulseScale = 0;
      if (sep > 0) {
        bias = sep * s.invH;  // speculative: close the gap within the substep, no further
      } else if (useBias) {
        if (s.model == ContactModel::kSoftStep) {
          bias = std::max(soft.biasRate * sep, -s.maxPush);
          massScale = soft.massScale, impulseScale = soft.impulseScale;
        } else if (s.model == ContactModel::kBaumgarte) {
          bias = s.baumgarte * s.invH * std::min(T(0), sep + s.slop);
        }
      }
      const T vn = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
      T impulse = -p.normalMass * massScale * (vn + bias) - impulseScale * p.normalImpulse;
      const T total = std::max(p.normalImpulse + impulse, T(0));
      impulse = total - p.normalImpulse;
      p.normalImpulse = total;
      p.maxNormalImpulse = std::max(p.maxNormalImpulse, impulse);
      // Restitution acts on the speed of the impact, met within a substep of it, rather than
      // on the speed at the step's start (gravity adds up to g dt by the impact).
      if (total > 0) p.relativeVelocity = std::min(p.relativeVelocity, vn);
      applyImpulse(a, b, p.rA, p.rB, Vec3<T>(impulse * c.normal));
    }
  }
}

// Restitution once after the substeps, on points that were approaching faster than the threshold
// and pushed (Box2D v3's b2ApplyRestitution).
template <class T>
void applyRestitution(std::vector<ContactConstraintT<T>>& contacts,
                      std::vector<SolverBodyT<T>>& bodies, T threshold) {
  for (ContactConstraintT<T>& c : contacts) {
    if (c.restitution == 0) continue;
    SolverBodyT<T>&a = bodies[c.a], &b = bodies[c.b];
    for (int i = 0; i < c.count; ++i) {
      ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
      if (p.relativeVelocity > -threshold || p.maxNormalImpulse == 0) continue;
      const T vn = relativeVelocity(a, b, p.rA, p.rB).dot(c.normal);
      T impulse = -p.normalMass * (vn + c.restitution * p.relativeVelocity);
      const T total = std::max(p.normalImpulse + impulse, T(0));
      impulse = total - p.normalImpulse;
      p.normalImpulse = total;
      applyImpulse(a, b, p.rA, p.rB, Vec3<T>(impulse * c.normal));
    }
  }
}

// The book's linear projection: each manifold's deepest point pushed back to the slop, a
// fraction at a time, shared by inverse mass.
template <class T>
void projectPositions(const std::vector<ContactConstraintT<T>>& contacts,
                      std::vector<SolverBodyT<T>>& bodies, T fraction, T slop) {
  for (const ContactConstraintT<T>& c : contacts) {
    SolverBodyT<T>&a = bodies[c.a], &b = bodies[c.b];
    const T mass = a.invMass + b.invMass;
    if (mass == 0) continue;
    const Separation<T> separation(a, b, c.normal);
    T sep = 0;
    for (int i = 0; i < c.count; ++i) sep = std::min(sep, separation(c.points[std::size_t(i)]));
    const T push = fraction * std::max(-sep - slop, T(0)) / mass;
    a.dp -= push * a.invMass * c.normal;
    b.dp += push * b.invMass * c.normal;
  }
}

}  // namespace simdphys::detail

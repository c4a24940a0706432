// The scalar reference of a particle step (particles.hpp), written once on Eigen for float (the
// reference path) and double (the truth errors are measured against): the integrators, the
// collision against the static obstacles along the path travelled, and the response. The SIMD
// kernel (simd/particles.cpp) mirrors it operation for operation.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/particle_step.hpp"
#include "simdphys/obstacles.hpp"
#include "simdphys/particles.hpp"
#include "src/bvh/scalar_walk.hpp"
#include "src/reference/geometry3d/raycast-inl.hpp"

namespace simdphys::reference {

// One system's settings for one substep, in T.
template <class T>
struct ParticleStep {
  Integrator integrator;
  Vec3<T> gravity;
  T dt, damping, drag, restitution, friction, threshold, skin, limit;
  int maxBounces;
  bool forces;               // read the force fields, or drag is on: a depends on more than gravity
  bool pushOutFirst = true;  // core::ParticleStepParams::pushOutFirst
};

using core::ParticleCounts;

#include "core/particle_integrate-inl.hpp"

// One step of length dt of x and v under the acceleration accel(x) (particles.hpp's formulas;
// damping is the caller's). The world passes a constant; the closed-form tests an oscillator's.
template <class T, class Accel>
void integrate(Integrator integrator, Vec3<T>& x, Vec3<T>& v, T dt, Accel&& accel) {
  integrateStep(std::uint32_t(integrator), x, v, dt, T(0.5), accel);
}

// Where a point strictly inside a solid leaves it by the shortest way, and the outward normal
// there; nothing if the point is not strictly inside.
template <class T>
struct Exit {
  Vec3<T> point, normal;
};

template <class T>
std::optional<Exit<T>> exitOf(const PlaneT<T>& plane, const Vec3<T>& p) {
  const T f = plane.normal.dot(p) + plane.d;
  if (!(f < 0)) return std::nullopt;
  return Exit<T>{p - f * plane.normal, plane.normal};
}

template <class T>
std::optional<Exit<T>> exitOf(const SphereT<T>& sphere, const Vec3<T>& p) {
  const Vec3<T> e = p - sphere.center;
  const T e2 = e.squaredNorm();
  if (!(e2 < sphere.radius * sphere.radius)) return std::nullopt;
  // At the very centre every way is shortest: up (+y), as documented.
  const Vec3<T> n = e2 > 0 ? Vec3<T>(e / std::sqrt(e2)) : Vec3<T>::UnitY();
  return Exit<T>{sphere.center + n * sphere.radius, n};
}

// An AABB is left through the face of least depth (ties: the lowest axis, its min face first).
template <class T>
std::optional<Exit<T>> exitOf(const AabbT<T>& box, const Vec3<T>& p) {
  int axis = 0;
  bool toMax = false;
  T depth = std::numeric_limits<T>::infinity();
  for (int k = 0; k < 3; ++k) {
    const T below = p[k] - box.min[k], above = box.max[k] - p[k];
    if (!(below > 0 && above > 0)) return std::nullopt;
    if (below < depth) depth = below, axis = k, toMax = false;
    if (above < depth) depth = above, axis = k, toMax = true;
  }
  Exit<T> e{p, Vec3<T>::Zero()};
  e.point[axis] = toMax ? box.max[axis] : box.min[axis];
  e.normal[axis] = toMax ? T(1) : T(-1);
  return e;
}

// An OBB is left through the face of least depth h - |q| of the local point q (ties: the lowest
// axis), on the side of q's sign (+ at 0).
template <class T>
std::optional<Exit<T>> exitOf(const ObbT<T>& box, const Vec3<T>& p) {
  const Vec3<T> q = box.axes.transpose() * (p - box.center);
  int axis = 0;
  T depth = std::numeric_limits<T>::infinity();
  for (int k = 0; k < 3; ++k) {
    const T d = box.halfExtents[k] - std::abs(q[k]);
    if (!(d > 0)) return std::nullopt;
    if (d < depth) depth = d, axis = k;
  }
  const Vec3<T> n =
      std::signbit(q[axis]) ? Vec3<T>(-box.axes.col(axis)) : Vec3<T>(box.axes.col(axis));
  return Exit<T>{p + n * depth, n};
}

// A mesh is a surface: nothing is inside it.
template <class T>
std::optional<Exit<T>> exitOf(const MeshObstacle&, const Vec3<T>&) {
  return std::nullopt;
}

// The float box around [lo, hi] (from double rounded outwards, within the supported range), for
// the trees' queries.
template <class T>
Aabb outwardBox(const Vec3<T>& lo, const Vec3<T>& hi) {
  if constexpr (std::is_same_v<T, float>) {
    return {lo, hi};
  } else {
    Aabb box;
    for (int k = 0; k < 3; ++k) {
      box.min[k] = std::nextafter(float(lo[k]), -kMaxCoordinate);
      box.max[k] = std::nextafter(float(hi[k]), kMaxCoordinate);
    }
    return box;
  }
}

// The first surface the path x0 -> x1 enters: the fraction s of the path and the outward normal
// there. Planes are entered from their front; solids through their surface (a path starting
// inside enters nothing).
template <class T>
struct Entry {
  T s;
  Vec3<T> normal;
};

template <class T>
std::optional<Entry<T>> entryOf(const PlaneT<T>& plane, const Vec3<T>& x0, const Vec3<T>& d) {
  const T f0 = plane.normal.dot(x0) + plane.d;
  const T rate = plane.normal.dot(d);
  if (!(f0 >= 0 && f0 + rate < 0)) return std::nullopt;
  return Entry<T>{f0 / -rate, plane.normal};
}

// A solid (sphere, AABB, OBB) is entered through its surface; a path starting inside enters
// nothing.
template <class S, class T>
requires detail::rays::Solid<S, T> std::optional<Entry<T>> entryOf(const S& solid,
                                                                   const Vec3<T>& x0,
                                                                   const Vec3<T>& d) {
  const auto h = detail::rays::hitSolid(solid, x0, d, T(1));
  if (!h || h->inside) return std::nullopt;
  return Entry<T>{h->t, h->normal};
}

// A mesh's triangles are two-sided: the path meets the first it crosses, found by the mesh's own
// closest-hit raycast along it (MeshBvh: within 1e-6 relative of the nearest, the lowest id; the
// same bits on every path), with hitTriangle's normal turned against the path. In double (the
// truth the float paths are measured against) the same through the triangles whose bounds meet
// the path's, the lowest id winning exact ties only.
template <class T>
std::optional<Entry<T>> entryOf(const MeshObstacle& mesh, const Vec3<T>& x0, const Vec3<T>& d) {
  if constexpr (std::is_same_v<T, float>) {
    const ElementHit h = mesh->raycast(Ray{x0, d}, 1.0f);
    if (!h.hit()) return std::nullopt;
    const Vec3d wide = detail::rays::triangleNormalWide(mesh->mesh().triangle(h.index));
    Vec3f n = detail::rays::unitOr<double>(wide, Vec3d::Zero()).cast<float>();  // it has area
    if (n.dot(d) > 0) n = -n;
    return Entry<T>{h.t, n};
  } else {
    const Vec3<T> x1 = x0 + d;
    std::optional<Entry<T>> first;
    for (std::uint32_t id : mesh->overlapping(outwardBox<T>(x0.cwiseMin(x1), x0.cwiseMax(x1)))) {
      const auto h = detail::rays::hitTriangle(cast<T>(mesh->mesh().triangle(id)),
                                               WatertightRayT<T>(x0, d), T(1));
      if (h && (!first || h->t < first->s)) first = Entry<T>{h->t, h->normal};
    }
    return first;
  }
}

// Whether the path from -> to may come near a box grown around an obstacle (ObstacleRow::lo):
// the path's box widened by a slack far above the rounding of the exact tests where the
// coordinates are large (1e-4 of their magnitudes). The kernel's cull (simd/particles.cpp:
// pathBox, Row::near), operation for operation: a NaN or infinite coordinate is never culled.
template <class T>
bool mayMeet(const Aabb& box, const Vec3<T>& from, const Vec3<T>& to) {
  using std::abs;
  const T slack =
      (abs(from[0]) + abs(from[1]) + abs(from[2]) + abs(to[0]) + abs(to[1]) + abs(to[2])) *
      T(1e-4f);
  for (int k = 0; k < 3; ++k) {
    const T lo = (from[k] < to[k] ? from[k] : to[k]) - slack;
    const T hi = (from[k] > to[k] ? from[k] : to[k]) + slack;
    if (hi < T(box.min[k]) || lo > T(box.max[k])) return false;
  }
  return true;
}

// The obstacles a particle is tested against: every one, in order; or, with a tree (more than
// Obstacles::kFewObstacles bounded ones), the planes and the bounded obstacles whose grown boxes
// the path may meet (mayMeet), still in order: the tree only finds them faster.
template <class T>
class ObstacleSetT {
 public:
  explicit ObstacleSetT(std::span<const ObstacleShapeT<T>> shapes, const Bvh* tree = nullptr,
                        std::span<const std::uint32_t> bounded = {},
                        std::span<const Aabb> boxes = {},
                        std::span<const std::uint32_t> planes = {})
      : shapes_(shapes), tree_(tree), bounded_(bounded), boxes_(boxes), planes_(planes) {}

  // Calls f(shape) for each obstacle that the path from -> to may meet, in order.
  template <class F>
  void near(const Vec3<T>& from, const Vec3<T>& to, F&& f) const {
    if (!tree_) {
      for (const auto& s : shapes_) f(s);
      return;
    }
    std::vector<std::uint32_t> ids(planes_.begin(), planes_.end());
    // A box around mayMeet's for the tree (twice its slack covers the rounding to float).
    const T slack = T(2e-4) * (from.cwiseAbs().sum() + to.cwiseAbs().sum());
    const Vec3<T> lo = from.cwiseMin(to).array() - slack, hi = from.cwiseMax(to).array() + slack;
    const Aabb box = outwardBox<T>(lo, hi);
    if (!(box.min.array() <= box.max.array()).all()) {  // a NaN: every obstacle
      for (const auto& s : shapes_) f(s);
      return;
    }
    overlappingLeaves(tree_->nodes(), box, [&](std::uint32_t k, std::uint32_t) {
      if (mayMeet(boxes_[k], from, to)) ids.push_back(bounded_[k]);
    });
    std::sort(ids.begin(), ids.end());
    for (std::uint32_t i : ids) f(shapes_[i]);
  }

 private:
  std::span<const ObstacleShapeT<T>> shapes_;
  const Bvh* tree_;
  std::span<const std::uint32_t> bounded_;
  std::span<const Aabb> boxes_;
  std::span<const std::uint32_t> planes_;
};

// Pushes p out of every obstacle it is strictly inside, in order, to `skin` outside, and takes
// the part of v into that surface away; counts each push.
template <class T>
void pushOut(const ObstacleSetT<T>& obstacles, T skin, Vec3<T>& p, Vec3<T>& v,
             ParticleCounts& counts) {
  obstacles.near(p, p, [&](const ObstacleShapeT<T>& o) {  // near where p starts
    const auto e = std::visit([&](const auto& shape) { return exitOf(shape, p); }, o);
    if (!e) return;
    p = e->point + e->normal * skin;
    const T vn = v.dot(e->normal);
    if (vn < 0) v = v - e->normal * vn;
    ++counts.pushedOut;
  });
}

// The velocity after meeting a surface of normal n: the normal part reversed and scaled by the
// restitution (none below the threshold speed), the tangential part reduced by Coulomb friction
// with the normal impulse, never reversed.
template <class T>
Vec3<T> respond(const ParticleStep<T>& p, const Vec3<T>& v, const Vec3<T>& n) {
  const T vn = v.dot(n);
  if (!(vn < 0)) return v;
  const T e = -vn > p.threshold ? p.restitution : T(0);
  Vec3<T> vt = v - n * vn;
  const T vtLength = vt.norm();
  if (vtLength > 0) vt = vt * std::max(T(0), T(1) - p.friction * ((T(1) + e) * -vn) / vtLength);
  return vt - n * (e * vn);
}

// Resting contact on a surface of normal n for the time tau left: the surface takes the part of
// the velocity and of the acceleration into it, and Coulomb friction, of magnitude friction times
// the acceleration it takes, acts against the sliding velocity; if that would stop the particle
// within tau, it stops, and slides on only by what the rest of a exceeds static friction with.
template <class T>
void rest(const ParticleStep<T>& p, const Vec3<T>& n, T tau, Vec3<T>& v, Vec3<T>& a) {
  const T vn = v.dot(n);
  if (vn < 0) v = v - n * vn;
  const T an = a.dot(n);
  if (!(an < 0)) return;
  a = a - n * an;
  const T f = p.friction * -an;
  const Vec3<T> vt = v - n * v.dot(n);
  const T speed = vt.norm();
  if (speed > 0) {
    const Vec3<T> sliding = a - vt * (f / speed);
    if ((vt + sliding * tau).dot(vt) > 0) {  // still sliding the same way at the end
      a = sliding;
      return;
    }
  }
  v = v - vt;
  const T at = a.norm();
  a = at > f ? Vec3<T>(a * (T(1) - f / at)) : Vec3<T>::Zero();
}

// One particle's step: the push out of an obstacle it starts in (looked for only when one may be:
// ParticleStepParams::pushOutFirst), forces, damping, integration, then the path x -> x' against
// the obstacles.
// The first surface the path enters ends it there: a fast impact bounces (respond) and the path
// goes on from the contact for the time left; a slow one (at most the restitution threshold) is a
// resting contact, under rest() for the time left, and if the particle was already touching the
// surface, for the whole step from its start, so that gravity cannot creep a particle along a
// surface friction holds it on. At most maxBounces contacts; past them the particle stays at the
// last one.
template <class T>
void stepParticle(const ParticleStep<T>& p, const ObstacleSetT<T>& obstacles, Vec3<T>& x,
                  Vec3<T>& v, T invMass, const Vec3<T>& force, ParticleCounts& counts) {
  if (!(invMass > 0)) return;  // pinned
  if (p.pushOutFirst) pushOut(obstacles, p.skin, x, v, counts);
  const Vec3<T> xIn = x, vIn = v;
  Vec3<T> a = p.gravity;
  if (p.forces) a = a + (force - v * p.drag) * invMass;
  const auto constant = [&](const Vec3<T>&) { return a; };
  Vec3<T> x0 = x, v0 = v * p.damping, x1 = x0, v1 = v0;
  T tau = p.dt;
  integrate(p.integrator, x1, v1, tau, constant);
  for (int bounce = 0;; ++bounce) {
    const Vec3<T> d = x1 - x0;
    if (d.squaredNorm() == 0) break;  // not moving: meets nothing
    std::optional<Entry<T>> first;
    obstacles.near(x0, x1, [&](const ObstacleShapeT<T>& o) {
      const auto e = std::visit([&](const auto& shape) { return entryOf(shape, x0, d); }, o);
      if (e && (!first || e->s < first->s)) first = e;
    });
    if (!first) break;
    ++counts.contacts;
    const Vec3<T> n = first->normal;
    const Vec3<T> vh = v0 + a * (first->s * tau);  // the velocity at the contact
    if (bounce == p.maxBounces) {
      ++counts.bounceLimited;
      x1 = x0 + d * first->s + n * p.skin;
      v1 = respond(p, vh, n);
      pushOut(obstacles, p.skin, x1, v1, counts);
      break;
    }
    if (-vh.dot(n) <= p.threshold) {
      // Resting. A particle that was already touching (within two skins along n) re-runs its
      // path from the start; one that arrived from further stops at the contact first, so that
      // it does not hover where the step began.
      if (first->s * -d.dot(n) > 2 * p.skin) {
        v0 = vh;
        x0 = x0 + d * first->s + n * p.skin;
        pushOut(obstacles, p.skin, x0, v0, counts);
        tau = (T(1) - first->s) * tau;
      }
      rest(p, n, tau, v0, a);
    } else {
      v0 = respond(p, vh, n);
      x0 = x0 + d * first->s + n * p.skin;
      pushOut(obstacles, p.skin, x0, v0, counts);  // a contact in a corner between obstacles
      tau = (T(1) - first->s) * tau;
    }
    x1 = x0;
    v1 = v0;
    integrate(p.integrator, x1, v1, tau, constant);
  }
  // A path that ends within rounding of a surface it runs along (its entry computed just past
  // its end) may end a hair inside: no particle ends a step inside an obstacle.
  const std::uint64_t before = counts.pushedOut;
  pushOut(obstacles, p.skin, x1, v1, counts);
  counts.endPushed += counts.pushedOut - before;
  // A step that would take the particle past the supported range (a force far beyond any real
  // world's, or a NaN from one) is not taken: it stays as it was (pushed out, if it was inside),
  // counted, and nothing non-finite enters the streams.
  bool inRange = true;
  for (int k = 0; k < 3; ++k)
    inRange = inRange && std::abs(x1[k]) <= p.limit && std::abs(v1[k]) <= p.limit;  // NaN: false
  if (!inRange) {
    ++counts.outOfRange;
    x = xIn, v = vIn;
    return;
  }
  x = x1;
  v = v1;
}

}  // namespace simdphys::reference

namespace simdphys::reference {

// The kernels' parameters in T.
template <class T>
ParticleStep<T> particleStep(const core::ParticleStepParams& p) {
  return {Integrator(p.integrator),
          Vec3<T>(T(p.gravity[0]), T(p.gravity[1]), T(p.gravity[2])),
          T(p.dt),
          T(p.damping),
          T(p.drag),
          T(p.restitution),
          T(p.friction),
          T(p.threshold),
          T(p.skin),
          T(p.limit),
          p.maxBounces,
          p.forces,
          p.pushOutFirst};
}

}  // namespace simdphys::reference

// One rigid-body step (rigid.hpp) on Eigen, templated on the scalar: find the contacts, warm
// start them from last step's, then the substeps of the contact model, restitution, and the
// impulses kept for the next step.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

#include "src/reference/rigid/narrowphase-inl.hpp"
#include "src/reference/rigid/solver-inl.hpp"

namespace simdphys::detail {

struct RigidStepStats {
  double deepest = 0;
  std::size_t manifolds = 0, points = 0, colours = 0, overflow = 0;
  double passSeconds = 0;  // in the contact passes (warm start, solve, relax, restitution)
};

// Last step's impulses for the contacts whose key and feature ids match.
template <class T>
void warmStartFrom(const std::vector<CachedManifoldT<T>>& cache,
                   std::vector<ContactConstraintT<T>>& contacts) {
  // The contacts come mostly in key order (findContacts'): each search starts from the last
  // match and gallops forward, so a step's lookups cost about one pass over the cache.
  const auto before = [](const CachedManifoldT<T>& m,
                         const std::pair<std::uint64_t, std::uint32_t>& k) {
    return std::pair(m.key, m.sub) < k;
  };
  auto from = cache.begin();
  for (ContactConstraintT<T>& c : contacts) {
    const std::pair key(c.key, c.sub);
    if (from != cache.begin() && !before(*(from - 1), key)) from = cache.begin();
    std::size_t step = 1;
    auto to = from;
    while (to != cache.end() && before(*to, key)) {
      from = to + 1;
      to = std::size_t(cache.end() - from) > step ? from + std::ptrdiff_t(step) : cache.end();
      step *= 2;
    }
    const auto it = std::lower_bound(from, to, key, before);
    from = it;
    if (it == cache.end() || it->key != c.key || it->sub != c.sub) continue;
    for (int i = 0; i < c.count; ++i)
      for (int j = 0; j < it->count; ++j)
        if (it->id[j] == c.points[std::size_t(i)].id) {
          ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
          p.normalImpulse = it->impulse[j][0];
          p.tangentImpulse[0] = it->impulse[j][1];
          p.tangentImpulse[1] = it->impulse[j][2];
        }
  }
}

template <class T>
void keepImpulses(const std::vector<ContactConstraintT<T>>& contacts,
                  std::vector<CachedManifoldT<T>>& cache) {
  // The keys sorted with each contact's index, then the entries written in that order: sorting
  // 16-byte keys rather than the 80-byte entries.
  struct Keyed {
    std::uint64_t key;
    std::uint32_t sub, index;
  };
  std::vector<Keyed> order(contacts.size());
  for (std::uint32_t k = 0; k < contacts.size(); ++k)
    order[k] = {contacts[k].key, contacts[k].sub, k};
  const auto before = [](const Keyed& l, const Keyed& r) {
    return std::pair(l.key, l.sub) < std::pair(r.key, r.sub);
  };
  // On the kernels the contacts lie as findContacts made them, two runs in key order (the pairs,
  // then the obstacles' by body, in key order while bodies keep their first slots): a merge.
  const auto run = std::is_sorted_until(order.begin(), order.end(), before);
  if (std::is_sorted(run, order.end(), before))
    std::inplace_merge(order.begin(), run, order.end(), before);
  else
    std::sort(order.begin(), order.end(), before);
  cache.resize(contacts.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const ContactConstraintT<T>& c = contacts[order[k].index];
    CachedManifoldT<T>& m = cache[k];
    m = {c.key, c.sub, c.count, {}, {}};
    for (int i = 0; i < c.count; ++i) {
      const ContactPointConstraintT<T>& p = c.points[std::size_t(i)];
      m.id[i] = p.id;
      m.impulse[i][0] = p.normalImpulse;
      m.impulse[i][1] = p.tangentImpulse[0];
      m.impulse[i][2] = p.tangentImpulse[1];
    }
  }
}

// Gravity, forces and damping over h, on a body's velocities v and w (its solver's, or a
// kernel's record's).
template <class T>
struct Acceleration {
  Vec3<T> g;
  T h, linear, angular;
  Acceleration(const RigidSettings& s, T step)
      : g(s.gravity.template cast<T>()),
        h(step),
        linear(1 / (1 + step * T(s.linearDamping))),
        angular(1 / (1 + step * T(s.angularDamping))) {}
  template <class V3>
  void apply(const BodyT<T>& b, const Mat3<T>& invInertia, V3&& v, V3&& w) const {
    v = linear * (v + h * (g + b.invMass * b.force));
    w = angular * (w + h * (invInertia * b.torque));
  }
};

template <class T>
void integrateVelocities(const std::vector<BodyT<T>>& bodies, std::vector<SolverBodyT<T>>& solver,
                         const RigidSettings& s, T h) {
  const Acceleration<T> a(s, h);
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (solver[i].invMass != 0)  // not kinematic or asleep
      a.apply(bodies[i], solver[i].invInertia, solver[i].v, solver[i].w);
}

// q turned by the rotation vector r (first order, normalised).
template <class T>
Quat<T> turned(const Quat<T>& q, const Vec3<T>& r) {
  Quat<T> out = q;
  out.coeffs() += (Quat<T>(0, r.x(), r.y(), r.z()) * q).coeffs() * T(0.5);
  return out.normalized();
}

// Moves the bodies by their velocities. A body's angular momentum L = I w is kept through the
// turn, which is taken at the rate of the turn's midpoint, w = I^-1 L there (second order), and
// w = I'^-1 L at the new orientation: a free body tumbles with L fixed and its energy drifting
// at O(h^2), where an explicit w x Iw term gains energy and an implicit one loses it at O(h).
template <class T>
void integratePositions(const std::vector<BodyT<T>>& bodies, std::vector<SolverBodyT<T>>& solver,
                        T h) {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyT<T>& body = bodies[i];
    SolverBodyT<T>& b = solver[i];
    b.dp += h * b.v;
    if (b.invMass == 0) {
      b.dq = turned(b.dq, Vec3<T>(h * b.w));
      continue;
    }
    const auto rate = [&](const Quat<T>& q, const Vec3<T>& L) {
      return Vec3<T>(q * Vec3<T>(body.invInertia.cwiseProduct(q.conjugate() * L)));
    };
    const Quat<T> was = b.dq * body.q;
    const Vec3<T> L =
        was * Vec3<T>(body.invInertia.cwiseInverse().cwiseProduct(was.conjugate() * b.w));
    const Vec3<T> mid = rate(turned(was, Vec3<T>(T(0.5) * h * b.w)), L);
    b.dq = turned(b.dq, Vec3<T>(h * mid));
    b.w = rate(b.dq * body.q, L);
  }
}

// Sleeping: islands of awake bodies still for timeToSleep fall asleep; sleeping islands an awake
// body touched wake (for the next step: their own contacts were not made in this one).
template <class T>
void updateSleep(std::vector<BodyT<T>>& bodies, std::span<const std::uint32_t> slots,
                 const std::vector<ContactConstraintT<T>>& contacts, const RigidSettings& s, T dt) {
  const std::size_t n = bodies.size();
  const auto awakeDynamic = [&](std::uint32_t i) {
    return i < n && bodies[i].invMass > 0 && bodies[i].island == 0;
  };
  std::vector<std::uint32_t> wake;
  for (const ContactConstraintT<T>& c : contacts)
    if (c.b < n && (bodies[c.a].island == 0) != (bodies[c.b].island == 0)) {
      const std::uint32_t sleeper = bodies[c.a].island != 0 ? c.a : c.b;
      const std::uint32_t other = sleeper == c.a ? c.b : c.a;
      if (bodies[other].invMass > 0 || bodies[other].v.squaredNorm() > 0 ||
          bodies[other].w.squaredNorm() > 0)
        wake.push_back(bodies[sleeper].island);
    }
  // Still or not, by the speed of the body's fastest point (its reach times the angular speed).
  const T tolerance = T(s.sleepSpeed);
  for (std::size_t i = 0; i < n; ++i) {
    BodyT<T>& b = bodies[i];
    if (!awakeDynamic(std::uint32_t(i))) continue;
    const T reach = b.shape == BodyShape::kSphere ? b.half.x() : b.half.norm();
    const bool still = b.v.norm() + reach * b.w.norm() <= tolerance && b.force.squaredNorm() == 0 &&
                       b.torque.squaredNorm() == 0;
    b.sleepTime = still ? b.sleepTime + dt : T(0);
  }
  // Islands of awake dynamic bodies joined by contacts (union-find), each the stillness of its
  // least still body.
  std::vector<std::uint32_t> parent(n);
  for (std::uint32_t i = 0; i < n; ++i) parent[i] = i;
  const auto find = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const ContactConstraintT<T>& c : contacts)
    if (awakeDynamic(c.a) && awakeDynamic(c.b)) {
      const std::uint32_t ra = find(c.a), rb = find(c.b);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  std::vector<T> least(n, std::numeric_limits<T>::infinity());
  for (std::uint32_t i = 0; i < n; ++i)
    if (awakeDynamic(i)) least[find(i)] = std::min(least[find(i)], bodies[i].sleepTime);
  for (std::uint32_t i = 0; i < n; ++i)
    if (awakeDynamic(i) && least[find(i)] >= T(s.timeToSleep)) {
      BodyT<T>& b = bodies[i];
      b.island = slots[find(i)] + 1;  // the id outlives index changes
      b.v.setZero(), b.w.setZero();
    }
  for (BodyT<T>& b : bodies)
    if (b.island != 0 && std::find(wake.begin(), wake.end(), b.island) != wake.end())
      b.island = 0, b.sleepTime = 0;
}

// The contact passes and the bodies' motion on Eigen, one contact or body at a time: the
// reference. A kernel's passes (src/rigid/contact_rows.hpp) take the same calls.
template <class T>
struct ReferencePasses {
  // The contacts into solving order (the passes then take them as they lie).
  void prepare(std::vector<ContactConstraintT<T>>& c, const ColourOrder& colours,
               const SolveParams<T>&, const std::vector<BodyT<T>>&,
               const std::vector<SolverBodyT<T>>& b) {
    putInOrder(c, colours);
    prepareContacts(c, b);
  }
  void integrateVelocities(const std::vector<BodyT<T>>& bodies, std::vector<SolverBodyT<T>>& b,
                           const RigidSettings& s, T h) {
    detail::integrateVelocities(bodies, b, s, h);
  }
  void warmStart(std::vector<ContactConstraintT<T>>& c, std::vector<SolverBodyT<T>>& b) {
    detail::warmStart(c, b);
  }
  void solve(std::vector<ContactConstraintT<T>>& c, std::vector<SolverBodyT<T>>& b,
             const SolveParams<T>& p, bool useBias, bool reverse) {
    solveContacts(c, b, p, useBias, reverse);
  }
  void integratePositions(const std::vector<BodyT<T>>& bodies, std::vector<SolverBodyT<T>>& b,
                          T h) {
    detail::integratePositions(bodies, b, h);
  }
  void project(const std::vector<ContactConstraintT<T>>& c, std::vector<SolverBodyT<T>>& b,
               T fraction, T slop) {
    projectPositions(c, b, fraction, slop);
  }
  void restitution(std::vector<ContactConstraintT<T>>& c, std::vector<SolverBodyT<T>>& b,
                   T threshold) {
    applyRestitution(c, b, threshold);
  }
  void finish(std::vector<ContactConstraintT<T>>&, std::vector<SolverBodyT<T>>&) {}
};

// One step of dt: bodies (their positions, orientations and velocities) move; `cache` holds
// last step's manifolds (their impulses, and the pairs' geometry), `next` receives this step's.
template <class T, class Passes = ReferencePasses<T>>
RigidStepStats stepState(std::vector<BodyT<T>>& bodies, std::span<const std::uint32_t> slots,
                         const ContactCacheT<T>& cache, ContactCacheT<T>& next,
                         BroadphaseCache& broadphase, const Obstacles& obstacles,
                         const RigidSettings& s, T dt, int threads = 1,
                         Passes&& passes = Passes()) {
  RigidStepStats stats;
  T deepest = 0;
  // A thread's buffer, reused from step to step (rewritten whole: no state carries over).
  static thread_local std::vector<ContactConstraintT<T>> contacts;
  findContacts(contacts, bodies, slots, cache.pairs, next.pairs, broadphase, obstacles, s, dt,
               threads, deepest);
  // In findContacts' order: near key order.
  if (s.warmStarting) warmStartFrom(cache.manifolds, contacts);
  const ColourOrder colours = colourContacts(contacts, bodies);
  stats.overflow = colours.begin[1];
  for (std::size_t k = 1; k + 1 < colours.begin.size(); ++k)
    stats.colours += colours.begin[k + 1] > colours.begin[k] ? 1 : 0;
  stats.deepest = double(deepest);
  stats.manifolds = contacts.size();
  for (const auto& c : contacts) stats.points += std::size_t(c.count);

  const std::size_t n = bodies.size();
  std::vector<SolverBodyT<T>> solver(n + 1);  // the last: the static dummy of obstacle contacts
  for (std::size_t i = 0; i < n; ++i) {
    if (bodies[i].island != 0) continue;  // asleep: held still, as the static dummy is
    const Mat3<T> R = bodies[i].q.toRotationMatrix();
    solver[i].v = bodies[i].v, solver[i].w = bodies[i].w, solver[i].invMass = bodies[i].invMass;
    solver[i].invInertia = R * bodies[i].invInertia.asDiagonal() * R.transpose();
  }

  const T h = dt / T(s.substeps);
  SolveParams<T> p{s.model, h, 1 / h, {}, {}, T(s.maxPushSpeed), T(s.baumgarte), T(s.linearSlop)};
  const T hertz = std::min(T(s.contactHertz), T(0.25) / h);
  p.soft = Softness<T>(hertz, T(s.contactDampingRatio), h);
  p.staticSoft = Softness<T>(2 * hertz, T(s.contactDampingRatio), h);
  passes.prepare(contacts, colours, p, bodies, solver);
  using Clock = std::chrono::steady_clock;
  const auto timed = [&](auto&& pass) {
    const auto start = Clock::now();
    pass();
    stats.passSeconds += std::chrono::duration<double>(Clock::now() - start).count();
  };
  for (int sub = 0; sub < s.substeps; ++sub) {
    passes.integrateVelocities(bodies, solver, s, h);
    timed([&] { passes.warmStart(contacts, solver); });
    // The points of a manifold are solved in turn, forward in one pass and backward in the
    // next, so the order's bias (the first point takes the load and turns the body) cancels.
    for (int it = 0; it < s.iterations; ++it)
      timed([&] { passes.solve(contacts, solver, p, true, ((sub + it) & 1) != 0); });
    passes.integratePositions(bodies, solver, h);
    if (s.model == ContactModel::kProjection)  // reads only the points' geometry
      passes.project(contacts, solver, T(s.projection), T(s.linearSlop));
    if (s.model == ContactModel::kSoftStep)
      for (int it = 0; it < s.iterations; ++it)
        timed([&] { passes.solve(contacts, solver, p, false, ((sub + it) & 1) == 0); });
  }
  timed([&] { passes.restitution(contacts, solver, T(s.restitutionThreshold)); });
  passes.finish(contacts, solver);

  for (std::size_t i = 0; i < n; ++i) {
    BodyT<T>& b = bodies[i];
    b.x += solver[i].dp;
    b.q = (solver[i].dq * b.q).normalized();
    b.v = solver[i].v, b.w = solver[i].w;
  }
  if (s.sleeping) updateSleep(bodies, slots, contacts, s, dt);
  keepImpulses(contacts, next.manifolds);
  return stats;
}

}  // namespace simdphys::detail

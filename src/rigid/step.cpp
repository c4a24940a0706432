// The rigid bodies' step (src/rigid/step.hpp): the streams to the reference's bodies and back.
#include "src/rigid/step.hpp"

#include <cmath>
#include <string>

#include "src/core/on_path.hpp"
#include "src/reference/rigid/step-inl.hpp"
#include "src/reference/validate-inl.hpp"
#include "src/rigid/contact_rows.hpp"

namespace simdphys {

namespace F = fields;
using Internals = RigidBodies::Internals;

template <class T>
std::vector<detail::BodyT<T>> Internals::load(const RigidBodies& r) {
  const auto vec = [&](std::size_t f, std::size_t i) {
    return Vec3<T>(T(r.value(f, i)), T(r.value(f + 1, i)), T(r.value(f + 2, i)));
  };
  std::vector<detail::BodyT<T>> out(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    detail::BodyT<T>& b = out[i];
    b.x = vec(F::Body::x, i), b.v = vec(F::Body::vx, i), b.w = vec(F::Body::wx, i);
    b.q = Quat<T>(T(r.value(F::Body::qw, i)), T(r.value(F::Body::qx, i)),
                  T(r.value(F::Body::qy, i)), T(r.value(F::Body::qz, i)));
    b.invMass = T(r.value(F::Body::invMass, i));
    b.invInertia = vec(F::Body::invIx, i);
    b.shape = BodyShape(int(r.value(F::Body::shape, i)));
    b.half = vec(F::Body::ex, i);
    if (b.shape == BodyShape::kHull)
      b.hull = r.hulls_[std::size_t(r.value(F::Body::hull, i))].get();
    b.friction = T(r.value(F::Body::friction, i));
    b.restitution = T(r.value(F::Body::restitution, i));
    b.force = vec(F::Body::fx, i), b.torque = vec(F::Body::tx, i);
    b.sleepTime = T(r.value(F::Body::sleepTime, i));
    b.island = std::uint32_t(r.value(F::Body::island, i));
  }
  return out;
}

template <class T>
void Internals::store(RigidBodies& r, const std::vector<detail::BodyT<T>>& state) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    const detail::BodyT<T>& b = state[i];
    r.storeVec(F::Body::x, i, b.x.template cast<float>());
    r.storeVec(F::Body::vx, i, b.v.template cast<float>());
    r.storeVec(F::Body::wx, i, b.w.template cast<float>());
    r.storeVec(F::Body::qx, i, b.q.vec().template cast<float>());
    r.paddedData(F::Body::qw)[i] = float(b.q.w());
    r.paddedData(F::Body::sleepTime)[i] = float(b.sleepTime);
    r.paddedData(F::Body::island)[i] = float(b.island);
  }
}

std::vector<std::uint32_t> Internals::slots(const RigidBodies& r) {
  std::vector<std::uint32_t> out(r.size());
  for (std::uint32_t i = 0; i < r.size(); ++i) out[i] = r.handles_.handle(i).slot;
  return out;
}

template std::vector<detail::BodyT<float>> Internals::load(const RigidBodies&);
template std::vector<detail::BodyT<double>> Internals::load(const RigidBodies&);
template void Internals::store(RigidBodies&, const std::vector<detail::BodyT<float>>&);
template void Internals::store(RigidBodies&, const std::vector<detail::BodyT<double>>&);

namespace {
// The kernels' rows and records, a thread's, reused from step to step (rebuilt whole each step:
// no state carries over) so that their hundreds of kilobytes are not faulted in every step.
detail::KernelPasses& kernelPasses(std::size_t bodies) {
  static thread_local detail::KernelPasses passes(false, 0);
  passes.reset(detail::plainLoopsActive(), std::uint32_t(bodies));
  return passes;
}
}  // namespace

void Internals::step(RigidBodies& bodies, const Obstacles& obstacles, float dt, int threads,
                     const std::string& where) {
  using namespace detail;
  std::vector<BodyT<float>> state = Internals::load<float>(bodies);
  const std::vector<std::uint32_t> slots = Internals::slots(bodies);
  // The next cache: a thread's buffer, swapped with the bodies' on success (so each keeps its
  // pages from step to step).
  static thread_local ContactCacheT<float> next;
  const auto& cache = bodies.cache_;
  // The contact passes on the active path: the reference on Eigen, or the kernels over rows
  // (or their plain loops), the rest of the step shared.
  const RigidStepStats stats =
      referencePathActive() ? stepState(state, slots, cache, next, bodies.broadphase_, obstacles,
                                        bodies.settings(), dt, threads)
                            : stepState(state, slots, cache, next, bodies.broadphase_, obstacles,
                                        bodies.settings(), dt, threads, kernelPasses(state.size()));
  // Nothing is stored unless every body stays finite and in range: the world is unchanged then.
  for (std::size_t i = 0; i < state.size(); ++i) {
    const auto inRange = [](const Vec3f& x) {
      return inSupportedRange(std::abs(double(x.x()))) &&
             inSupportedRange(std::abs(double(x.y()))) && inSupportedRange(std::abs(double(x.z())));
    };
    if (inRange(state[i].x) && inRange(state[i].v) && inRange(state[i].w)) continue;
    const std::string body = where + ": body " + std::to_string(i);  // built for the message only
    requireFiniteField(state[i].x, body, "position after the step");
    requireFiniteField(state[i].v, body, "velocity after the step");
    requireFiniteField(state[i].w, body, "angular velocity after the step");
  }
  Internals::store(bodies, state);
  std::swap(bodies.cache_, next);
  bodies.deepest_ = float(stats.deepest);
  bodies.manifolds_ = stats.manifolds;
  bodies.points_ = stats.points;
  bodies.colours_ = stats.colours;
  bodies.overflow_ = stats.overflow;
  bodies.passSeconds_ = stats.passSeconds;
}

void detail::stepBodies(RigidBodies& bodies, const Obstacles& obstacles, float dt, int threads,
                        const std::string& where) {
  Internals::step(bodies, obstacles, dt, threads, where);
}

}  // namespace simdphys

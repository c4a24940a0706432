// Stepping the rigid bodies of a world (rigid.hpp) on the active path (the reference solver for
// now; the wide kernel to come), and the streams as the reference's bodies.
#pragma once

#include <string>
#include <vector>

#include "simdphys/obstacles.hpp"
#include "simdphys/rigid.hpp"
#include "src/reference/rigid/bodies-inl.hpp"

namespace simdphys {

struct RigidBodies::Internals {
  template <class T>
  static std::vector<detail::BodyT<T>> load(const RigidBodies& bodies);
  template <class T>
  static void store(RigidBodies& bodies, const std::vector<detail::BodyT<T>>& state);
  static std::vector<std::uint32_t> slots(const RigidBodies& bodies);
  static void step(RigidBodies& bodies, const Obstacles& obstacles, float dt, int threads,
                   const std::string& where);
};

namespace detail {

// One step of dt on `threads` threads (0: OpenMP's default; the result does not depend on it).
// Throws Error naming `where` and the body, with nothing moved, if a body would leave the
// supported range or its state stop being finite.
void stepBodies(RigidBodies& bodies, const Obstacles& obstacles, float dt, int threads,
                const std::string& where);

}  // namespace detail
}  // namespace simdphys

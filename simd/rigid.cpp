// The rigid bodies' contact passes and motion (core/rigid_solve.hpp) as kernels:
// simd/rigid_contacts-inl.hpp and simd/rigid_motion-inl.hpp with Highway vectors, a contact or a
// body per lane, and the same passes one at a time (the plain-loop baseline, "Autovec").
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/rigid.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/particle_lanes-inl.hpp"

#include "simd/rigid_records-inl.hpp"

#include "simd/rigid_contacts-inl.hpp"

#include "simd/rigid_motion-inl.hpp"

void PrepareContacts(const core::ContactRows& rows, const core::SolverBody* bodies) {
  prepareT(hn::ScalableTag<float>(), rows, bodies);
}
void WarmStartContacts(const core::ContactRows& rows, core::SolverBody* bodies) {
  warmStartT(hn::ScalableTag<float>(), rows, bodies);
}
void SolveContacts(const core::ContactRows& rows, core::SolverBody* bodies,
                   const core::ContactPass& pass) {
  solveT(hn::ScalableTag<float>(), rows, bodies, pass);
}
void RestituteContacts(const core::ContactRows& rows, core::SolverBody* bodies, float threshold) {
  restitutionT(hn::ScalableTag<float>(), rows, bodies, threshold);
}
void PrepareContactsAutovec(const core::ContactRows& rows, const core::SolverBody* bodies) {
  prepareT(ScalarLane(), rows, bodies);
}
void WarmStartContactsAutovec(const core::ContactRows& rows, core::SolverBody* bodies) {
  warmStartT(ScalarLane(), rows, bodies);
}
void SolveContactsAutovec(const core::ContactRows& rows, core::SolverBody* bodies,
                          const core::ContactPass& pass) {
  solveT(ScalarLane(), rows, bodies, pass);
}
void RestituteContactsAutovec(const core::ContactRows& rows, core::SolverBody* bodies,
                              float threshold) {
  restitutionT(ScalarLane(), rows, bodies, threshold);
}

void IntegrateBodies(core::SolverBody* bodies, const core::BodyFrames& frames, float h) {
  integrateT(hn::ScalableTag<float>(), bodies, frames, h);
}
void IntegrateBodiesAutovec(core::SolverBody* bodies, const core::BodyFrames& frames, float h) {
  integrateT(ScalarLane(), bodies, frames, h);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(PrepareContacts, prepareContacts);
SIMDPHYS_EXPORT(WarmStartContacts, warmStartContacts);
SIMDPHYS_EXPORT(SolveContacts, solveContacts);
SIMDPHYS_EXPORT(RestituteContacts, restituteContacts);
SIMDPHYS_EXPORT(PrepareContactsAutovec, prepareContactsAutovec);
SIMDPHYS_EXPORT(WarmStartContactsAutovec, warmStartContactsAutovec);
SIMDPHYS_EXPORT(SolveContactsAutovec, solveContactsAutovec);
SIMDPHYS_EXPORT(RestituteContactsAutovec, restituteContactsAutovec);
SIMDPHYS_EXPORT(IntegrateBodies, integrateBodies);
SIMDPHYS_EXPORT(IntegrateBodiesAutovec, integrateBodiesAutovec);
}  // namespace simdphys::simd
#endif

// The contact passes and the bodies' motion of a rigid step on the kernels (simd/rigid.cpp): the
// step's coloured contacts laid out as rows of lanes, batch after batch, each padded to
// kStreamPad lanes with inert lanes, and the solver bodies as the kernels' records from the
// step's preparation to its end.
#pragma once

#include <vector>

#include "core/rigid_solve.hpp"
#include "simdphys/core.hpp"
#include "src/reference/rigid/step-inl.hpp"

namespace simdphys::detail {

class KernelPasses {
 public:
  // plainLoops: the passes' plain-loop baseline rather than the kernels. dummy: the static
  // dummy's index (the last solver body).
  KernelPasses(bool plainLoops, std::uint32_t dummy) : plainLoops_(plainLoops), dummy_(dummy) {}
  void reset(bool plainLoops, std::uint32_t dummy) { plainLoops_ = plainLoops, dummy_ = dummy; }

  // The rows and the records for a step; the records then hold the bodies' motion until finish.
  void prepare(const std::vector<ContactConstraintT<float>>& contacts, const ColourOrder& colours,
               const SolveParams<float>& p, const std::vector<BodyT<float>>& bodies,
               const std::vector<SolverBodyT<float>>& solver);
  void integrateVelocities(const std::vector<BodyT<float>>& bodies,
                           std::vector<SolverBodyT<float>>& solver, const RigidSettings& s,
                           float h);
  void warmStart(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>&);
  void solve(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>&,
             const SolveParams<float>& p, bool useBias, bool reverse);
  void integratePositions(const std::vector<BodyT<float>>&, std::vector<SolverBodyT<float>>&,
                          float h);
  void project(const std::vector<ContactConstraintT<float>>& contacts,
               std::vector<SolverBodyT<float>>& solver, float fraction, float slop);
  void restitution(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>&,
                   float threshold);
  // The records' motion back into the solver bodies, and the accumulated impulses into the
  // contacts, for the next step's warm start.
  void finish(std::vector<ContactConstraintT<float>>& contacts,
              std::vector<SolverBodyT<float>>& solver);

 private:
  core::ContactRows rows();
  void toRecords(const std::vector<SolverBodyT<float>>& solver);
  void fromRecords(std::vector<SolverBodyT<float>>& solver) const;

  bool plainLoops_;
  std::uint32_t dummy_;
  AlignedVector<float> fields_;         // the rows' blocks (core::ContactRows)
  AlignedVector<std::uint32_t> a_, b_;  // each lane's bodies
  std::vector<std::uint32_t> batchBegin_;
  std::vector<std::uint32_t> laneOf_;  // each contact's lane
  std::vector<std::uint32_t> order_;   // the contacts in solving order (project's)
  std::size_t lanes_ = 0;
  std::vector<core::SolverBody> records_;  // the solver bodies, padded to whole blocks
  AlignedVector<float> frames_;            // core::BodyFrames' 8 streams of records_.size()
};

}  // namespace simdphys::detail

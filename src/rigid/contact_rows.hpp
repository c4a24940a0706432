// The contact passes of a rigid step on the kernels (simd/rigid.cpp): the step's coloured
// contacts laid out as rows of lanes, batch after batch, each padded to kStreamPad lanes with
// inert lanes, and the solver bodies as the kernels' records around each pass.
#pragma once

#include <vector>

#include "core/rigid_solve.hpp"
#include "simdphys/core.hpp"
#include "src/reference/rigid/solver-inl.hpp"

namespace simdphys::detail {

class KernelPasses {
 public:
  // plainLoops: the passes' plain-loop baseline rather than the kernels. dummy: the static
  // dummy's index (the last solver body).
  KernelPasses(bool plainLoops, std::uint32_t dummy) : plainLoops_(plainLoops), dummy_(dummy) {}
  void reset(bool plainLoops, std::uint32_t dummy) { plainLoops_ = plainLoops, dummy_ = dummy; }

  void prepare(const std::vector<ContactConstraintT<float>>& contacts,
               const std::vector<std::uint32_t>& colourBegin, const SolveParams<float>& p,
               const std::vector<SolverBodyT<float>>& bodies);
  void warmStart(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>& b);
  void solve(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>& b,
             const SolveParams<float>& p, bool useBias, bool reverse);
  void restitution(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>& b,
                   float threshold);
  // The accumulated impulses back into the contacts, for the next step's warm start.
  void finish(std::vector<ContactConstraintT<float>>& contacts);

 private:
  core::ContactRows rows();
  void toRecords(const std::vector<SolverBodyT<float>>& bodies);
  void fromRecords(std::vector<SolverBodyT<float>>& bodies) const;

  bool plainLoops_;
  std::uint32_t dummy_;
  AlignedVector<float> fields_;         // the rows' blocks (core::ContactRows)
  AlignedVector<std::uint32_t> a_, b_;  // each lane's bodies
  std::vector<std::uint32_t> batchBegin_;
  std::vector<std::uint32_t> laneOf_;  // each contact's lane
  std::size_t lanes_ = 0;
  std::vector<core::SolverBody> records_;
};

}  // namespace simdphys::detail

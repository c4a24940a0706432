// KernelPasses (src/rigid/contact_rows.hpp).
#include "src/rigid/contact_rows.hpp"

#include <tuple>

#include "core/prefetch.hpp"
#include "simd/kernels.hpp"

namespace simdphys::detail {

using R = core::ContactRows;

void KernelPasses::prepare(const std::vector<ContactConstraintT<float>>& contacts,
                           const ColourOrder& colours, const SolveParams<float>& p,
                           const std::vector<BodyT<float>>& bodies,
                           const std::vector<SolverBodyT<float>>& solver) {
  // Batches: each overflow contact alone (they may share bodies), then each colour; ranges of
  // the solving order.
  const std::vector<std::uint32_t>& begin = colours.begin;
  order_ = colours.order;
  batchBegin_.assign(1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
  for (std::uint32_t i = 0; i < begin[1]; ++i) ranges.push_back({i, i + 1});
  for (std::size_t k = 1; k + 1 < begin.size(); ++k)
    if (begin[k + 1] > begin[k]) ranges.push_back({begin[k], begin[k + 1]});
  for (const auto& [first, last] : ranges)
    batchBegin_.push_back(batchBegin_.back() + std::uint32_t(paddedSize(last - first)));
  lanes_ = batchBegin_.back();
  static_assert(R::kBlockLanes == kStreamPad);
  // The rows only grow: every field of every lane is written below, so nothing is cleared (a
  // memset of megabytes a step).
  const std::size_t size = R::kBlock * (lanes_ / R::kBlockLanes);
  if (fields_.size() < size) fields_.resize(size);
  // Padding lanes join the static dummy to itself: no mass, no impulse, nothing moves.
  a_.assign(lanes_, dummy_), b_.assign(lanes_, dummy_);
  constexpr std::uint32_t kPadding = ~0u;
  constexpr std::size_t kAhead = 4;
  std::vector<std::uint32_t> contactAt(lanes_, kPadding);
  laneOf_.resize(contacts.size());
  // Within a batch, the lanes by their manifolds' counts, most points first (in solving order
  // among equals): a vector's lanes then mostly share a count, and the passes skip the points
  // past its fullest lane's. The lanes of a batch are independent: their order changes nothing.
  std::size_t batch = 0;
  std::vector<int> counts;
  for (const auto& [first, last] : ranges) {
    counts.resize(last - first);
    for (std::uint32_t i = first; i < last; ++i) counts[i - first] = contacts[order_[i]].count;
    std::uint32_t lane = batchBegin_[batch];
    for (int count = 4; count >= 1; --count)
      for (std::uint32_t i = first; i < last; ++i)
        if (counts[i - first] == count) laneOf_[order_[i]] = lane, contactAt[lane++] = order_[i];
    ++batch;
  }
  const core::ContactRows r = rows();
  const auto at = [&](std::size_t field, std::size_t lane) -> float& {
    return r.lanes(lane)[field * R::kBlockLanes];
  };
  // Lane after lane: a block's 16 lanes fill its lines while they are cached.
  for (std::size_t lane = 0; lane < lanes_; ++lane) {
    const std::uint32_t i = contactAt[lane];
    const auto zero = [&](std::size_t from, std::size_t to) {
      for (std::size_t f = from; f < to; ++f) at(f, lane) = 0.0f;
    };
    if (i == kPadding) {
      zero(0, R::kFields);
      continue;
    }
    const ContactConstraintT<float>& c = contacts[i];
    // A batch's contacts lie apart in `contacts`: the one a few lanes on fetched meanwhile.
    if (lane + kAhead < lanes_ && contactAt[lane + kAhead] != kPadding) {
      core::prefetchLines(&contacts[contactAt[lane + kAhead]], sizeof(c));
    }
    a_[lane] = c.a, b_[lane] = c.b;
    for (int k = 0; k < 3; ++k) {
      at(R::nx + std::size_t(k), lane) = c.normal[k];  // the tangents are prepareT's
    }
    at(R::friction, lane) = c.friction, at(R::restitution, lane) = c.restitution;
    at(R::count, lane) = float(c.count);
    const Softness<float>& soft = c.isStatic ? p.staticSoft : p.soft;
    at(R::biasRate, lane) = soft.biasRate, at(R::massScale, lane) = soft.massScale;
    at(R::impulseScale, lane) = soft.impulseScale;
    for (const auto& [body, mass, inertia] :
         {std::tuple(c.a, R::invMassA, R::inertiaA), std::tuple(c.b, R::invMassB, R::inertiaB)}) {
      const SolverBodyT<float>& sb = solver[body];
      const Mat3f& I = sb.invInertia;
      at(mass, lane) = sb.invMass;
      const float upper[6] = {I(0, 0), I(0, 1), I(0, 2), I(1, 1), I(1, 2), I(2, 2)};
      for (std::size_t k = 0; k < 6; ++k) at(inertia + k, lane) = upper[k];
    }
    // The points past the count are inert: all zero.
    zero(R::kPoint + std::size_t(c.count) * R::kPointFields, R::kFields);
    for (int j = 0; j < c.count; ++j) {
      const ContactPointConstraintT<float>& q = c.points[std::size_t(j)];
      const std::size_t o = R::kPoint + std::size_t(j) * R::kPointFields;
      for (int k = 0; k < 3; ++k) {
        at(o + R::rAx + std::size_t(k), lane) = q.rA[k];
        at(o + R::rBx + std::size_t(k), lane) = q.rB[k];
      }
      at(o + R::base, lane) = q.baseSeparation;
      at(o + R::normalImpulse, lane) = q.normalImpulse;
      at(o + R::tangent1, lane) = q.tangentImpulse[0];
      at(o + R::tangent2, lane) = q.tangentImpulse[1];
    }
  }
  // The records, and what moving them needs of the bodies.
  toRecords(solver);
  const std::size_t count = records_.size();
  frames_.assign(8 * count, 0.0f);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyT<float>& body = bodies[i];
    const float q[4] = {body.q.x(), body.q.y(), body.q.z(), body.q.w()};
    for (std::size_t k = 0; k < 4; ++k) frames_[k * count + i] = q[k];
    for (std::size_t k = 0; k < 3; ++k) frames_[(4 + k) * count + i] = body.invInertia[int(k)];
    frames_[7 * count + i] = solver[i].invMass > 0 ? 1.0f : 0.0f;
  }
  // The masses and normal velocities, lane-wide.
  (plainLoops_ ? simd::prepareContactsAutovec : simd::prepareContacts)(r, records_.data());
}

core::ContactRows KernelPasses::rows() {
  core::ContactRows r;
  r.data = fields_.data();
  r.a = a_.data(), r.b = b_.data();
  r.batchBegin = batchBegin_.data();
  r.batches = batchBegin_.size() - 1;
  return r;
}

void KernelPasses::toRecords(const std::vector<SolverBodyT<float>>& solver) {
  // Whole blocks: the padding records are still bodies (no velocity, no turn).
  records_.assign(paddedSize(solver.size()), core::SolverBody{});
  for (core::SolverBody& r : records_) r.dq[3] = 1.0f;
  for (std::size_t i = 0; i < solver.size(); ++i) {
    const SolverBodyT<float>& b = solver[i];
    core::SolverBody& r = records_[i];
    for (int k = 0; k < 3; ++k) r.v[k] = b.v[k], r.w[k] = b.w[k], r.dp[k] = b.dp[k];
    r.dq[0] = b.dq.x(), r.dq[1] = b.dq.y(), r.dq[2] = b.dq.z(), r.dq[3] = b.dq.w();
  }
}

void KernelPasses::fromRecords(std::vector<SolverBodyT<float>>& solver) const {
  for (std::size_t i = 0; i < solver.size(); ++i) {
    const core::SolverBody& r = records_[i];
    SolverBodyT<float>& b = solver[i];
    for (int k = 0; k < 3; ++k) b.v[k] = r.v[k], b.w[k] = r.w[k], b.dp[k] = r.dp[k];
    b.dq = Quatf(r.dq[3], r.dq[0], r.dq[1], r.dq[2]);
  }
}

void KernelPasses::integrateVelocities(const std::vector<BodyT<float>>& bodies,
                                       std::vector<SolverBodyT<float>>& solver,
                                       const RigidSettings& s, float h) {
  const Acceleration<float> a(s, h);
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (solver[i].invMass != 0)  // not kinematic or asleep
      a.apply(bodies[i], solver[i].invInertia, Eigen::Map<Vec3f>(records_[i].v),
              Eigen::Map<Vec3f>(records_[i].w));
}

void KernelPasses::warmStart(std::vector<ContactConstraintT<float>>&,
                             std::vector<SolverBodyT<float>>&) {
  (plainLoops_ ? simd::warmStartContactsAutovec : simd::warmStartContacts)(rows(), records_.data());
}

void KernelPasses::solve(std::vector<ContactConstraintT<float>>&, std::vector<SolverBodyT<float>>&,
                         const SolveParams<float>& p, bool useBias, bool reverse) {
  core::ContactPass pass{core::ContactPass::kNone, p.invH, p.maxPush, p.baumgarte, p.slop, reverse};
  if (useBias && p.model == ContactModel::kSoftStep) pass.bias = core::ContactPass::kSoft;
  if (useBias && p.model == ContactModel::kBaumgarte) pass.bias = core::ContactPass::kBaumgarte;
  (plainLoops_ ? simd::solveContactsAutovec : simd::solveContacts)(rows(), records_.data(), pass);
}

void KernelPasses::integratePositions(const std::vector<BodyT<float>>&,
                                      std::vector<SolverBodyT<float>>&, float h) {
  const std::size_t count = records_.size();
  const float* f = frames_.data();
  const core::BodyFrames frames{{f, f + count, f + 2 * count, f + 3 * count},
                                {f + 4 * count, f + 5 * count, f + 6 * count},
                                f + 7 * count,
                                count};
  (plainLoops_ ? simd::integrateBodiesAutovec : simd::integrateBodies)(records_.data(), frames, h);
}

// The book's projection on Eigen (it reads the contacts' points, not the rows), in solving
// order: through the solver bodies and back.
void KernelPasses::project(const std::vector<ContactConstraintT<float>>& contacts,
                           std::vector<SolverBodyT<float>>& solver, float fraction, float slop) {
  fromRecords(solver);
  projectPositions(orderedCopy(contacts, order_), solver, fraction, slop);
  toRecords(solver);
}

void KernelPasses::restitution(std::vector<ContactConstraintT<float>>&,
                               std::vector<SolverBodyT<float>>&, float threshold) {
  (plainLoops_ ? simd::restituteContactsAutovec : simd::restituteContacts)(rows(), records_.data(),
                                                                           threshold);
}

void KernelPasses::finish(std::vector<ContactConstraintT<float>>& contacts,
                          std::vector<SolverBodyT<float>>& solver) {
  fromRecords(solver);
  const core::ContactRows r = rows();
  for (std::size_t i = 0; i < contacts.size(); ++i)
    for (int j = 0; j < contacts[i].count; ++j) {
      ContactPointConstraintT<float>& q = contacts[i].points[std::size_t(j)];
      const float* f =
          r.lanes(laneOf_[i]) + (R::kPoint + std::size_t(j) * R::kPointFields) * R::kBlockLanes;
      q.normalImpulse = f[R::normalImpulse * R::kBlockLanes];
      q.tangentImpulse[0] = f[R::tangent1 * R::kBlockLanes];
      q.tangentImpulse[1] = f[R::tangent2 * R::kBlockLanes];
    }
}

}  // namespace simdphys::detail

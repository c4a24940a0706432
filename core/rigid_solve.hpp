// What the rigid bodies' contact kernels are given (rigid.hpp), Eigen-free so that it crosses from
// the library to the kernels (simd/rigid.cpp): the solver bodies as fixed-size records, and the
// contacts as rows of SoA lanes, colour after colour. The scalar reference
// (src/reference/rigid/solver-inl.hpp) defines the arithmetic; the kernels follow it lane-wide.
#pragma once

#include <cstddef>
#include <cstdint>

namespace simdphys::core {

// A body as the solver moves it within a step (src/reference/rigid/bodies-inl.hpp's SolverBodyT):
// velocities and the motion since the step's start (the masses are in the contact rows). 16
// floats: a 64-byte line.
struct SolverBody {
  float v[3], w[3], dp[3], dq[4];  // dq: x, y, z, w
  float pad[3];
};

// The contacts, a lane each. Fields per lane, then per point k (0..3) the block at
// kPoint + k * kPointFields. A lane past a colour's contacts (padding) joins the static dummy to
// itself with zero masses and impulses, so it changes nothing.
struct ContactRows {
  enum : std::size_t {
    nx,
    ny,
    nz,
    t1x,
    t1y,
    t1z,
    t2x,
    t2y,
    t2z,
    friction,
    restitution,
    biasRate,
    massScale,
    impulseScale,
    count,  // the manifold's points (a float); the points past it are inert (all zero)
    // The bodies' inverse masses and world inverse inertias (xx, xy, xz, yy, yz, zz), fixed for
    // the step: read with the lane's other fields rather than gathered from the records.
    invMassA,
    inertiaA,
    invMassB = inertiaA + 6,
    inertiaB,
    kPoint = inertiaB + 6
  };
  enum : std::size_t {
    rAx,
    rAy,
    rAz,
    rBx,
    rBy,
    rBz,
    base,
    normalMass,
    tangentMass1,
    tangentMass2,
    normalImpulse,
    tangent1,
    tangent2,
    maxNormal,
    relative,
    kPointFields
  };
  static constexpr std::size_t kFields = kPoint + 4 * kPointFields;
  // Blocks of kBlockLanes lanes (kStreamPad, the widest vector), each block's fields one after
  // another (Box2D v3's wide constraint structs): a vector's fields lie at fixed offsets from its
  // block, one cache-friendly run of kFields * 64 bytes.
  static constexpr std::size_t kBlockLanes = 16;
  static constexpr std::size_t kBlock = kFields * kBlockLanes;
  // The first field of `lane`'s block, at the lane; field k is then k * kBlockLanes further.
  float* lanes(std::size_t lane) const {
    return data + lane / kBlockLanes * kBlock + lane % kBlockLanes;
  }
  float* data;
  const std::uint32_t *a, *b;       // the bodies of each lane (b: the dummy for an obstacle)
  const std::uint32_t* batchBegin;  // batches + 1 lane offsets, each a multiple of kBlockLanes
  std::size_t batches;
};

// What moving a body's record over a substep needs beyond the record (simd/rigid.cpp's
// integrateBodies): its orientation at the step's start (x, y, z, w), its inverse inertia about
// its own axes, and whether it has mass (1; else it turns at its w). Streams of `count` floats, a
// multiple of ContactRows::kBlockLanes, as many as the records (the padding still).
struct BodyFrames {
  const float* q[4];
  const float* invInertia[3];
  const float* dynamic;
  std::size_t count;
};

// One pass's constants (SolveParams of the reference): the model's bias for penetrating points.
struct ContactPass {
  enum Bias : std::uint32_t { kNone, kSoft, kBaumgarte };
  std::uint32_t bias;
  float invH, maxPush, baumgarte, slop;
  bool reverse;  // points backward
};

}  // namespace simdphys::core

// What a cloth step kernel is given (cloth.hpp), Eigen-free so that it crosses from the library
// to the kernels (simd/cloth.cpp): the streams over slots, the springs as a coloured network and,
// for a grid, as families of shifted copies of the grid, the tethers and the obstacles as rows.
// The scalar reference (src/reference/cloth/step-inl.hpp) defines the arithmetic.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/particle_step.hpp"

namespace simdphys::core {

// The streams over slots: positions, velocities, the substep's start, inverse mass, forces
// (mass-spring) and each tethered slot's anchor position (copied by the step's start: anchors are
// pinned, so no substep moves them).
struct ClothStreams {
  enum : std::size_t { x, y, z, vx, vy, vz, px, py, pz, w, fx, fy, fz, ax, ay, az, kCount };
};

template <class T>
struct ClothView {
  T* s[ClothStreams::kCount];
  std::size_t slots;  // a multiple of kStreamPad; the arrays hold more (ClothLayout::extra)
};

// The springs in solving order, batch after batch: spring k joins slots a[k] and b[k].
struct SpringNetwork {
  const std::uint32_t *a, *b;
  const float *rest, *compliance, *stiffness, *damping;
  const std::uint32_t* batchBegin;  // batches + 1 offsets
  std::size_t batches;
};

// A grid's springs: family f joins slot p to p + offset(f) where rest[f][p] >= 0 (-1 elsewhere).
// Families in solving order: x+1, z+1, shear (x+1, z+1), shear (x-1, z+1), bend x+2, bend z+2,
// of kinds structural, structural, shear, shear, bend, bend; each solved as two colours (see
// simd/cloth_step-inl.hpp), in the order of the network's batches of Cloth::grid.
struct SpringGrid {
  enum Family : std::uint32_t { kX, kZ, kShear, kShearBack, kBendX, kBendZ, kFamilies };
  static constexpr std::uint32_t kKind[kFamilies] = {0, 0, 1, 1, 2, 2};
  const float* rest[kFamilies];
  float compliance[3], stiffness[3], damping[3];  // by kind
  std::size_t stride, rows;                       // slots per row, rows (nz)
  std::ptrdiff_t offset(std::uint32_t f) const {
    const auto s = std::ptrdiff_t(stride);
    const std::ptrdiff_t o[kFamilies] = {1, s, s + 1, s - 1, 2, 2 * s};
    return o[f];
  }
};

// Tethers: slot p is kept within length[p] of slot anchor[p] where length[p] >= 0 (-1: none).
struct Tethers {
  const std::uint32_t* anchor;  // null: no tethers
  const float* length;
};

// ClothSettings for one step: h the substep, the factors derived from it in float once.
struct ClothStepParams {
  enum Model : std::uint32_t { kXpbd, kMassSpring };
  std::uint32_t model;
  int substeps;
  float h, invH, invH2;  // h, 1 / h, 1 / (h h)
  float keep;            // 1 - damping h: the velocity kept per substep
  float gravity[3];
  float margin, friction;  // margin: kept off surfaces by the path test (0 with penalty springs)
  float penalty, zone;     // penalty springs: N/m (0: none) within `zone` of a surface
  bool damped;             // some spring has damping != 0
};

}  // namespace simdphys::core

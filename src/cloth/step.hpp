// Stepping a cloth (cloth.hpp) on the active path: the reference, the kernel or its plain-loop
// baseline.
#pragma once

#include <span>
#include <vector>

#include "core/cloth_step.hpp"
#include "simdphys/cloth.hpp"
#include "simdphys/obstacles.hpp"

namespace simdphys::detail {

// The obstacles as cloth meets them, a row each in order: AABBs as OBBs, a mesh's row naming it by
// its index (core::ObstacleQueries::meshEntry).
std::vector<core::ObstacleRow> clothRows(const Obstacles& obstacles);

// The substeps of a step of dt: the settings', raised for the mass-spring model to its stability
// bound. Throws Error naming `where` if that takes more than ClothSettings::kMaxSubsteps, or the
// model is mass-spring and a spring is rigid.
int clothSubsteps(const Cloth& cloth, float dt, const std::string& where);

core::ClothStepParams clothParams(const Cloth& cloth, float dt, int substeps);

// One step of dt on `threads` OpenMP threads (0: OpenMP's default; the result does not depend on
// it) (clothSubsteps() first: it throws, this does not, for valid input). If a
// particle would leave the supported range, nothing moves and it throws Error naming it. Returns
// the spring updates done (springs times substeps).
std::size_t stepCloth(Cloth& cloth, const Obstacles& obstacles,
                      std::span<const core::ObstacleRow> rows, float dt, int substeps, int threads,
                      const std::string& where);

}  // namespace simdphys::detail

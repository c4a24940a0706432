// The static obstacles as the particle kernels read them: flat rows with grown boxes, and the
// tree's candidates as row indices (core/particle_step.hpp).
#pragma once

#include <optional>
#include <vector>

#include "core/particle_step.hpp"
#include "simdphys/obstacles.hpp"

namespace simdphys::detail {

// An obstacle's row; a mesh has none.
std::optional<core::ObstacleRow> rowOf(const ObstacleShape& shape);

// Every obstacle's row, in order (meshes left out).
std::vector<core::ObstacleRow> obstacleRows(const Obstacles& obstacles);

// The obstacles' tree as the kernels query it; null without a tree.
std::optional<core::ObstacleTree> obstacleTree(const Obstacles& obstacles);

}  // namespace simdphys::detail

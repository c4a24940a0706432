// The static obstacles as the particle kernels read them: flat rows with grown boxes, and the
// tree's candidates as row indices (core/particle_step.hpp).
#pragma once

#include <optional>
#include <vector>

#include "core/particle_step.hpp"
#include "simdphys/obstacles.hpp"

namespace simdphys::detail {

// An obstacle's row, with its grown box (for a mesh, its vertices' box grown).
core::ObstacleRow rowOf(const ObstacleShape& shape);

// Every obstacle's row, in order: the row index is the obstacle's.
std::vector<core::ObstacleRow> obstacleRows(const Obstacles& obstacles);

// What the kernels ask of these obstacles (their tree, their meshes); nothing if neither.
std::optional<core::ObstacleQueries> obstacleQueries(const Obstacles& obstacles);

}  // namespace simdphys::detail

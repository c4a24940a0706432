// 2D geometry (book chapters 4-6): primitives and their validation, point containment and
// closest points, segment tests and raycasts, shape-versus-shape tests (the separating axis
// theorem for rectangles) with contact manifolds, containing circle and rectangle, compound
// shapes, and the quadtree.
//
// Conventions (each part's header states its own details):
// - Scalar reference, templates on float (the API) and double (the reference), declared in the
//   headers and compiled once for both in src/reference/geometry2d/.
// - x right, y up, angles in radians counter-clockwise; shapes closed and solid, touching counts.
// - Zero sizes are valid (points); queries never divide by zero and have documented answers.
// - Rounding is absorbed by kGeometry2dTolerance (16 eps) times a per-function scale; the
//   axis-aligned rectangle tests and the quadtree's rectangle answers are exact.
// - Invalid input is rejected by validate(shape, where), which throws Error saying what and where.
#pragma once

#include "simdphys/geometry2d/collisions.hpp"
#include "simdphys/geometry2d/containing.hpp"
#include "simdphys/geometry2d/line_tests.hpp"
#include "simdphys/geometry2d/point_tests.hpp"
#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry2d/quadtree.hpp"

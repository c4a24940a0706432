// 3D geometry (book chapters 7-11): primitives, point tests, shape-vs-shape tests, raycasts and
// linetests, GJK and EPA, and the streams and batch forms over many primitives.
#pragma once

#include "simdphys/geometry3d/batch.hpp"
#include "simdphys/geometry3d/epa.hpp"
#include "simdphys/geometry3d/gjk.hpp"
#include "simdphys/geometry3d/intersect.hpp"
#include "simdphys/geometry3d/point_tests.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/geometry3d/raycast.hpp"
#include "simdphys/geometry3d/streams.hpp"
#include "simdphys/geometry3d/support.hpp"

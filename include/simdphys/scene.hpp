// Scenes (book chapters 12-13), the umbrella of scene/: the frustum and culling, cameras, models,
// the octree and the scene.
#pragma once

#include "simdphys/scene/camera.hpp"
#include "simdphys/scene/frustum.hpp"
#include "simdphys/scene/model.hpp"
#include "simdphys/scene/octree.hpp"
#include "simdphys/scene/scene.hpp"

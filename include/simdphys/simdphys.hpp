// simdphys: everything in one include.
#pragma once

#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/core.hpp"
#include "simdphys/geometry2d.hpp"
#include "simdphys/geometry2d/batch.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/math.hpp"
#include "simdphys/scene.hpp"

// simdphys: everything in one include, every subject's public header.
#pragma once

#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/core.hpp"
#include "simdphys/geometry2d.hpp"
#include "simdphys/geometry2d/batch.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/handle.hpp"
#include "simdphys/math.hpp"
#include "simdphys/mesh.hpp"
#include "simdphys/mesh_bvh.hpp"
#include "simdphys/obstacles.hpp"
#include "simdphys/pair_finder.hpp"
#include "simdphys/particles.hpp"
#include "simdphys/rigid.hpp"
#include "simdphys/rigid/manifold.hpp"
#include "simdphys/scene.hpp"  // every header of scene/
#include "simdphys/spring_bodies.hpp"
#include "simdphys/world.hpp"

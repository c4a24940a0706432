// The settings blocks of a scene file, each read over the library's defaults (docs/scenes.md).
#pragma once

#include "json_node.hpp"
#include "simdphys/cloth.hpp"
#include "simdphys/particles.hpp"
#include "simdphys/rigid.hpp"
#include "simdphys/world.hpp"

namespace simdphys::scenefile {

WorldSettings worldSettings(const Node& n);  // the members beside "frames" and "path"
ParticleSettings particleSettings(const Node& n);
ClothSettings clothSettings(const Node& n);
RigidSettings rigidSettings(const Node& n);

// A rotation: {"axis": [x, y, z], "angle": radians} or {"quaternion": [x, y, z, w]}; either is
// normalised here (a zero axis or quaternion is an error).
Quatd rotation(const Node& n);
// The same as a matrix, computed in double and rounded once.
Mat3f rotationMatrix(const Node& n);

}  // namespace simdphys::scenefile

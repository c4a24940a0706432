// W5 `pyramid` of WORKLOADS.md, generated exactly: a square pyramid of unit boxes on a ground box,
// as plain data with no World in it (tests, benchmarks, peers); and the measures W5 reports,
// computed one way for every solver.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/math.hpp"

namespace simdphys::workloads {

inline constexpr int kPyramidFrames = 600;                // 10 s at 60 Hz
inline constexpr float kPyramidFrameTime = 1.0f / 60.0f;  // s
inline constexpr int kPyramidBases[] = {10, 20};          // B: 385 and 2,870 boxes
inline constexpr float kPyramidHalf = 0.5f;               // every box's half extent, m
inline constexpr float kPyramidMass = 1.0f;               // kg
inline constexpr float kPyramidFriction = 0.6f;           // every contact, box-box and box-ground
inline constexpr float kPyramidRestitution = 0.0f;
inline const Vec3f kPyramidGravity{0, -9.82f, 0};  // m/s^2
// The ground: a static box, centre (0, -0.5, 0), half extents (100, 0.5, 100).
inline const Obb kPyramidGround{{0, -0.5f, 0}, {100, 0.5f, 100}, Mat3f::Identity()};

// The boxes' centres in creation order: layer k = 0 .. B-1 from the bottom holds (B-k)^2 boxes
// at y = 0.5 + k on a lattice of pitch 1 centred on the y axis (so each layer sits half a pitch
// off the one below), row by row along z, within a row along x.
std::vector<Vec3f> pyramidCenters(int base);
constexpr std::size_t pyramidBoxCount(int base) {
  return std::size_t(base) * std::size_t(base + 1) * std::size_t(2 * base + 1) / 6;
}

// What W5 reports of a final state, against the start.
struct PyramidMeasures {
  double maxDisplacement = 0;  // m: the largest distance of a box from its start
  bool standing = true;        // every box within 0.5 of its start
};
PyramidMeasures measurePyramid(std::span<const Vec3f> start, std::span<const Vec3f> end);

}  // namespace simdphys::workloads

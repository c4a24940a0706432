// W3 `cloth` of WORKLOADS.md, generated exactly: an n x n particle grid hanging from two corners
// over a sphere, with its structural, shear and bend springs, as plain data with no World in it
// (tests, benchmarks, peers); and the measures W3 reports, computed one way for every solver.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/cloth.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/math.hpp"

namespace simdphys::workloads {

inline constexpr int kClothFrames = 300;                  // 5 s at 60 Hz
inline constexpr float kClothFrameTime = 1.0f / 60.0f;    // s
inline constexpr double kClothSpacing = 0.05;             // d, m
inline constexpr double kClothHeight = 2;                 // the grid's plane, y = 2
inline constexpr std::size_t kClothSizes[] = {128, 256};  // n: default and large
inline const Vec3f kClothGravity{0, -9.82f, 0};           // m/s^2
inline const Sphere kClothSphere{{0, 1.2f, 0.3f}, 0.5f};  // the true sphere W3 measures against

enum class SpringKind : std::uint8_t { kStructural, kShear, kBend };

// A spring between particles a and b, at rest at length `rest`.
struct ClothSpring {
  std::uint32_t a, b;
  float rest;
  SpringKind kind;
};

// W3's cloth. Particle (i, j), i and j in [0, n), has index j * n + i: i runs along x, j along z,
// and row j = 0 (z = -(n-1)/2 d) holds both pinned corners, indices 0 and n - 1. Position
// x = (i - (n-1)/2) d, y = 2, z = (j - (n-1)/2) d, each computed in double and rounded once.
// Inverse mass 1 (mass 1), 0 at the two pinned corners.
// Springs, kind by kind (structural, shear, bend), within a kind the two families in the order
// WORKLOADS.md lists them, within a family by the index of (i, j), the family's first corner,
// j-major (rows of constant j in turn, i increasing along each):
//   structural (i,j)-(i+1,j), (i,j)-(i,j+1); shear (i,j)-(i+1,j+1), (i+1,j)-(i,j+1);
//   bend (i,j)-(i+2,j), (i,j)-(i,j+2).
// `a` is the first particle as listed, `b` the second. Rest length: the distance between the
// two (float) positions, computed in double and rounded once.
struct ClothWorkload {
  std::size_t n = 0;
  std::vector<Vec3f> positions;
  std::vector<float> invMass;
  std::vector<ClothSpring> springs;
};
ClothWorkload makeClothWorkload(std::size_t n = 128);  // throws Error if n < 3

// W3's cloth as simdphys models it: the grid (rigid springs: XPBD's default) and the same
// springs as a general network, in the workload's order.
ClothGrid clothGrid(const ClothWorkload& w);
std::vector<Spring> clothSprings(const ClothWorkload& w);

// Spring counts from the grid: structural 2 n (n-1), shear 2 (n-1)^2, bend 2 n (n-2).
std::size_t clothSpringCount(std::size_t n, SpringKind kind);

// W3's stretch figures over the structural springs: the relative stretch |l - l0| / l0 of each,
// l its length at `positions`. p99 is the nearest-rank 99th percentile (the ceil(0.99 m)-th
// smallest of the m stretches); maxAwayFromPins the maximum over the springs that touch no
// pinned particle (invMass 0). A non-finite length counts as an infinite stretch.
struct ClothStretch {
  double mean, p99, max, maxAwayFromPins;
};
ClothStretch clothStretch(const ClothWorkload& w, std::span<const Vec3f> positions);

// The deepest penetration of any position into `sphere`: max(0, r - |p - c|), in double (0 when
// none is inside; infinite if a position is not finite, so a run that blew up fails any bound).
double spherePenetration(const Sphere& sphere, std::span<const Vec3f> positions);

// Whether every coordinate is finite.
bool allFinite(std::span<const Vec3f> positions);

}  // namespace simdphys::workloads

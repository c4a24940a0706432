// The standard workloads (docs/workloads.md), generated exactly: the same inputs for the tests,
// the benchmarks, the peers and the demo. Compiled without floating-point contraction so the
// draws round as the specification says.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/geometry2d/primitives.hpp"
#include "simdphys/geometry2d/streams.hpp"
#include "simdphys/geometry3d.hpp"
#include "simdphys/random.hpp"
#include "simdphys/scene/frustum.hpp"

namespace simdphys::workloads {

// SplitMix64 (simdphys/random.hpp): the workloads draw from it as WORKLOADS.md says.
using simdphys::Random;

// W1: N boxes and Q query boxes from seed 1.
struct AabbWorkload {
  BoxStream boxes;
  std::vector<Aabb> queries;
};
AabbWorkload makeAabbWorkload(std::size_t boxes, std::size_t queries = 1024);

// The reference figures of W1, for N = 100,000 and 1,000,000.
struct AabbReference {
  std::size_t boxes;
  std::uint64_t queryOverlaps, pairs, checksum;
};
inline constexpr AabbReference kAabbReference[] = {
    {100'000, 14'452, 20'234, 66'755'941'226'798ull},
    {1'000'000, 148'413, 2'016'018, 671'287'551'327'981'067ull},
};
// The W1 pairs checksum: the sum over pairs of (a * N + b), modulo 2^64.
std::uint64_t pairChecksum(std::span<const Pair> pairs, std::size_t n);

// W6: N spheres (and the same as boxes) from seed 6, and the camera's frustum.
struct CullWorkload {
  SphereStream spheres;
  BoundsStream boxes;
  Mat4d viewProjection;
  Frustum frustum;  // from viewProjection, normals computed in double then rounded
};
CullWorkload makeCullWorkload(std::size_t n = 1'000'000);
inline constexpr std::size_t kCullSpheresVisible = 101'017;
inline constexpr std::size_t kCullBoxesVisible = 102'099;

// W7: N 2D shapes from seed 7, circles (even indices) and oriented rectangles (odd ones), at a
// density that does not depend on N; `bounds` holds every shape's bounding rectangle in shape
// order, the broadphase's input. Then Q query shapes drawn the same way (Q / 2 of each kind).
struct Shapes2dWorkload {
  CircleStream circles;              // shape 2k
  OrientedRectStream orientedRects;  // shape 2k + 1
  RectStream bounds;                 // shape i's bounding rectangle
  std::vector<Circle> queryCircles;
  std::vector<OrientedRect> queryOrientedRects;
};
Shapes2dWorkload makeShapes2dWorkload(std::size_t shapes, std::size_t queries = 256);

// The reference figures of W7: overlapping pairs of bounding rectangles (closed), and how many of
// them collide (intersects() on the shapes themselves).
struct Shapes2dReference {
  std::size_t shapes;
  std::uint64_t boundPairs, collidingPairs;
};
const Shapes2dReference& shapes2dReference(std::size_t shapes);  // throws Error if not listed
// The narrowphase: how many of the candidate pairs (shape indices) intersect.
std::uint64_t collidingPairs(const Shapes2dWorkload& w, std::span<const Pair> candidates);

}  // namespace simdphys::workloads

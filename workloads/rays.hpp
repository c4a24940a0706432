// W2 `rays` (../shared/WORKLOADS.md): the heightfield mesh, the two ray sets, the reference
// figures, and a double-precision walk over the grid that gives each ray's reference hit.
// Compiled without floating-point contraction, like every workload generator.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/mesh.hpp"
#include "simdphys/mesh_bvh.hpp"

namespace simdphys::workloads {

inline constexpr std::uint32_t kRaysGrid = 513;  // G: 524,288 triangles
inline constexpr std::uint32_t kCameraWidth = 1024, kCameraHeight = 768;
inline constexpr std::size_t kIncoherentRays = 1'000'000;

// The heightfield of G x G vertices over [-100, 100]^2 (x, z), W2's heights and triangle order.
Mesh makeHeightfield(std::uint32_t g = kRaysGrid);
// W2's height function, in double.
double heightfieldHeight(double x, double z);

// rays/coherent: the pinhole camera's 1024 x 768 rays in scanline order; rays/incoherent: seed 2,
// `n` rays. tMax = infinity for all.
RayStream makeCoherentRays(std::uint32_t width = kCameraWidth,
                           std::uint32_t height = kCameraHeight);
RayStream makeIncoherentRays(std::size_t n = kIncoherentRays);

struct RaysReference {
  std::uint64_t hits;
  double sumT;
  std::uint64_t sumId;
};
// W2's figures for G = 513: exact hits and id sums; sum t is given to 8 significant digits.
inline constexpr RaysReference kCoherentReference{468'848, 5.7717072e7, 68'007'914'670ull};
inline constexpr RaysReference kIncoherentReference{295'892, 1.5857945e7, 77'579'130'893ull};
// Sum t agrees with the reference when within this relative difference: the figure's 8 digits.
inline constexpr double kSumTTolerance = 1e-7;

// The figures of a set of hits: hits, sum of t (in double), sum of ids (64 bits).
RaysReference summarise(std::span<const ElementHit> hits);

// A ray's hit from the double-precision walk: its t, the triangle, and the distance of the hit
// point from the triangle's nearest edge (W2 excuses a disagreement when it is below 1e-5).
struct ReferenceHit {
  std::uint32_t id = kNoHit;
  double t = 0;
  double edgeDistance = 0;
};
// Walks the grid cells the ray crosses (in x, z) in double, testing each cell's two triangles
// with the watertight test in double (vertices and ray exactly as the floats given), W2's tie rule
// (within 1e-6 relative, the smaller id). `g` is the heightfield's G; `mesh` must be
// makeHeightfield(g).
ReferenceHit referenceHit(const Mesh& mesh, std::uint32_t g, const Ray& ray);
std::vector<ReferenceHit> referenceHits(const Mesh& mesh, std::uint32_t g, const RayStream& rays);

// How many rays' answers differ from the reference (hit or miss, or the triangle), not counting
// rays whose reference hit lies within 1e-5 of an edge; and the largest relative difference of t
// over rays that hit the same triangle.
struct ReferenceComparison {
  std::size_t differ = 0, excused = 0;
  double maxRelativeT = 0;
};
ReferenceComparison compareWithReference(std::span<const ElementHit> hits,
                                         std::span<const ReferenceHit> reference);

}  // namespace simdphys::workloads

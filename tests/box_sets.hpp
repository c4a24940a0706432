// Box sets for the BVH and broadphase tests: random ones and named hard cases; the pair oracles.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "simdphys/broadphase.hpp"
#include "simdphys/bvh.hpp"
#include "simdphys/geometry2d/broadphase.hpp"
#include "simdphys/geometry2d/collisions.hpp"
#include "workloads.hpp"

namespace simdphys::test {

struct BoxSet {
  std::string name;
  BoxStream boxes;
};

inline BoxStream randomBoxes(std::uint64_t seed, std::size_t n, float spread, float minHalf,
                             float maxHalf, Vec3f offset = Vec3f::Zero()) {
  workloads::Random r(seed);
  BoxStream boxes;
  for (std::size_t i = 0; i < n; ++i) {
    Vec3f c(r.uniform(-spread, spread), r.uniform(-spread, spread), r.uniform(-spread, spread));
    Vec3f h(r.uniform(minHalf, maxHalf), r.uniform(minHalf, maxHalf), r.uniform(minHalf, maxHalf));
    c += offset;
    boxes.push({c - h, c + h});
  }
  return boxes;
}

inline std::vector<BoxSet> hardBoxSets() {
  std::vector<BoxSet> sets;
  // Unit cubes on a unit lattice: every neighbour only touches (shared faces, edges, corners).
  BoxStream lattice;
  for (int x = 0; x < 9; ++x)
    for (int y = 0; y < 9; ++y)
      for (int z = 0; z < 9; ++z)
        lattice.push({Vec3f(float(x), float(y), float(z)), Vec3f(x + 1.0f, y + 1.0f, z + 1.0f)});
  sets.push_back({"touching_lattice", std::move(lattice)});
  // Points (zero-size boxes), some coincident, some on other boxes' faces.
  BoxStream points;
  workloads::Random r(11);
  for (int i = 0; i < 600; ++i) {
    Vec3f p(float(int(r.uniform(0, 6))), float(int(r.uniform(0, 6))), float(int(r.uniform(0, 6))));
    points.push({p, p});
    if (i % 3 == 0) points.push({p, p + Vec3f::Ones()});
  }
  sets.push_back({"zero_size_boxes", std::move(points)});
  // Far from the origin, tiny: at 1e5 a float step is 0.0078, so extents of 1e-2 are one ulp.
  sets.push_back({"far_tiny", randomBoxes(12, 1500, 0.5f, 0.0f, 0.01f, Vec3f(1e5f, -1e5f, 1e5f))});
  // All boxes the same: the SAH finds no split and the build must still terminate, balanced.
  BoxStream same;
  for (int i = 0; i < 700; ++i) same.push({Vec3f::Zero(), Vec3f::Ones()});
  sets.push_back({"identical", std::move(same)});
  // Very mixed sizes: a few huge boxes spanning every grid cell among small ones.
  BoxStream mixed = randomBoxes(13, 1500, 50, 0.1f, 2);
  for (int i = 0; i < 5; ++i) mixed.push({Vec3f::Constant(-60.0f + i), Vec3f::Constant(60.0f - i)});
  sets.push_back({"huge_among_small", std::move(mixed)});
  // Everything on one plane (flat along y): the grid has a single row.
  BoxStream flat;
  for (int i = 0; i < 1000; ++i) {
    float x = float(i % 40), z = float(i / 40);
    flat.push({Vec3f(x, 0, z), Vec3f(x + 1.5f, 0, z + 1.5f)});
  }
  sets.push_back({"flat", std::move(flat)});
  return sets;
}

// Brute force, in the order (a, b) sorted: the oracle, for boxes and for rectangles (overlaps(),
// the closed test: intersects(Rect, Rect) in 2D).
template <class Stream>
std::vector<Pair> bruteForcePairs(const Stream& s) {
  std::vector<Pair> pairs;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    for (std::uint32_t j = i + 1; j < s.size(); ++j)
      if (overlaps(s[i], s[j])) pairs.push_back({i, j});
  return pairs;
}

}  // namespace simdphys::test

// Physical measures of a running world: the figures the standard workloads report
// (docs/workloads.md), taken for any world: a workload's scene file gives the workload's figures,
// and any other scene is judged the same way (docs/cli.md).
//  - rigid bodies (W5): each body's largest distance from where it started, whether every body is
//    within 0.5 m of its start ("standing"), the deepest contact penetration over all steps;
//  - cloths (W3): the relative stretch |l - l0| / l0 of the structural springs (a grid's
//    neighbours along x and z, a network's every spring), mean, nearest-rank 99th percentile and
//    maximum, the maximum also over springs that touch no pinned particle; the deepest any
//    particle went into a solid obstacle (plane, sphere, box) over all steps;
//  - particles (W4): how many end inside an obstacle, the mean height;
//  and whether every position stayed finite. Measures are computed in double.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "simdphys/world.hpp"

namespace simdphys {

// Stretch of springs (a, b, rest > 0) at `positions`; pinned: invMass 0. A non-finite length
// counts as an infinite stretch. All zero for no springs.
struct Stretch {
  double mean = 0, p99 = 0, max = 0, maxAwayFromPins = 0;
};
Stretch stretchOf(std::span<const Spring> springs, std::span<const Vec3f> positions,
                  std::span<const float> invMass);

// How far `p` lies inside the solid `shape` (0 outside; meshes have no inside), in double.
double depthInside(const ObstacleShape& shape, const Vec3f& p);

struct BodyMeasures {
  std::size_t count = 0;
  double maxDisplacement = 0;     // m, from each body's start
  bool standing = true;           // every body within 0.5 m of its start
  double deepestPenetration = 0;  // m, the largest contact depth over the steps observed
  bool finite = true;
};
struct ClothMeasures {
  std::size_t particles = 0, springs = 0;  // springs: those the stretch is taken over
  Stretch stretch;
  double deepestPenetration = 0;  // m, into the world's solid obstacles, over the steps observed
  bool finite = true;
};
struct ParticleMeasures {
  std::size_t count = 0, inside = 0;  // inside: strictly inside an obstacle now
  double meanHeight = 0;              // m, the mean y
  bool finite = true;
};
struct WorldMeasures {
  BodyMeasures bodies;
  std::vector<ClothMeasures> cloths;        // in the world's order
  std::vector<ParticleMeasures> particles;  // in the world's order
};

// Watches a world from its start: construct it before the first step (it records the bodies'
// starting positions and the cloths' rest lengths), call observe() after every step.
class WorldMonitor {
 public:
  explicit WorldMonitor(const World& world);
  void observe(const World& world);
  WorldMeasures measure(const World& world) const;

 private:
  std::vector<Handle> bodies_;
  std::vector<Vec3f> bodyStart_;
  std::vector<std::vector<Spring>> clothSprings_;  // per cloth, in particle indices
  double deepestBody_ = 0;
  std::vector<double> deepestCloth_;
};

}  // namespace simdphys

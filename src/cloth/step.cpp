// Stepping a cloth on the active path (step.hpp).
#include "src/cloth/step.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <omp.h>

#include "simd/kernels.hpp"
#include "src/cloth/internals.hpp"
#include "src/core/on_path.hpp"
#include "src/reference/cloth/step-inl.hpp"
#include "src/world/obstacle_rows.hpp"

namespace simdphys::detail {

using S = core::ClothStreams;
using Internals = Cloth::Internals;

std::vector<core::ObstacleRow> clothRows(const Obstacles& obstacles) {
  std::vector<core::ObstacleRow> rows = obstacleRows(obstacles);
  for (core::ObstacleRow& row : rows) {
    if (row.kind != core::ObstacleRow::kAabb) continue;
    // An AABB as an OBB of identity axes: one box test.
    const Aabb box{Vec3f(row.v[0], row.v[1], row.v[2]), Vec3f(row.v[3], row.v[4], row.v[5])};
    row = rowOf(Obb{box.center(), box.halfExtents(), Mat3f::Identity()});
  }
  return rows;
}

int clothSubsteps(const Cloth& cloth, float dt, const std::string& where) {
  const ClothSettings& s = cloth.settings();
  if (s.model != ClothModel::kMassSpring) return s.substeps;
  // Semi-implicit Euler on x'' = -w2 x - g x' is stable for h^2 w2 + 2 h g <= 4; the bound
  // asked here keeps a fifth of that in hand, with Gershgorin bounds for w2 and g.
  const double w2 = Internals::rate2(cloth) + Internals::maxInvMass(cloth) * double(s.penalty),
               g = Internals::dampRate(cloth);
  if (std::isinf(w2))
    throw Error(where +
                ": the mass-spring model cannot step a rigid spring (stiffness kRigid); "
                "give it a stiffness or use ClothModel::kXpbd");
  const double limit = 0.8 * 4;
  const double hMax = w2 > 0  ? (-g + std::sqrt(g * g + limit * w2)) / w2
                      : g > 0 ? limit / (2 * g)
                              : HUGE_VAL;
  const double needed = std::ceil(double(dt) / hMax);
  if (needed > ClothSettings::kMaxSubsteps)
    throw Error(where + ": the mass-spring model needs " + std::to_string(needed) +
                " substeps for its stiffest spring at this time step (the explicit stability "
                "bound, h < about 2 sqrt(m / k)), more than ClothSettings::kMaxSubsteps; lower "
                "the stiffness or the time step, or use ClothModel::kXpbd");
  return std::max(s.substeps, int(needed));
}

core::ClothStepParams clothParams(const Cloth& cloth, float dt, int substeps) {
  const ClothSettings& s = cloth.settings();
  core::ClothStepParams p{};
  p.model = std::uint32_t(s.model);
  p.substeps = substeps;
  p.h = dt / float(substeps);
  p.invH = 1.0f / p.h;
  p.invH2 = 1.0f / (p.h * p.h);
  p.keep = std::max(0.0f, 1.0f - s.damping * p.h);
  for (int k = 0; k < 3; ++k) p.gravity[k] = s.gravity[k];
  p.margin = s.penalty > 0 ? 0.0f : s.margin, p.friction = s.friction;
  p.penalty = s.penalty, p.zone = s.margin;
  p.damped = Internals::damped(cloth);
  return p;
}

std::size_t stepCloth(Cloth& cloth, const Obstacles& obstacles,
                      std::span<const core::ObstacleRow> rows, float dt, int substeps, int threads,
                      const std::string& where) {
  const core::ClothView<float> v = Internals::view(cloth);
  // The positions and velocities kept to undo a step that would leave the supported range.
  std::vector<float> kept(6 * v.slots);
  for (std::size_t f = 0; f < 6; ++f)
    std::copy_n(v.s[S::x + f], v.slots, kept.data() + f * v.slots);
  const core::ClothStepParams params = clothParams(cloth, dt, substeps);
  const core::SpringNetwork net = Internals::network(cloth);
  const core::Tethers tethers = Internals::tethers(cloth);
  const std::optional<core::ObstacleQueries> queries = obstacleQueries(obstacles);
  const core::ObstacleQueries* q = queries ? &*queries : nullptr;
  if (referencePathActive()) {
    reference::stepCloth<float>(v, net, tethers, rows, q, params);
  } else {
    const core::SpringGrid grid = Internals::grid(cloth);
    const auto& kernel = plainLoopsActive() ? simd::stepClothAutovec : simd::stepCloth;
    // A small cloth's passes are shorter than the threads' start and barriers.
    const int t = v.slots < 8192 ? 1 : threads > 0 ? threads : omp_get_max_threads();
    kernel({v, net, cloth.isGrid() ? &grid : nullptr, tethers, rows.data(), rows.size(), q,
            Internals::quads(cloth), params, t});
  }
  for (std::size_t f = 0; f < 6; ++f)
    for (std::size_t i = 0; i < v.slots; ++i)
      if (!(std::abs(v.s[S::x + f][i]) <= kMaxCoordinate)) {
        const float bad = v.s[S::x + f][i];
        for (std::size_t g = 0; g < 6; ++g)
          std::copy_n(kept.data() + g * v.slots, v.slots, v.s[S::x + g]);
        throw Error(where + ": the step would take particle " +
                    std::to_string(Internals::particleOf(cloth, i)) + "'s " +
                    (f < 3 ? "position" : "velocity") + " to " + std::to_string(bad) +
                    ", outside the supported range; nothing moved");
      }
  Internals::refit(cloth);
  return cloth.springs().size() * std::size_t(substeps);
}

}  // namespace simdphys::detail

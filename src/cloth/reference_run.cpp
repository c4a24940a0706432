// testing/cloth.hpp: a cloth stepped by the double-precision reference.
#include <cmath>

#include "src/cloth/internals.hpp"
#include "src/cloth/step.hpp"
#include "src/reference/cloth/step-inl.hpp"
#include "src/world/obstacle_rows.hpp"
#include "testing/cloth.hpp"

namespace simdphys::test {

using Internals = Cloth::Internals;

ClothD::ClothD(const Cloth& cloth) {
  const core::ClothView<float> v = Internals::view(const_cast<Cloth&>(cloth));
  for (std::size_t f = 0; f < core::ClothStreams::kCount; ++f)
    s_.emplace_back(v.s[f], v.s[f] + v.slots);
}

void ClothD::step(const Cloth& cloth, const World& world) {
  core::ClothView<double> v{{}, s_[0].size()};
  for (std::size_t f = 0; f < core::ClothStreams::kCount; ++f) v.s[f] = s_[f].data();
  const std::vector<core::ObstacleRow> rows = detail::clothRows(world.obstacles());
  const std::optional<core::ObstacleQueries> q = detail::obstacleQueries(world.obstacles());
  const WorldSettings& w = world.settings();
  const float dt = w.timeStep / float(w.substeps);
  const int substeps = detail::clothSubsteps(cloth, dt, "test::ClothD::step");
  for (int sub = 0; sub < w.substeps; ++sub)
    reference::stepCloth<double>(v, Internals::network(cloth), Internals::tethers(cloth), rows,
                                 q ? &*q : nullptr, detail::clothParams(cloth, dt, substeps));
}

std::vector<Vec3d> ClothD::positions(const Cloth& cloth) const {
  std::vector<Vec3d> out;
  for (std::uint32_t i = 0; i < cloth.size(); ++i) {
    const std::size_t p = Internals::slotOf(cloth, i);
    out.emplace_back(s_[0][p], s_[1][p], s_[2][p]);
  }
  return out;
}

PositionError positionError(const std::vector<Vec3f>& a, const std::vector<Vec3d>& b) {
  PositionError e;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = (a[i].cast<double>() - b[i]).norm();
    e.max = std::max(e.max, d), e.rms += d * d;
  }
  e.rms = a.empty() ? 0 : std::sqrt(e.rms / double(a.size()));
  return e;
}

}  // namespace simdphys::test

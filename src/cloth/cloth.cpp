// Cloth (cloth.hpp): validation, the colouring of a spring network, the grid's families, the
// tethers, and the particle accessors.
#include "simdphys/cloth.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <tuple>

#include "src/cloth/internals.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

using S = core::ClothStreams;

const char* toString(ClothModel model) {
  switch (model) {
    case ClothModel::kXpbd:
      return "XPBD";
    case ClothModel::kMassSpring:
      return "mass-spring";
  }
  return "unknown cloth model";
}

void validate(const ClothSettings& s, const std::string& where) {
  using detail::require;
  const auto m = unsigned(s.model);
  require(m <= unsigned(ClothModel::kMassSpring), m, where, "model", "not a ClothModel");
  detail::requireFiniteField(s.gravity, where, "gravity");
  require(s.substeps >= 1 && s.substeps <= ClothSettings::kMaxSubsteps, s.substeps, where,
          "substeps", "must be in [1, ClothSettings::kMaxSubsteps]");
  require(s.damping >= 0 && std::isfinite(s.damping), s.damping, where, "damping",
          "must be finite and >= 0");
  require(s.margin > 0 && s.margin <= 1, s.margin, where, "margin", "must be in (0, 1] m");
  require(s.friction >= 0 && std::isfinite(s.friction), s.friction, where, "friction",
          "must be finite and >= 0");
  require(s.penalty >= 0 && std::isfinite(s.penalty), s.penalty, where, "penalty",
          "must be finite and >= 0");
  require(s.penalty == 0 || s.model == ClothModel::kMassSpring, s.penalty, where, "penalty",
          "needs ClothModel::kMassSpring (penalty springs are forces)");
}

namespace {

std::string springWhere(const std::string& where, std::size_t k) {
  return where + ": spring " + std::to_string(k);
}

void validateSpring(const Spring& s, std::size_t count, const std::string& where) {
  using detail::require;
  require(s.a < count, s.a, where, "a", "is not a particle index");
  require(s.b < count, s.b, where, "b", "is not a particle index");
  require(s.a != s.b, s.a, where, "b", "joins the particle to itself");
  detail::requireInRange(s.rest, where, "rest");
  require(s.rest >= 0, s.rest, where, "rest", "must be >= 0");
  require(s.stiffness > 0 && !std::isnan(s.stiffness), s.stiffness, where, "stiffness",
          "must be > 0 (or kRigid)");
  require(s.stiffness == kRigid || detail::inSupportedRange(s.stiffness), s.stiffness, where,
          "stiffness", "is finite and outside the supported range (or kRigid)");
  detail::requireInRange(s.damping, where, "damping");
  require(s.damping >= 0, s.damping, where, "damping", "must be >= 0");
}

// Greedy colouring: the lowest colour none of the spring's particles has yet.
std::vector<std::uint32_t> colour(std::span<const Spring> springs, std::size_t count) {
  std::vector<std::vector<std::uint32_t>> used(count);
  std::vector<std::uint32_t> batch(springs.size());
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const auto& ua = used[springs[k].a];
    const auto& ub = used[springs[k].b];
    std::uint32_t c = 0;
    while (std::find(ua.begin(), ua.end(), c) != ua.end() ||
           std::find(ub.begin(), ub.end(), c) != ub.end())
      ++c;
    batch[k] = c;
    used[springs[k].a].push_back(c);
    used[springs[k].b].push_back(c);
  }
  return batch;
}

// The rest length between two float positions: in double, rounded once.
float restLength(const Vec3f& a, const Vec3f& b) {
  return float((a.cast<double>() - b.cast<double>()).norm());
}

}  // namespace

Cloth::Cloth(std::span<const Vec3f> positions, std::span<const float> invMass,
             std::span<const Spring> springs, const ClothSettings& settings,
             std::span<const std::uint32_t> batches) {
  const std::string where = "Cloth";
  validate(settings, where);
  settings_ = settings;
  springs_.assign(springs.begin(), springs.end());
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const Spring& x = springs[k];
    const bool ok = x.a < positions.size() && x.b < positions.size() && x.a != x.b && x.rest >= 0 &&
                    x.rest <= kMaxCoordinate && x.stiffness > 0 &&
                    (x.stiffness == kRigid || x.stiffness <= kMaxCoordinate) && x.damping >= 0 &&
                    x.damping <= kMaxCoordinate;
    if (!ok) validateSpring(x, positions.size(), springWhere(where, k));  // throws, saying why
  }
  build(positions, invMass, batches);
}

Cloth Cloth::grid(const ClothGrid& g, const ClothSettings& settings) {
  const std::string where = "Cloth::grid";
  detail::require(g.nx >= 2 && g.nz >= 2, g.nx < 2 ? g.nx : g.nz, where, g.nx < 2 ? "nx" : "nz",
                  "must be >= 2");
  detail::require(g.positions.size() == g.nx * g.nz, g.positions.size(), where, "positions.size()",
                  "must be nx * nz");
  const SpringKindSettings kinds[3] = {g.structural, g.shear, g.bend};
  for (int k = 0; k < 3; ++k)
    validateSpring({0, 1, 0, kinds[k].stiffness, kinds[k].damping}, 2,
                   where + (k == 0   ? ": structural"
                            : k == 1 ? ": shear"
                                     : ": bend"));
  validate(settings, where);
  Cloth c;
  c.settings_ = settings;
  c.nx_ = g.nx, c.nz_ = g.nz;
  c.stride_ = paddedSize(g.nx);
  for (int k = 0; k < 3; ++k) c.kinds_[k] = kinds[k];
  // The springs family by family, each as its two colours (core::SpringGrid): batch 2 f + c.
  std::vector<std::uint32_t> batches;
  for (std::uint32_t f = 0; f < core::SpringGrid::kFamilies; ++f) {
    const int di[] = {1, 0, 1, -1, 2, 0}, dj[] = {0, 1, 1, 1, 0, 2};
    for (std::uint32_t colour = 0; colour < 2; ++colour)
      for (std::size_t j = 0; j + dj[f] < g.nz; ++j)
        for (std::size_t i = 0; i < g.nx; ++i) {
          const std::ptrdiff_t i2 = std::ptrdiff_t(i) + di[f];
          if (i2 < 0 || i2 >= std::ptrdiff_t(g.nx)) continue;
          const std::size_t along = dj[f] == 0 ? i : j;  // what the family's colours alternate on
          if ((f == core::SpringGrid::kBendX || f == core::SpringGrid::kBendZ ? along / 2 : along) %
                  2 !=
              colour)
            continue;
          const auto a = std::uint32_t(j * g.nx + i), b = std::uint32_t((j + dj[f]) * g.nx + i2);
          const SpringKindSettings& kind = kinds[core::SpringGrid::kKind[f]];
          c.springs_.push_back(
              {a, b, restLength(g.positions[a], g.positions[b]), kind.stiffness, kind.damping});
          batches.push_back(2 * f + colour);
        }
  }
  for (std::size_t k = 0; k < c.springs_.size(); ++k)
    if (!(c.springs_[k].rest <= kMaxCoordinate))
      detail::requireInRange(c.springs_[k].rest, springWhere(where, k), "rest");
  c.build(g.positions, g.invMass, batches);
  return c;
}

void Cloth::build(std::span<const Vec3f> positions, std::span<const float> invMass,
                  std::span<const std::uint32_t> given) {
  const std::string where = "Cloth";
  using detail::require;
  count_ = positions.size();
  require(invMass.size() == count_, invMass.size(), where, "invMass.size()",
          "must be the number of positions");
  for (std::size_t i = 0; i < count_; ++i) {
    const bool ok = (positions[i].array().abs() <= kMaxCoordinate).all() && invMass[i] >= 0 &&
                    invMass[i] <= kMaxCoordinate;
    if (ok) continue;  // the message is built for a bad value only
    const std::string at = where + ": particle " + std::to_string(i);
    detail::requireFiniteField(positions[i], at, "position");
    detail::requireInRange(invMass[i], at, "invMass");
    require(invMass[i] >= 0, invMass[i], at, "invMass", "must be >= 0");
  }
  std::vector<std::uint32_t> batches(given.begin(), given.end());
  if (given.empty()) {
    batches = colour(springs_, count_);
  } else {
    require(given.size() == springs_.size(), given.size(), where, "batches.size()",
            "must be the number of springs");
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;  // (batch, particle)
    for (std::size_t k = 0; k < springs_.size(); ++k)
      ends.push_back({given[k], springs_[k].a}), ends.push_back({given[k], springs_[k].b});
    std::sort(ends.begin(), ends.end());
    const auto twice = std::adjacent_find(ends.begin(), ends.end());
    if (twice != ends.end())
      throw Error(where + ": particle " + std::to_string(twice->second) +
                  " has two springs in batch " + std::to_string(twice->first));
  }
  // Springs batch after batch, in the order given within a batch.
  std::vector<std::uint32_t> order(springs_.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t p, std::uint32_t q) { return batches[p] < batches[q]; });
  std::vector<Spring> sorted;
  batchOf_.clear();
  for (const std::uint32_t k : order) sorted.push_back(springs_[k]), batchOf_.push_back(batches[k]);
  springs_ = std::move(sorted);
  const std::uint32_t nb = batchOf_.empty() ? 0 : batchOf_.back() + 1;
  batchBegin_.assign(nb + 1, 0);
  for (const std::uint32_t b : batchOf_) ++batchBegin_[b + 1];
  for (std::uint32_t b = 0; b < nb; ++b) batchBegin_[b + 1] += batchBegin_[b];

  // Streams over slots, with room past the last for the grid kernels' shifted reads.
  slots_ = isGrid() ? stride_ * nz_ : paddedSize(count_);
  const std::size_t room = slots_ + (isGrid() ? 2 * stride_ : 0) + 2 * kStreamPad;
  for (auto& field : s_) field.assign(room, 0.0f);
  if (!isGrid()) quads_.assign(4 * room, 0.0f);
  for (std::uint32_t i = 0; i < count_; ++i) {
    const std::uint32_t p = slot(i, "Cloth");
    for (int k = 0; k < 3; ++k) s_[S::x + k][p] = s_[S::px + k][p] = positions[i][k];
    s_[S::w][p] = invMass[i];
  }
  sa_.clear(), sb_.clear(), sRest_.clear(), sCompliance_.clear(), sStiffness_.clear();
  sDamping_.clear();
  for (const Spring& s : springs_) {
    sa_.push_back(slot(s.a, "Cloth")), sb_.push_back(slot(s.b, "Cloth"));
    sRest_.push_back(s.rest), sStiffness_.push_back(s.stiffness), sDamping_.push_back(s.damping);
    sCompliance_.push_back(s.stiffness == kRigid ? 0.0f : 1.0f / s.stiffness);
  }
  // Room for a whole vector past the last spring (its lanes read slot 0 and are never written).
  sa_.resize(sa_.size() + kStreamPad, 0), sb_.resize(sb_.size() + kStreamPad, 0);
  for (auto* f : {&sRest_, &sCompliance_, &sStiffness_, &sDamping_})
    f->resize(f->size() + kStreamPad, 0.0f);
  if (isGrid()) {
    for (auto& rest : gridRest_) rest.assign(room, -1.0f);
    for (std::size_t k = 0; k < springs_.size(); ++k)
      gridRest_[batchOf_[k] / 2][sa_[k]] = springs_[k].rest;
  }

  // Stability rates (Gershgorin, over M^-1 K): per particle the sum over its springs.
  std::vector<double> rate2(count_), damp(count_);
  for (const Spring& s : springs_) {
    const double w = std::max(invMass[s.a], invMass[s.b]);
    for (const std::uint32_t p : {s.a, s.b})
      rate2[p] += 2 * w * double(s.stiffness), damp[p] += 2 * w * double(s.damping);
  }
  rate2_ = dampRate_ = 0;
  maxInvMass_ = invMass.empty() ? 0.0 : double(*std::max_element(invMass.begin(), invMass.end()));
  damped_ =
      std::any_of(springs_.begin(), springs_.end(), [](const Spring& s) { return s.damping != 0; });
  for (std::size_t i = 0; i < count_; ++i)
    if (invMass[i] > 0)
      rate2_ = std::max(rate2_, rate2[i]), dampRate_ = std::max(dampRate_, damp[i]);

  // Tethers: each free particle to the pinned one nearest along the rigid springs (Dijkstra from
  // all pins at once, ties to the lower pin), at their straight rest distance.
  anchor_.assign(room, 0), tether_.assign(room, -1.0f);
  for (std::uint32_t p = 0; p < room; ++p) anchor_[p] = p;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> edges(count_);
  for (const Spring& s : springs_)  // along rigid springs only: a soft one may stretch
    if (s.stiffness == kRigid)
      edges[s.a].push_back({s.b, s.rest}), edges[s.b].push_back({s.a, s.rest});
  using Item = std::tuple<double, std::uint32_t, std::uint32_t>;  // distance, pin, particle
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  std::vector<double> dist(count_, HUGE_VAL);
  std::vector<std::uint32_t> pin(count_, std::uint32_t(-1));
  for (std::uint32_t i = 0; i < count_; ++i)
    if (invMass[i] == 0) open.push({0.0, i, i});
  while (!open.empty()) {
    const auto [d, from, i] = open.top();
    open.pop();
    if (pin[i] != std::uint32_t(-1)) continue;
    pin[i] = from, dist[i] = d;
    for (const auto& [j, rest] : edges[i])
      if (pin[j] == std::uint32_t(-1)) open.push({d + rest, from, j});
  }
  for (std::uint32_t i = 0; i < count_; ++i) {
    if (invMass[i] == 0 || pin[i] == std::uint32_t(-1)) continue;
    anchor_[slot(i, "Cloth")] = slot(pin[i], "Cloth");
    tether_[slot(i, "Cloth")] = restLength(positions[i], positions[pin[i]]);
  }
  refit();
}

std::uint32_t Cloth::slot(std::uint32_t i, const char* where) const {
  detail::require(i < count_, i, where, "particle", "is not a particle index");
  return isGrid() ? std::uint32_t(i / nx_ * stride_ + i % nx_) : i;
}

void Cloth::setSettings(const ClothSettings& settings) {
  validate(settings, "Cloth::setSettings");
  settings_ = settings;
}

Vec3f Cloth::position(std::uint32_t i) const {
  const std::uint32_t p = slot(i, "Cloth::position");
  return {s_[S::x][p], s_[S::y][p], s_[S::z][p]};
}

Vec3f Cloth::velocity(std::uint32_t i) const {
  const std::uint32_t p = slot(i, "Cloth::velocity");
  return {s_[S::vx][p], s_[S::vy][p], s_[S::vz][p]};
}

float Cloth::invMass(std::uint32_t i) const { return s_[S::w][slot(i, "Cloth::invMass")]; }

std::vector<Vec3f> Cloth::positions() const {
  std::vector<Vec3f> out(count_);
  for (std::uint32_t i = 0; i < count_; ++i) out[i] = position(i);
  return out;
}

void Cloth::setPosition(std::uint32_t i, const Vec3f& x) {
  const std::uint32_t p = slot(i, "Cloth::setPosition");
  detail::requireFiniteField(x, "Cloth::setPosition: particle " + std::to_string(i), "position");
  for (int k = 0; k < 3; ++k) s_[S::x + k][p] = s_[S::px + k][p] = x[k];
  refit();
}

void Cloth::setVelocity(std::uint32_t i, const Vec3f& v) {
  const std::uint32_t p = slot(i, "Cloth::setVelocity");
  detail::requireFiniteField(v, "Cloth::setVelocity: particle " + std::to_string(i), "velocity");
  for (int k = 0; k < 3; ++k) s_[S::vx + k][p] = v[k];
}

void Cloth::refit() {
  Vec3f lo = Vec3f::Constant(kMaxCoordinate), hi = -lo;
  const std::size_t rows = isGrid() ? nz_ : 1, width = isGrid() ? nx_ : count_;
  for (std::size_t j = 0; j < rows; ++j)
    for (int k = 0; k < 3; ++k) {
      const float* c = s_[S::x + k].data() + j * stride_;
      for (std::size_t i = 0; i < width; ++i)
        lo[k] = std::min(lo[k], c[i]), hi[k] = std::max(hi[k], c[i]);
    }
  bounds_ = {lo, hi};
}

std::optional<std::uint32_t> Cloth::pick(const Ray& ray, float radius, float maxT) const {
  const std::string where = "Cloth::pick";
  detail::requireFiniteField(ray.origin, where, "ray.origin");
  detail::requireFiniteField(ray.direction, where, "ray.direction");
  detail::require(radius >= 0 && std::isfinite(radius), radius, where, "radius",
                  "must be finite and >= 0");
  const Vec3d o = ray.origin.cast<double>(), dir = ray.direction.cast<double>();
  const double dd = dir.dot(dir);
  if (!(dd > 0)) throw Error(where + ": ray.direction is zero");
  std::optional<std::uint32_t> best;
  double bestT = HUGE_VAL;
  for (std::uint32_t i = 0; i < count_; ++i) {
    const Vec3d p = position(i).cast<double>();
    const double t = std::clamp((p - o).dot(dir) / dd, 0.0, double(maxT));
    if ((o + dir * t - p).squaredNorm() <= double(radius) * radius && t < bestT)
      best = i, bestT = t;
  }
  return best;
}

}  // namespace simdphys

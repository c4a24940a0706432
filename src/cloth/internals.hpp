// The cloth's streams and layouts as the step and its kernels read them (core/cloth_step.hpp).
#pragma once

#include "core/cloth_step.hpp"
#include "simdphys/cloth.hpp"

namespace simdphys {

struct Cloth::Internals {
  static core::ClothView<float> view(Cloth& c) {
    core::ClothView<float> v{{}, c.slots_};
    for (std::size_t f = 0; f < core::ClothStreams::kCount; ++f) v.s[f] = c.s_[f].data();
    return v;
  }
  static core::SpringNetwork network(const Cloth& c) {
    return {
        c.sa_.data(),         c.sb_.data(),       c.sRest_.data(),      c.sCompliance_.data(),
        c.sStiffness_.data(), c.sDamping_.data(), c.batchBegin_.data(), c.batchBegin_.size() - 1};
  }
  static core::SpringGrid grid(const Cloth& c) {
    core::SpringGrid g{};
    for (std::uint32_t f = 0; f < core::SpringGrid::kFamilies; ++f)
      g.rest[f] = c.gridRest_[f].data();
    for (int k = 0; k < 3; ++k) {
      const float stiffness = c.kinds_[k].stiffness;
      g.compliance[k] = stiffness == kRigid ? 0.0f : 1.0f / stiffness;
      g.stiffness[k] = stiffness, g.damping[k] = c.kinds_[k].damping;
    }
    g.stride = c.stride_, g.rows = c.nz_;
    return g;
  }
  static core::Tethers tethers(const Cloth& c) {
    return {c.settings_.tethers ? c.anchor_.data() : nullptr, c.tether_.data()};
  }
  static bool damped(const Cloth& c) { return c.damped_; }
  static float* quads(Cloth& c) { return c.isGrid() ? nullptr : c.quads_.data(); }
  static double rate2(const Cloth& c) { return c.rate2_; }
  static double maxInvMass(const Cloth& c) { return c.maxInvMass_; }
  static double dampRate(const Cloth& c) { return c.dampRate_; }
  static void refit(Cloth& c) { c.refit(); }
  static std::size_t slotOf(const Cloth& c, std::uint32_t particle) {
    return c.slot(particle, "Cloth::Internals::slotOf");
  }
  // The particle in a slot (slots past the particles: none, as count).
  static std::size_t particleOf(const Cloth& c, std::size_t slot) {
    if (!c.isGrid()) return slot;
    const std::size_t i = slot % c.stride_, j = slot / c.stride_;
    return i < c.nx_ && j < c.nz_ ? j * c.nx_ + i : c.count_;
  }
};

}  // namespace simdphys

// Test support: the book's per-object culling test in a loop, in any precision (the library culls
// with the same test on its reference path; double is the truth the benchmarks measure float
// against). Internal: not installed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "simdphys/scene/frustum.hpp"

namespace simdphys::reference {

template <class T>
std::size_t cullSpheres(const FrustumT<T>& f, std::span<const T> x, std::span<const T> y,
                        std::span<const T> z, std::span<const T> r,
                        std::vector<std::uint32_t>& visible) {
  visible.clear();
  for (std::size_t i = 0; i < x.size(); ++i)
    if (f.intersectsSphere({x[i], y[i], z[i]}, r[i])) visible.push_back(std::uint32_t(i));
  return visible.size();
}

template <class T>
std::size_t cullBoxes(const FrustumT<T>& f, std::span<const T> cx, std::span<const T> cy,
                      std::span<const T> cz, std::span<const T> ex, std::span<const T> ey,
                      std::span<const T> ez, std::vector<std::uint32_t>& visible) {
  visible.clear();
  for (std::size_t i = 0; i < cx.size(); ++i)
    if (f.intersectsBox({cx[i], cy[i], cz[i]}, {ex[i], ey[i], ez[i]}))
      visible.push_back(std::uint32_t(i));
  return visible.size();
}

}  // namespace simdphys::reference

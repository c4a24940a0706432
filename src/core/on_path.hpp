// Running an operation on the active path (core.hpp): the scalar reference or the dispatched SIMD
// kernel. Every batch query goes through here, so a new one writes only its two forms.
#pragma once

#include <cstdint>
#include <vector>

#include "core/view.hpp"
#include "simdphys/core.hpp"

namespace simdphys {

// The indices of the elements of stream view `v` that an operation selects, ascending in `out`,
// their number returned: on the reference path `test(i)` element by element, otherwise
// `kernel(v, room)` writing them into room for v.padded indices (kernels store whole vectors).
template <class Fields, class Test, class Kernel>
std::size_t selectOnPath(const core::View<Fields>& v, std::vector<std::uint32_t>& out, Test test,
                         Kernel kernel) {
  out.clear();
  if (referencePathActive()) {
    for (std::uint32_t i = 0; i < v.count; ++i)
      if (test(i)) out.push_back(i);
    return out.size();
  }
  out.resize(v.padded);
  out.resize(kernel(v, out.data()));
  return out.size();
}

namespace detail {
// While set (testing/pairs.hpp, for the tests and the benchmarks' second baseline), kernels run
// as the plain loops left to the auto-vectoriser: the pair finders' on the best SIMD target,
// whatever the active path; the particle step's on the active path if it is a SIMD one. Not
// thread-safe, as setPath() is not.
bool plainLoopsActive();
void setPlainLoops(bool on);
}  // namespace detail

}  // namespace simdphys

// Floating-point helpers shared by the scalar reference and the SIMD kernels (simd/): Eigen-free
// and intrinsic-free, so both may include them and compute the same bits. A public header only
// because raycast.hpp's templates still use them; once those are compiled in src/, this belongs
// in core/.
#pragma once

#include <cmath>
#include <type_traits>

namespace simdphys::detail {

// a * b - c * d with the sign exact when the rounded result is 0 (the only case in which the
// watertight ray-triangle test needs more): float recomputes in double, where the products are
// exact; double adds the exact remainders of its products (fma), whose difference is then the
// exact one. Separate statements keep Clang's default contraction (within an expression) from
// fusing a product into the subtraction; GCC's -ffp-contract=fast would still do it, which is why
// the library is built with -ffp-contract=off.
template <class T>
T differenceOfProducts(T a, T b, T c, T d) {
  const T ab = a * b;
  const T cd = c * d;
  const T r = ab - cd;
  if (r != 0) return r;
  if constexpr (std::is_same_v<T, float>) {
    const double abd = double(a) * double(b);
    const double cdd = double(c) * double(d);
    return T(abd - cdd);
  } else {
    return std::fma(a, b, -ab) - std::fma(c, d, -cd);
  }
}

}  // namespace simdphys::detail

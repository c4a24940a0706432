// Box-box manifolds (rigid/manifold.hpp): to be written.
#pragma once

#include "src/reference/rigid/manifold-inl.hpp"

namespace simdphys {

template <class T>
ManifoldT<T> collide(const ObbT<T>&, const ObbT<T>&, T) {
  return {};
}

}  // namespace simdphys

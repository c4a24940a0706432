// primitives.hpp, compiled once: validate and the named constructor of the shapes 2D and 3D
// share, for float and double in both dimensions.
#include "simdphys/primitives.hpp"

#include "src/reference/math-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

template <class T, int N>
void validate(const SegmentN<T, N>& s, std::string_view where) {
  detail::requireFiniteField(s.start, where, "start");
  detail::requireFiniteField(s.end, where, "end");
}

template <class T, int N>
void validate(const RayN<T, N>& r, std::string_view where) {
  detail::requireFiniteField(r.origin, where, "origin");
  detail::requireFiniteField(r.direction, where, "direction");
  detail::requireUnit(r.direction, where, "direction");
}

template <class T, int N>
void validate(const BallN<T, N>& b, std::string_view where) {
  detail::requireBall(b.center, b.radius, where);
}

template <class T, int N>
void validate(const BoxN<T, N>& b, std::string_view where) {
  detail::requireFiniteField(b.min, where, "min");
  detail::requireFiniteField(b.max, where, "max");
  detail::requireOrdered(b.min, b.max, where);
}

// Any finite non-zero offset works: unitOr (math.hpp) scales it before taking its length. The
// errors name the type as users spell it (Ray2, Ray).
template <class T, int N>
RayN<T, N> RayN<T, N>::fromTo(const VecN<T, N>& origin, const VecN<T, N>& target) {
  constexpr const char* where = N == 2 ? "Ray2::fromTo" : "Ray::fromTo";
  detail::requireFiniteField(origin, where, "origin");
  detail::requireFiniteField(target, where, "target");
  const VecN<T, N> d = target - origin;
  if ((d.array() == 0).all()) throw Error(std::string(where) + ": origin and target coincide");
  return {origin, detail::unitOr(d, VecN<T, N>::Zero().eval())};
}

#define SIMDPHYS_INSTANTIATE_PRIMITIVES(T, N)                              \
  template void validate(const SegmentN<T, N>& s, std::string_view where); \
  template void validate(const RayN<T, N>& r, std::string_view where);     \
  template void validate(const BallN<T, N>& b, std::string_view where);    \
  template void validate(const BoxN<T, N>& b, std::string_view where);     \
  template RayN<T, N> RayN<T, N>::fromTo(const VecN<T, N>& origin, const VecN<T, N>& target);
SIMDPHYS_INSTANTIATE_PRIMITIVES(float, 2)
SIMDPHYS_INSTANTIATE_PRIMITIVES(double, 2)
SIMDPHYS_INSTANTIATE_PRIMITIVES(float, 3)
SIMDPHYS_INSTANTIATE_PRIMITIVES(double, 3)
#undef SIMDPHYS_INSTANTIATE_PRIMITIVES

}  // namespace simdphys

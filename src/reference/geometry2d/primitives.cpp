// geometry2d/primitives.hpp, compiled once: validate for float and double (the shared
// shapes' in src/reference/primitives.cpp).
#include "simdphys/geometry2d/primitives.hpp"

#include "src/reference/math-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

template <class T>
void validate(const Vec2<T>& point, std::string_view where) {
  detail::requireFiniteField(point, where, "point");
}

template <class T>
void validate(const OrientedRectT<T>& b, std::string_view where) {
  detail::requireFiniteField(b.center, where, "center");
  detail::requireFiniteField(b.halfExtents, where, "halfExtents");
  detail::require(std::isfinite(b.rotation), b.rotation, where, "rotation", "not finite");
  detail::require(b.halfExtents.x() >= 0, b.halfExtents.x(), where, "halfExtents.x",
                  "must be >= 0");
  detail::require(b.halfExtents.y() >= 0, b.halfExtents.y(), where, "halfExtents.y",
                  "must be >= 0");
  detail::requireReachInRange(b.center, Vec2<T>(b.axes().cwiseAbs() * b.halfExtents), where,
                              "the rectangle (center +- |axes| halfExtents)");
}

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(T)                   \
  template void validate(const Vec2<T>& point, std::string_view where); \
  template void validate(const OrientedRectT<T>& b, std::string_view where);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES

}  // namespace simdphys

// geometry2d/primitives.hpp, compiled once: validate and the named constructor for float and
// double.
#include "simdphys/geometry2d/primitives.hpp"

#include "src/reference/math-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

template <class T>
void validate(const Vec2<T>& point, std::string_view where) {
  detail::requireFiniteField(point, where, "point");
}

template <class T>
void validate(const Segment2T<T>& s, std::string_view where) {
  detail::requireFiniteField(s.start, where, "start");
  detail::requireFiniteField(s.end, where, "end");
}

template <class T>
void validate(const Ray2T<T>& r, std::string_view where) {
  detail::requireFiniteField(r.origin, where, "origin");
  detail::requireFiniteField(r.direction, where, "direction");
  detail::requireUnit(r.direction, where, "direction");
}

template <class T>
void validate(const CircleT<T>& c, std::string_view where) {
  detail::requireBall(c.center, c.radius, where);
}

template <class T>
void validate(const RectT<T>& r, std::string_view where) {
  detail::requireFiniteField(r.min, where, "min");
  detail::requireFiniteField(r.max, where, "max");
  detail::requireOrdered(r.min, r.max, where);
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

// Any finite non-zero offset works: unitOr (math.hpp) scales it before taking its length.
template <class T>
Ray2T<T> Ray2T<T>::fromTo(const Vec2<T>& origin, const Vec2<T>& target) {
  detail::requireFiniteField(origin, "Ray2::fromTo", "origin");
  detail::requireFiniteField(target, "Ray2::fromTo", "target");
  const Vec2<T> d = target - origin;
  if ((d.array() == 0).all()) throw Error("Ray2::fromTo: origin and target coincide");
  return {origin, detail::unitOr(d, Vec2<T>::Zero().eval())};
}

#define SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(T)                        \
  template void validate(const Vec2<T>& point, std::string_view where);      \
  template void validate(const Segment2T<T>& s, std::string_view where);     \
  template void validate(const Ray2T<T>& r, std::string_view where);         \
  template void validate(const CircleT<T>& c, std::string_view where);       \
  template void validate(const RectT<T>& r, std::string_view where);         \
  template void validate(const OrientedRectT<T>& b, std::string_view where); \
  template Ray2T<T> Ray2T<T>::fromTo(const Vec2<T>& origin, const Vec2<T>& target);
SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(float)
SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY2D_PRIMITIVES

}  // namespace simdphys

// geometry3d/primitives.hpp, compiled once: validate and the named constructor for float and
// double (the shared shapes' in src/reference/primitives.cpp).
#include "simdphys/geometry3d/primitives.hpp"

#include "src/reference/math-inl.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

template <class T>
void validate(const PlaneT<T>& p, std::string_view where) {
  detail::requireFiniteField(p.normal, where, "normal");
  detail::requireInRange(p.d, where, "d");
  detail::requireUnit(p.normal, where, "normal");
}

template <class T>
void validate(const ObbT<T>& b, std::string_view where) {
  detail::requireFiniteField(b.center, where, "center");
  detail::requireFiniteField(b.halfExtents, where, "halfExtents");
  detail::requireFiniteField(b.axes.col(0), where, "axes.col(0)");
  detail::requireFiniteField(b.axes.col(1), where, "axes.col(1)");
  detail::requireFiniteField(b.axes.col(2), where, "axes.col(2)");
  for (int a = 0; a < 3; ++a)
    if (!(b.halfExtents[a] >= 0))
      throw Error(std::string(where) + ": halfExtents has a negative component");
  const T error = (b.axes.transpose() * b.axes - Mat3<T>::Identity()).cwiseAbs().maxCoeff();
  if (error > detail::kUnitTolerance<T> || b.axes.determinant() < 0)
    throw Error(std::string(where) + ": axes are not orthonormal and right-handed (|A^T A - I| = " +
                std::to_string(double(error)) + ")");
  detail::requireReachInRange(b.center, Vec3<T>(b.axes.cwiseAbs() * b.halfExtents), where,
                              "the box (center +- |axes| halfExtents)");
}

template <class T>
void validate(const TriangleT<T>& t, std::string_view where) {
  detail::requireFiniteField(t.a, where, "a");
  detail::requireFiniteField(t.b, where, "b");
  detail::requireFiniteField(t.c, where, "c");
}

// Accepts any finite non-zero normal (unitOr scales it before taking its length) and checks that
// the point is in the supported range and the plane passes within it.
template <class T>
PlaneT<T> PlaneT<T>::fromPointNormal(const Vec3<T>& point, const Vec3<T>& normal) {
  detail::requireFiniteField(point, "Plane::fromPointNormal", "point");
  if (!normal.allFinite()) throw Error("Plane::fromPointNormal: the normal is not finite");
  if ((normal.array() == 0).all()) throw Error("Plane::fromPointNormal: the normal is zero");
  const Vec3<T> n = detail::unitOr(normal, Vec3<T>::Zero().eval());
  const PlaneT plane{n, -n.dot(point)};
  validate(plane, "Plane::fromPointNormal");
  return plane;
}

#define SIMDPHYS_INSTANTIATE_GEOMETRY3D_PRIMITIVES(T)                    \
  template void validate(const PlaneT<T>& p, std::string_view where);    \
  template void validate(const ObbT<T>& b, std::string_view where);      \
  template void validate(const TriangleT<T>& t, std::string_view where); \
  template PlaneT<T> PlaneT<T>::fromPointNormal(const Vec3<T>& point, const Vec3<T>& normal);
SIMDPHYS_INSTANTIATE_GEOMETRY3D_PRIMITIVES(float)
SIMDPHYS_INSTANTIATE_GEOMETRY3D_PRIMITIVES(double)
#undef SIMDPHYS_INSTANTIATE_GEOMETRY3D_PRIMITIVES

}  // namespace simdphys

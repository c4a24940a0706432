// The checks behind validate() (geometry2d/primitives.hpp, geometry3d/primitives.hpp) and the
// streams', meshes' and queries' own input checks: values in the supported range of math.hpp,
// with an Error saying what and where.
#pragma once

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/math.hpp"

namespace simdphys::detail {

// Whether a magnitude is in the supported range. The range is a float range: a double is compared
// after rounding to float, so the double 1e18 is in it too. False for NaN.
inline bool inSupportedRange(double magnitude) {
  return magnitude <= std::numeric_limits<float>::max() && float(magnitude) <= kMaxCoordinate;
}

// x as the shortest text that reads back as the same float (the range is a float range; a double
// beyond float's range as the shortest double), so a value one ulp past the edge does not print
// as the edge: 1e+20, 1.00000008e+18.
inline std::string rangeText(double x) {
  char text[32];
  const float f = float(x);
  const auto end = std::isfinite(f) || !std::isfinite(x) ? std::to_chars(text, text + 32, f).ptr
                                                         : std::to_chars(text, text + 32, x).ptr;
  return std::string(text, end);
}

// Throws Error unless |x| is in the supported range: "where: field is 1e+20, outside the
// supported range +-1e+18" (or "..., not finite").
template <std::floating_point T>
void requireInRange(T x, std::string_view where, std::string_view field) {
  if (inSupportedRange(std::abs(double(x)))) return;
  throw Error(std::string(where) + ": " + std::string(field) + " is " + rangeText(double(x)) +
              (std::isfinite(x) ? ", outside the supported range +-" + rangeText(kMaxCoordinate)
                                : ", not finite"));
}

// Throws Error unless the shape center +- reach (reach >= 0 per axis: a radius, a box's extent
// along the axis) lies in the supported range on every axis, so that its bounds are in range
// too: for float input, float(center + reach) <= kMaxCoordinate exactly when this passes (the sum
// is taken in double, then rounded to float).
template <class C, class R>
void requireReachInRange(const C& center, const R& reach, std::string_view where,
                         std::string_view what) {
  constexpr char kAxis[] = {'x', 'y', 'z', 'w'};
  for (int a = 0; a < int(center.size()); ++a) {
    const double bound = std::abs(double(center[a])) + double(reach[a]);
    if (inSupportedRange(bound)) continue;
    throw Error(std::string(where) + ": " + std::string(what) + " reaches " + rangeText(bound) +
                " on " + kAxis[a] + ", outside the supported range +-" + rangeText(kMaxCoordinate));
  }
}

// Each component of a 2D, 3D or 4D vector finite and within the supported range, e.g. "where:
// min.y is 1e+20, outside the supported range +-1e+18".
template <class V>
void requireFiniteField(const V& v, std::string_view where, const char* field) {
  constexpr char kAxis[] = {'x', 'y', 'z', 'w'};
  for (int a = 0; a < int(v.size()); ++a)  // the field's name is built only for the message
    if (!inSupportedRange(std::abs(double(v[a]))))
      requireInRange(v[a], where, std::string(field) + '.' + kAxis[a]);
}

// "where: field is x, <what it must be>" unless ok.
template <class T>
void require(bool ok, T x, std::string_view where, const char* field, const char* must) {
  if (ok) return;
  std::ostringstream msg;
  msg << where << ": " << field << " is " << x << ", " << must;
  throw Error(msg.str());
}

// Tolerance for "unit length" and "orthonormal": a few rounding steps of a normalisation in T.
template <class T>
constexpr T kUnitTolerance = T(64) * std::numeric_limits<T>::epsilon();

// |v| = 1 within kUnitTolerance: "where: direction is not unit length (|direction| = 1.5)".
template <class V>
void requireUnit(const V& v, std::string_view where, const char* field) {
  using T = typename V::Scalar;
  const T length = v.norm();
  if (!(std::abs(length - T(1)) > kUnitTolerance<T>)) return;
  std::ostringstream msg;
  msg << where << ": " << field << " is not unit length (|" << field << "| = " << length << ")";
  throw Error(msg.str());
}

// A box's corners: min <= max on every axis, "where: min.y (3) > max.y (2)".
template <class V>
void requireOrdered(const V& min, const V& max, std::string_view where) {
  constexpr char kAxis[] = {'x', 'y', 'z', 'w'};
  for (int a = 0; a < int(min.size()); ++a) {
    if (min[a] <= max[a]) continue;
    std::ostringstream msg;
    msg << where << ": min." << kAxis[a] << " (" << min[a] << ") > max." << kAxis[a] << " ("
        << max[a] << ")";
    throw Error(msg.str());
  }
}

// A circle or sphere: center in range, radius finite and >= 0, center +- radius in range.
template <class V, class T>
void requireBall(const V& center, T radius, std::string_view where) {
  requireFiniteField(center, where, "center");
  require(std::isfinite(radius), radius, where, "radius", "not finite");
  require(radius >= 0, radius, where, "radius", "must be >= 0");
  requireReachInRange(center, V::Constant(radius), where, "center +- radius");
}

}  // namespace simdphys::detail

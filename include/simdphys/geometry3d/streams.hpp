// Streams of 3D primitives: one aligned, padded array per field (core.hpp). Each stream
// validates what it is given and names the offending element; padding makes padded lanes inert
// (an empty box, a sphere of radius -inf).
#pragma once

#include <array>
#include <limits>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys {

// Boxes as min/max corners, the layout of overlap tests.
class BoxStream {
 public:
  std::size_t size() const { return minX_.size(); }
  std::size_t padded() const { return minX_.padded(); }
  void reserve(std::size_t n);
  void clear() { resize(0); }
  void push(const Aabb& box);
  void set(std::size_t i, const Aabb& box);
  Aabb operator[](std::size_t i) const;

  const Stream<float>& minX() const { return minX_; }
  const Stream<float>& minY() const { return minY_; }
  const Stream<float>& minZ() const { return minZ_; }
  const Stream<float>& maxX() const { return maxX_; }
  const Stream<float>& maxY() const { return maxY_; }
  const Stream<float>& maxZ() const { return maxZ_; }

 private:
  void resize(std::size_t n);
  auto fields() { return std::array{&minX_, &minY_, &minZ_, &maxX_, &maxY_, &maxZ_}; }
  Stream<float> minX_{kEmptyMin}, minY_{kEmptyMin}, minZ_{kEmptyMin};
  Stream<float> maxX_{kEmptyMax}, maxY_{kEmptyMax}, maxZ_{kEmptyMax};
  static constexpr float kEmptyMin = std::numeric_limits<float>::infinity();
  static constexpr float kEmptyMax = -std::numeric_limits<float>::infinity();
};

// Spheres as centre and radius.
class SphereStream {
 public:
  std::size_t size() const { return r_.size(); }
  std::size_t padded() const { return r_.padded(); }
  void reserve(std::size_t n);
  void clear() { resize(0); }
  void push(const Sphere& sphere);
  void set(std::size_t i, const Sphere& sphere);
  Sphere operator[](std::size_t i) const;

  const Stream<float>& x() const { return x_; }
  const Stream<float>& y() const { return y_; }
  const Stream<float>& z() const { return z_; }
  const Stream<float>& r() const { return r_; }

 private:
  void resize(std::size_t n);
  auto fields() { return std::array{&x_, &y_, &z_, &r_}; }
  Stream<float> x_, y_, z_, r_{-std::numeric_limits<float>::infinity()};
};

// Boxes as centre and half extents, the layout of culling (n.c + d + |n|.h needs no
// conversion, so no rounding is added to the workload's inputs).
class BoundsStream {
 public:
  std::size_t size() const { return cx_.size(); }
  std::size_t padded() const { return cx_.padded(); }
  void reserve(std::size_t n);
  void clear() { resize(0); }
  void push(const Vec3f& center, const Vec3f& halfExtents);
  Aabb operator[](std::size_t i) const;  // as min/max, for single queries

  const Stream<float>& cx() const { return cx_; }
  const Stream<float>& cy() const { return cy_; }
  const Stream<float>& cz() const { return cz_; }
  const Stream<float>& ex() const { return ex_; }
  const Stream<float>& ey() const { return ey_; }
  const Stream<float>& ez() const { return ez_; }

 private:
  void resize(std::size_t n);
  auto fields() { return std::array{&cx_, &cy_, &cz_, &ex_, &ey_, &ez_}; }
  static constexpr float kEmpty = -std::numeric_limits<float>::infinity();
  Stream<float> cx_, cy_, cz_, ex_{kEmpty}, ey_{kEmpty}, ez_{kEmpty};
};

}  // namespace simdphys

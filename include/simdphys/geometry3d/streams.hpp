// Streams of 3D primitives: one aligned, padded array per field (core.hpp). Each stream
// validates what it is given (validate() of primitives.hpp: finite, within the supported range of
// math.hpp, sizes >= 0, ...) and names the offending element; padding makes padded lanes inert
// (an empty box, a sphere of radius -inf), so kernels can run over whole vectors.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys {

namespace detail {
// The streams' error messages: "where: element i", and an index check naming it.
inline std::string at(std::string_view where, std::size_t i) {
  return std::string(where) + ": element " + std::to_string(i);
}
inline void requireIndex(std::size_t i, std::size_t size, std::string_view where) {
  if (i >= size) throw Error(at(where, i) + " is out of range (size " + std::to_string(size) + ")");
}
}  // namespace detail

// N float fields of one length, each with its own padding value: what every stream is made of.
template <std::size_t N>
class StreamSet {
 public:
  std::size_t size() const { return fields_[0].size(); }
  std::size_t padded() const { return fields_[0].padded(); }
  void reserve(std::size_t n) {
    for (Stream<float>& f : fields_) f.reserve(n);
  }
  void clear() { resize(0); }

 protected:
  explicit StreamSet(const std::array<float, N>& pads) {
    for (std::size_t k = 0; k < N; ++k) fields_[k] = Stream<float>(pads[k]);
  }
  void resize(std::size_t n) {
    for (Stream<float>& f : fields_) f.resize(n);
  }
  void store(std::size_t i, const std::array<float, N>& values) {
    for (std::size_t k = 0; k < N; ++k) fields_[k][i] = values[k];
  }
  void append(const std::array<float, N>& values) {
    resize(size() + 1);
    store(size() - 1, values);
  }
  float value(std::size_t k, std::size_t i) const { return fields_[k][i]; }

  std::array<Stream<float>, N> fields_;
};

inline constexpr float kPadInf = std::numeric_limits<float>::infinity();

// Boxes as min/max corners, the layout of overlap tests. Padding: empty boxes (min = +inf,
// max = -inf), which overlap nothing.
class BoxStream : public StreamSet<6> {
 public:
  BoxStream() : StreamSet({kPadInf, kPadInf, kPadInf, -kPadInf, -kPadInf, -kPadInf}) {}
  void push(const Aabb& box);
  void set(std::size_t i, const Aabb& box);
  Aabb operator[](std::size_t i) const;

  const Stream<float>& minX() const { return fields_[0]; }
  const Stream<float>& minY() const { return fields_[1]; }
  const Stream<float>& minZ() const { return fields_[2]; }
  const Stream<float>& maxX() const { return fields_[3]; }
  const Stream<float>& maxY() const { return fields_[4]; }
  const Stream<float>& maxZ() const { return fields_[5]; }
};

// Spheres as centre and radius. Padding: radius -inf, which every test fails.
class SphereStream : public StreamSet<4> {
 public:
  SphereStream() : StreamSet({0, 0, 0, -kPadInf}) {}
  void push(const Sphere& sphere);
  void set(std::size_t i, const Sphere& sphere);
  Sphere operator[](std::size_t i) const;

  const Stream<float>& x() const { return fields_[0]; }
  const Stream<float>& y() const { return fields_[1]; }
  const Stream<float>& z() const { return fields_[2]; }
  const Stream<float>& r() const { return fields_[3]; }
};

// Boxes as centre and half extents, the layout of culling (n.c + d + |n|.h needs no
// conversion, so no rounding is added to the inputs). push checks that the box, centre +- half
// extents, lies in the supported range, so operator[]'s min and max are finite and in range.
// Padding: extents -inf.
class BoundsStream : public StreamSet<6> {
 public:
  BoundsStream() : StreamSet({0, 0, 0, -kPadInf, -kPadInf, -kPadInf}) {}
  void push(const Vec3f& center, const Vec3f& halfExtents);
  Aabb operator[](std::size_t i) const;  // as min/max, for single queries

  const Stream<float>& cx() const { return fields_[0]; }
  const Stream<float>& cy() const { return fields_[1]; }
  const Stream<float>& cz() const { return fields_[2]; }
  const Stream<float>& ex() const { return fields_[3]; }
  const Stream<float>& ey() const { return fields_[4]; }
  const Stream<float>& ez() const { return fields_[5]; }
};

// Triangles as the SoA of their vertices (a triangle soup). Degenerate triangles (collinear
// vertices: the normal, computed in double, is exactly zero) are rejected, as they have no
// surface to hit. Padding: all vertices at the origin, which no ray hits (no area).
class TriangleStream : public StreamSet<9> {
 public:
  TriangleStream() : StreamSet({0, 0, 0, 0, 0, 0, 0, 0, 0}) {}
  void push(const Triangle& t);
  Triangle operator[](std::size_t i) const {
    return {{value(0, i), value(1, i), value(2, i)},
            {value(3, i), value(4, i), value(5, i)},
            {value(6, i), value(7, i), value(8, i)}};
  }
  // Vertex v (0, 1, 2 for a, b, c), coordinate k (0, 1, 2 for x, y, z).
  const Stream<float>& vertex(int v, int k) const { return fields_[3 * v + k]; }
};

// Oriented boxes: centre, half extents and the 3 x 3 axes (columns: the box's local x, y, z, as in
// ObbT), each element validated like ObbT (validate: in range, extents >= 0, orthonormal and
// right-handed axes). Padding: a point box at the origin with identity axes. No value makes a
// separating-axis test fail for every query (its arithmetic reads NaN and inf as "not
// separated"), so this stream's padding is not inert by value: kernels mask lanes >= size().
class ObbStream : public StreamSet<15> {
 public:
  ObbStream() : StreamSet({0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}) {}
  void push(const Obb& box);
  void set(std::size_t i, const Obb& box);
  Obb operator[](std::size_t i) const;

  // Coordinate k (0, 1, 2 for x, y, z) of the centre and of the half extents.
  const Stream<float>& center(int k) const { return fields_[k]; }
  const Stream<float>& halfExtent(int k) const { return fields_[3 + k]; }
  // Coordinate k of axis `column` (axes(k, column) of ObbT).
  const Stream<float>& axis(int column, int k) const { return fields_[6 + 3 * column + k]; }
};

// Points, the output of batch closest-point queries. Padding: zeros.
class PointStream : public StreamSet<3> {
 public:
  PointStream() : StreamSet({0, 0, 0}) {}
  void push(const Vec3f& p);
  Vec3f operator[](std::size_t i) const { return {value(0, i), value(1, i), value(2, i)}; }
  // Makes the stream n points long and lets `write(x, y, z)` fill them (it may write the padding
  // too, which is restored after).
  template <class Writer>
  void overwrite(std::size_t n, Writer write) {
    resize(n);
    write(fields_[0].data(), fields_[1].data(), fields_[2].data());
    resize(n);
  }
  const Stream<float>& x() const { return fields_[0]; }
  const Stream<float>& y() const { return fields_[1]; }
  const Stream<float>& z() const { return fields_[2]; }
};

}  // namespace simdphys

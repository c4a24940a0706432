// Streams of 3D primitives: one aligned, padded array per field (core.hpp). Each stream
// validates what it is given (validate() of primitives.hpp: finite, within the supported range of
// math.hpp, sizes >= 0, ...) and names the offending element; padding makes padded lanes inert
// (an empty box, a sphere of radius -inf), so kernels can run over whole vectors.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "simdphys/core.hpp"
#include "simdphys/geometry3d/primitives.hpp"
#include "simdphys/stream_fields.hpp"

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

// The float fields of a layout (stream_fields.hpp), of one length, each padded with the layout's
// inert value: what every stream is made of. Readers see a field as a whole padded Stream; the
// owner (the derived stream) writes live elements in place through writable(), which cannot
// reach the padding, or whole vectors through overwrite(), which restores it after.
template <class Fields>
class StreamSet {
 public:
  using Layout = Fields;
  static constexpr std::size_t kFields = Fields::kCount;

  // Every field empty, with the layout's padding.
  StreamSet() {
    for (std::size_t k = 0; k < kFields; ++k) fields_[k] = Stream<float>(Fields::kPad[k]);
  }

  std::size_t size() const { return fields_[0].size(); }
  std::size_t padded() const { return fields_[0].padded(); }
  // Field f (a name of the layout: boxes.field(fields::Box::minX), ...), with its padding: the
  // one way to read a field, so a layout's names are written only in stream_fields.hpp.
  const Stream<float>& field(std::size_t f) const { return fields_[f]; }
  void reserve(std::size_t n) {
    for (Stream<float>& f : fields_) f.reserve(n);
  }
  void clear() { resize(0); }

 protected:
  void resize(std::size_t n) {
    for (Stream<float>& f : fields_) f.resize(n);
  }
  void store(std::size_t i, const std::array<float, kFields>& values) {
    for (std::size_t k = 0; k < kFields; ++k) fields_[k][i] = values[k];
  }
  void append(const std::array<float, kFields>& values) {
    resize(size() + 1);
    store(size() - 1, values);
  }
  float value(std::size_t k, std::size_t i) const { return fields_[k][i]; }
  // Removes element i, moving the last element into its place (dense, as handles want it).
  void eraseSwap(std::size_t i) {
    const std::size_t last = size() - 1;
    for (Stream<float>& f : fields_) f[i] = f[last];
    resize(last);
  }
  // push and set of a stream of shapes: the shape checked by its validate() (primitives.hpp),
  // errors named by `where` ("BoxStream::push") and the element, then its values stored. A
  // rejected shape changes nothing.
  template <class Shape>
  void pushValid(const char* where, const Shape& shape, const std::array<float, kFields>& values) {
    validate(shape, detail::at(where, size()));
    append(values);
  }
  template <class Shape>
  void setValid(const char* where, std::size_t i, const Shape& shape,
                const std::array<float, kFields>& values) {
    detail::requireIndex(i, size(), where);
    validate(shape, detail::at(where, i));
    store(i, values);
  }
  // Throws Error "where: <element> i: <name> is v, not finite or beyond +-1e18" for the first
  // live value of fields 0 .. names.size() - 1 outside the supported range (math.hpp): what a
  // stream written in place (numpy views) is checked with before a step.
  void requireInRange(std::span<const char* const> names, const std::string& where,
                      const char* element) const {
    for (std::size_t f = 0; f < names.size(); ++f)
      for (std::size_t i = 0; i < size(); ++i)
        if (!(std::abs(fields_[f][i]) <= kMaxCoordinate))
          throw Error(where + ": " + element + " " + std::to_string(i) + ": " + names[f] + " is " +
                      std::to_string(fields_[f][i]) + ", not finite or beyond +-1e18");
  }
  // Field f's whole padded array, for a kernel that stores whole vectors and writes back the
  // padding's values unchanged (a particle step leaves pinned lanes as they are).
  float* paddedData(std::size_t f) { return fields_[f].data(); }
  // Field f's size() live elements, to write in place: the padding is out of reach, so it stays
  // inert whatever the owner writes.
  std::span<float> writable(std::size_t f) { return fields_[f].view(); }
  // Makes the stream n long and lets write(p) fill every field, p[f] pointing at field f's padded
  // array (kernels store whole vectors, padding included); the padding is restored after.
  template <class Writer>
  void overwrite(std::size_t n, Writer write) {
    resize(n);
    std::array<float*, kFields> p;
    for (std::size_t k = 0; k < kFields; ++k) p[k] = fields_[k].data();
    write(p);
    resize(n);
  }

 private:
  friend struct detail::Snapshot;
  std::array<Stream<float>, kFields> fields_;
};

using fields::kPadInf;

// Boxes as min/max corners, the layout of overlap tests. Padding: empty boxes (min = +inf,
// max = -inf), which overlap nothing.
class BoxStream : public StreamSet<fields::Box> {
 public:
  void push(const Aabb& box);
  void set(std::size_t i, const Aabb& box);
  Aabb operator[](std::size_t i) const;
};

// Spheres as centre and radius. Padding: radius -inf, which every test fails.
class SphereStream : public StreamSet<fields::Sphere> {
 public:
  void push(const Sphere& sphere);
  void set(std::size_t i, const Sphere& sphere);
  Sphere operator[](std::size_t i) const;
};

// Boxes as centre and half extents, the layout of culling (n.c + d + |n|.h needs no
// conversion, so no rounding is added to the inputs). push checks that the box, centre +- half
// extents, lies in the supported range, so operator[]'s min and max are finite and in range.
// Padding: extents -inf.
class BoundsStream : public StreamSet<fields::Bounds> {
 public:
  void push(const Vec3f& center, const Vec3f& halfExtents);
  Aabb operator[](std::size_t i) const;  // as min/max, for single queries
};

// Triangles as the SoA of their vertices (a triangle soup). Degenerate triangles (collinear
// vertices: the normal, computed in double, is exactly zero) are rejected, as they have no
// surface to hit. Padding: all vertices at the origin, which no ray hits (no area).
class TriangleStream : public StreamSet<fields::Triangle> {
 public:
  void push(const Triangle& t);
  Triangle operator[](std::size_t i) const {
    return {{value(0, i), value(1, i), value(2, i)},
            {value(3, i), value(4, i), value(5, i)},
            {value(6, i), value(7, i), value(8, i)}};
  }
  // Vertex v (0, 1, 2 for a, b, c), coordinate k (0, 1, 2 for x, y, z).
  const Stream<float>& vertex(int v, int k) const {
    return field(fields::Triangle::vertex + 3 * v + k);
  }
};

// Oriented boxes: centre, half extents and the 3 x 3 axes (columns: the box's local x, y, z, as in
// ObbT), each element validated like ObbT (validate: in range, extents >= 0, orthonormal and
// right-handed axes). Padding: a point box at the origin with identity axes. No value makes a
// separating-axis test fail for every query (its arithmetic reads NaN and inf as "not
// separated"), so this stream's padding is not inert by value: kernels mask lanes >= size().
class ObbStream : public StreamSet<fields::Obb> {
 public:
  void push(const Obb& box);
  void set(std::size_t i, const Obb& box);
  Obb operator[](std::size_t i) const;

  // Coordinate k (0, 1, 2 for x, y, z) of the centre and of the half extents.
  const Stream<float>& center(int k) const { return field(fields::Obb::center + k); }
  const Stream<float>& halfExtent(int k) const { return field(fields::Obb::half + k); }
  // Coordinate k of axis `column` (axes(k, column) of ObbT).
  const Stream<float>& axis(int column, int k) const {
    return field(fields::Obb::axis + 3 * column + k);
  }
};

// Points, the output of batch closest-point queries. Padding: zeros.
class PointStream : public StreamSet<fields::Point> {
 public:
  void push(const Vec3f& p);
  Vec3f operator[](std::size_t i) const { return {value(0, i), value(1, i), value(2, i)}; }
  // Makes the stream n points long and lets `write(x, y, z)` fill them (it may write the padding
  // too, which is restored after).
  template <class Writer>
  void overwrite(std::size_t n, Writer write) {
    StreamSet::overwrite(n, [&](const std::array<float*, 3>& p) { write(p[0], p[1], p[2]); });
  }
};

}  // namespace simdphys

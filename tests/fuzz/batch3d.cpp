// Fuzz target: the 3D batch queries (geometry3d/batch.hpp) on streams decoded from the bytes (up
// to 40 elements: more than one vector of every width, and a tail), each on every path against
// the reference path, exactly: indices, counts, hit indices and the bits of t and of points.
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "simdphys/geometry3d/batch.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace simdphys {
namespace {

using Hit = std::optional<std::pair<std::uint32_t, std::uint32_t>>;
Hit key(const ElementHit& h) { return h.hit() ? Hit({h.index, fuzz::bitsOf(h.t)}) : std::nullopt; }

// Mostly valid elements (corners sorted, sizes non-negative); sometimes as decoded, which the
// stream must reject with an Error.
Aabb box(fuzz::Input& in) {
  const Vec3f a = in.vec3(), b = in.vec3();
  return in.byte() < 240 ? Aabb{a.cwiseMin(b), a.cwiseMax(b)} : Aabb{a, b};
}
Sphere sphere(fuzz::Input& in) {
  const Vec3f c = in.vec3();
  const float r = in.scalar();
  return {c, in.byte() < 240 ? std::abs(r) : r};
}
Obb obb(fuzz::Input& in) {
  const Vec3f c = in.vec3(), e = in.vec3();
  return {c, in.byte() < 240 ? Vec3f(e.cwiseAbs()) : e, in.axes()};
}
Triangle triangle(fuzz::Input& in) {
  const Vec3f a = in.vec3(), b = in.vec3();
  return {a, b, in.vec3()};
}

// A ray query's input and the reference path's answer, for a finding's message.
template <class Stream>
std::string describe(const Ray& r, float tMax, const Stream& s) {
  std::ostringstream o;
  o.precision(9);
  o << "\n  ray (" << r.origin.transpose() << ") dir (" << r.direction.transpose() << ") tMax "
    << tMax;
  for (std::size_t i = 0; i < s.size(); ++i) {
    o << "\n  element " << i << ":";
    if constexpr (std::is_same_v<Stream, SphereStream>)
      o << " (" << s[i].center.transpose() << ") r " << s[i].radius;
    else if constexpr (std::is_same_v<Stream, BoxStream>)
      o << " (" << s[i].min.transpose() << ") (" << s[i].max.transpose() << ")";
    else
      o << " (" << s[i].a.transpose() << ") (" << s[i].b.transpose() << ") (" << s[i].c.transpose()
        << ")";
  }
  ScopedPath p("reference");
  if (const ElementHit h = raycast(r, s, tMax); h.hit())
    o << "\n  reference: " << h.index << " t " << h.t;
  else
    o << "\n  reference: miss";
  return o.str();
}

template <class Stream>
void rays(const char* what, const Ray& r, float t, const Stream& s) {
  fuzz::sameOnEveryPath(
      what, [&] { return key(raycast(r, s, t)); }, [&] { return describe(r, t, s); });
}

float tMax(fuzz::Input& in) {
  return in.byte() < 160 ? std::numeric_limits<float>::infinity() : in.scalar();
}

}  // namespace
}  // namespace simdphys

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  fuzz::Input in(data, size);
  try {
    switch (in.byte() % 9) {
      case 0: {
        const auto s = fuzz::streamOf<SphereStream>(in, sphere);
        const Sphere q = sphere(in);
        fuzz::indices("overlapping(Sphere, SphereStream)",
                      [&](auto& out) { return overlapping(q, s, out); });
        break;
      }
      case 1: {
        const auto s = fuzz::streamOf<BoxStream>(in, box);
        const Sphere q = sphere(in);
        fuzz::indices("overlapping(Sphere, BoxStream)",
                      [&](auto& out) { return overlapping(q, s, out); });
        break;
      }
      case 2: {
        const auto s = fuzz::streamOf<ObbStream>(in, obb);
        const Obb q = obb(in);
        fuzz::indices("overlapping(Obb, ObbStream)",
                      [&](auto& out) { return overlapping(q, s, out); });
        break;
      }
      case 3: {
        const auto s = fuzz::streamOf<BoxStream>(in, box);
        const Vec3f p = in.vec3();
        fuzz::indices("containing(point, BoxStream)",
                      [&](auto& out) { return containing(p, s, out); });
        break;
      }
      case 4: {
        const auto s = fuzz::streamOf<BoxStream>(in, box);
        const Vec3f p = in.vec3();
        fuzz::sameOnEveryPath("closestPoints(point, BoxStream)", [&] {
          PointStream out;
          closestPoints(p, s, out);
          std::vector<std::uint32_t> bits;
          for (std::size_t i = 0; i < out.size(); ++i)
            for (int k = 0; k < 3; ++k) bits.push_back(fuzz::bitsOf(out[i][k]));
          return bits;
        });
        break;
      }
      case 5: {
        const auto s = fuzz::streamOf<BoxStream>(in, box);
        const Ray r{in.vec3(), in.direction()};
        const float t = tMax(in);
        rays("raycast(Ray, BoxStream)", r, t, s);
        break;
      }
      case 6: {
        const auto s = fuzz::streamOf<SphereStream>(in, sphere);
        const Ray r{in.vec3(), in.direction()};
        const float t = tMax(in);
        rays("raycast(Ray, SphereStream)", r, t, s);
        break;
      }
      default: {
        const auto s = fuzz::streamOf<TriangleStream>(in, triangle);
        const Ray r{in.vec3(), in.direction()};
        const float t = tMax(in);
        rays("raycast(Ray, TriangleStream)", r, t, s);
        break;
      }
    }
  } catch (const Error&) {  // a stream rejected an element
  }
  return 0;
}

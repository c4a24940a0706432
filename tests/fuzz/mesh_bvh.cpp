// Fuzz target: MeshBvh queries on a small mesh decoded from the bytes (up to 16 vertices, 24
// triangles, so vertices are shared and triangles touch): rays, ray streams, linecasts and
// overlaps, each on every path against the reference path, and against brute force over the
// triangles (tests/mesh_oracles.hpp) where mesh_bvh.hpp promises equality.
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "simdphys/mesh_bvh.hpp"
#include "tests/fuzz/fuzz_input.hpp"
#include "tests/mesh_oracles.hpp"

namespace simdphys {
namespace {

std::pair<std::uint32_t, std::uint32_t> key(const ElementHit& h) {
  return {h.index, fuzz::bitsOf(h.t)};
}

// The mesh's triangles and a list of ids, for a finding's message.
std::string show(const Mesh& m, const std::vector<std::uint32_t>& ids) {
  std::ostringstream s;
  s.precision(9);
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Triangle t = m.triangle(i);
    s << "\n  triangle " << i << ": (" << t.a.transpose() << "), (" << t.b.transpose() << "), ("
      << t.c.transpose() << ")";
  }
  s << "\n  ids:";
  for (std::uint32_t id : ids) s << " " << id;
  return s.str();
}

// A shape, for a finding's message.
std::string describe(const Sphere& s) {
  std::ostringstream o;
  o.precision(9);
  o << "Sphere{(" << s.center.transpose() << "), " << s.radius << "}";
  return o.str();
}
std::string describe(const Aabb& b) {
  std::ostringstream o;
  o.precision(9);
  o << "Aabb{(" << b.min.transpose() << "), (" << b.max.transpose() << ")}";
  return o.str();
}
std::string describe(const Obb& b) {
  std::ostringstream o;
  o.precision(9);
  o << "Obb{(" << b.center.transpose() << "), (" << b.halfExtents.transpose() << "), axes ("
    << b.axes.reshaped().transpose() << ")}";
  return o.str();
}
std::string describe(const Triangle& t) {
  std::ostringstream o;
  o.precision(9);
  o << "Triangle{(" << t.a.transpose() << "), (" << t.b.transpose() << "), (" << t.c.transpose()
    << ")}";
  return o.str();
}

template <class Shape>
void overlap(const MeshBvh& bvh, const Shape& shape, const char* name) {
  const std::string what = std::string("MeshBvh::overlapping(") + name + ")";
  const auto out = fuzz::sameOnEveryPath(what.c_str(), [&] { return bvh.overlapping(shape); });
  const auto* ids = fuzz::resultOf(out);
  if (!ids) return;
  const std::vector<std::uint32_t> brute = test::bruteOverlapping(bvh.mesh(), shape);
  if (*ids != brute)
    fuzz::finding(what + ": differs from brute force on " + describe(shape) +
                  show(bvh.mesh(), *ids) + " (brute force:" + show(Mesh{}, brute).substr(7) + ")");
}

void query(const MeshBvh& bvh, fuzz::Input& in) {
  const Mesh& m = bvh.mesh();
  switch (in.byte() % 8) {
    case 0: {
      const Ray ray{in.vec3(), in.direction()};
      const float tMax = in.byte() < 128 ? std::numeric_limits<float>::infinity() : in.scalar();
      const auto out =
          fuzz::sameOnEveryPath("MeshBvh::raycast", [&] { return key(bvh.raycast(ray, tMax)); });
      if (const auto* hit = fuzz::resultOf(out))
        fuzz::require(*hit == key(test::bruteRaycast(m, ray, tMax)),
                      "MeshBvh::raycast: differs from brute force");
      break;
    }
    case 1: {
      const Ray ray{in.vec3(), in.direction()};
      const float tMax = in.byte() < 128 ? std::numeric_limits<float>::infinity() : in.scalar();
      const auto out =
          fuzz::sameOnEveryPath("MeshBvh::occluded", [&] { return bvh.occluded(ray, tMax); });
      if (const auto* hit = fuzz::resultOf(out))
        fuzz::require(*hit == test::bruteOccluded(m, ray, tMax),
                      "MeshBvh::occluded: differs from brute force");
      break;
    }
    case 2: {
      const Segment s{in.vec3(), in.vec3()};
      fuzz::sameOnEveryPath("MeshBvh::linecast", [&] { return key(bvh.linecast(s)); });
      fuzz::sameOnEveryPath("MeshBvh::linetest", [&] { return bvh.linetest(s); });
      break;
    }
    case 3: {
      const Sphere s{in.vec3(), in.scalar()};
      overlap(bvh, s, "Sphere");
      break;
    }
    case 4: {
      const Vec3f a = in.vec3(), b = in.vec3();
      const Aabb box = in.byte() < 224 ? Aabb{a.cwiseMin(b), a.cwiseMax(b)} : Aabb{a, b};
      overlap(bvh, box, "Aabb");
      break;
    }
    case 5: {
      const Vec3f c = in.vec3(), e = in.vec3();
      overlap(bvh, Obb{c, in.byte() < 224 ? e.cwiseAbs() : e, in.axes()}, "Obb");
      break;
    }
    case 6: {
      const Vec3f a = in.vec3(), b = in.vec3();
      overlap(bvh, Triangle{a, b, in.vec3()}, "Triangle");
      break;
    }
    case 7: {  // a stream of rays in each mode, against single rays on the reference path
      RayStream rays;
      try {
        for (std::size_t i = 0, n = 1 + in.count(23); i < n; ++i)
          rays.push(Ray{in.vec3(), in.direction()});
      } catch (const Error&) {
        return;
      }
      std::vector<std::pair<std::uint32_t, std::uint32_t>> single;
      {
        ScopedPath p("reference");
        for (std::size_t i = 0; i < rays.size(); ++i) single.push_back(key(bvh.raycast(rays[i])));
      }
      using Mode = RayStreamOptions::Mode;
      const RayStreamOptions options{Mode(in.byte() % 3), in.byte() % 2 ? 8u : 16u,
                                     std::uint32_t(in.count(5))};
      fuzz::sameOnEveryPath("MeshBvh::raycast(RayStream)", [&] {
        std::vector<ElementHit> out(rays.size());
        bvh.raycast(rays, out, options);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> keys;
        for (const ElementHit& h : out) keys.push_back(key(h));
        fuzz::require(keys == single, "MeshBvh::raycast(RayStream): differs from single rays");
        return keys;
      });
      break;
    }
  }
}

}  // namespace
}  // namespace simdphys

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  fuzz::Input in(data, size);
  Mesh m;
  const std::size_t vertices = 3 + in.count(13);
  for (std::size_t i = 0; i < vertices; ++i) m.vertices.push_back(in.vec3());
  for (std::size_t i = 0, n = 1 + in.count(23); i < n; ++i)
    m.triangles.push_back({std::uint32_t(in.byte() % vertices), std::uint32_t(in.byte() % vertices),
                           std::uint32_t(in.byte() % vertices)});
  std::optional<MeshBvh> bvh;
  try {
    bvh.emplace(std::move(m));
  } catch (const Error&) {
    return 0;
  }
  for (int q = 0; q < 4; ++q) query(*bvh, in);
  return 0;
}

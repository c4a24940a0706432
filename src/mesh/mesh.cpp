// Mesh validation and the procedural meshes.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <tuple>

#include "simdphys/geometry3d/raycast.hpp"  // triangleNormalWide: the raycast's degeneracy test
#include "simdphys/mesh.hpp"
#include "src/mesh/mesh_internal.hpp"
#include "src/reference/validate-inl.hpp"

namespace simdphys {

Aabb Mesh::bounds() const {
  if (vertices.empty()) return {Vec3f::Zero(), Vec3f::Zero()};
  Aabb b{vertices.front(), vertices.front()};
  for (const Vec3f& v : vertices) b.min = b.min.cwiseMin(v), b.max = b.max.cwiseMax(v);
  return b;
}

std::vector<std::uint8_t> activeEdges(const Mesh& mesh) {
  // Every edge as (lower vertex, higher vertex, triangle, edge), sorted so the triangles sharing
  // an edge lie next to each other (deterministic, unlike a hash map's order).
  struct Edge {
    std::uint32_t lo, hi, triangle, edge;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * mesh.size());
  for (std::uint32_t i = 0; i < mesh.size(); ++i)
    for (std::uint32_t e = 0; e < 3; ++e) {
      const std::uint32_t p = mesh.triangles[i][e], q = mesh.triangles[i][(e + 1) % 3];
      edges.push_back({std::min(p, q), std::max(p, q), i, e});
    }
  std::sort(edges.begin(), edges.end(), [](const Edge& l, const Edge& r) {
    return std::tie(l.lo, l.hi, l.triangle) < std::tie(r.lo, r.hi, r.triangle);
  });
  const auto normal = [&](std::uint32_t i) {
    const Triangle t = mesh.triangle(i);
    return Vec3d((t.b - t.a).cast<double>().cross((t.c - t.a).cast<double>()).normalized());
  };
  std::vector<std::uint8_t> active(mesh.size(), 0);
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t end = k + 1;
    while (end < edges.size() && edges[end].lo == edges[k].lo && edges[end].hi == edges[k].hi)
      ++end;
    bool isActive = end - k != 2;  // the boundary, or more than two triangles meet
    if (!isActive) {
      const Edge &f = edges[k], &g = edges[k + 1];
      const Vec3d nf = normal(f.triangle), ng = normal(g.triangle);
      // g's vertex off the edge, seen from f's plane: behind it (falling away) is convex.
      const Vec3f off = mesh.vertices[mesh.triangles[g.triangle][(g.edge + 2) % 3]];
      const Vec3f on = mesh.vertices[f.lo];
      const bool convex = nf.dot((off - on).cast<double>()) < 0;
      isActive = convex && nf.dot(ng) < double(kActiveEdgeCosine);
    }
    if (isActive)
      for (std::size_t j = k; j < end; ++j)
        active[edges[j].triangle] |= std::uint8_t(1u << edges[j].edge);
    k = end;
  }
  return active;
}

void Mesh::validate(std::string_view where) const {
  detail::validateVertices(*this, where);
  for (std::size_t i = 0; i < triangles.size(); ++i) detail::validateTriangle(*this, i, where);
}

void detail::validateVertices(const Mesh& mesh, std::string_view where) {
  const auto& vertices = mesh.vertices;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!vertices[i].allFinite())
      detail::requireFiniteField(vertices[i], std::string(where) + ": vertex " + std::to_string(i),
                                 "position");
    if (vertices[i].cwiseAbs().maxCoeff() > kMaxCoordinate) {
      std::ostringstream msg;
      msg << where << ": vertex " << i << ": position (" << vertices[i].transpose()
          << ") is outside the supported range (|coordinate| <= " << kMaxCoordinate << ")";
      throw Error(msg.str());
    }
  }
}

void detail::validateTriangle(const Mesh& mesh, std::size_t i, std::string_view where) {
  const auto& t = mesh.triangles[i];
  const std::size_t n = mesh.vertices.size();
  for (int k = 0; k < 3; ++k)
    if (t[k] >= n)
      throw Error(std::string(where) + ": triangle " + std::to_string(i) + ": vertex index " +
                  std::to_string(t[k]) + " is out of range (" + std::to_string(n) + " vertices)");
  if ((detail::rays::triangleNormalWide(mesh.triangle(i)).array() == 0).all())
    throw Error(std::string(where) + ": triangle " + std::to_string(i) + " (vertices " +
                std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                ") is degenerate: its vertices are collinear");
}

Mesh heightfieldMesh(std::uint32_t columns, std::uint32_t rows, double x0, double x1, double z0,
                     double z1, const std::function<double(double, double)>& height) {
  if (columns < 2 || rows < 2)
    throw Error("heightfieldMesh: " + std::to_string(columns) + " x " + std::to_string(rows) +
                " vertices; at least 2 x 2 are needed");
  if (std::uint64_t(columns) * rows > std::uint64_t(UINT32_MAX))
    throw Error("heightfieldMesh: more vertices than 32-bit indices can name");
  Mesh m;
  m.vertices.reserve(std::size_t(columns) * rows);
  for (std::uint32_t j = 0; j < rows; ++j)
    for (std::uint32_t i = 0; i < columns; ++i) {
      const float x = float(x0 + (x1 - x0) * double(i) / double(columns - 1));
      const float z = float(z0 + (z1 - z0) * double(j) / double(rows - 1));
      m.vertices.emplace_back(x, float(height(double(x), double(z))), z);
    }
  m.triangles.reserve(2 * std::size_t(columns - 1) * (rows - 1));
  auto v = [columns](std::uint32_t i, std::uint32_t j) { return j * columns + i; };
  for (std::uint32_t j = 0; j + 1 < rows; ++j)
    for (std::uint32_t i = 0; i + 1 < columns; ++i) {
      m.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      m.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  m.validate("heightfieldMesh");
  return m;
}

Mesh boxMesh(const Aabb& box) {
  validate(box, "boxMesh");
  Mesh m;
  for (int k = 0; k < 8; ++k)  // corner k: bit 0 picks max x, bit 1 max y, bit 2 max z
    m.vertices.emplace_back(k & 1 ? box.max.x() : box.min.x(), k & 2 ? box.max.y() : box.min.y(),
                            k & 4 ? box.max.z() : box.min.z());
  // Each face as a quad counter-clockwise seen from outside, split along its first diagonal.
  const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  m.validate("boxMesh");  // a flat box has degenerate faces
  return m;
}

Mesh sphereMesh(const Vec3f& center, float radius, std::uint32_t rings, std::uint32_t segments) {
  if (rings < 2 || segments < 3)
    throw Error("sphereMesh: " + std::to_string(rings) + " rings and " + std::to_string(segments) +
                " segments; at least 2 and 3 are needed");
  if (!center.allFinite() || !(radius > 0) || !std::isfinite(radius))
    throw Error("sphereMesh: the centre is not finite or the radius not positive");
  Mesh m;
  const double pi = std::numbers::pi;
  m.vertices.push_back(center + Vec3f(0, radius, 0));  // north pole: index 0
  for (std::uint32_t r = 1; r < rings; ++r) {
    const double polar = pi * r / rings;
    for (std::uint32_t s = 0; s < segments; ++s) {
      const double azimuth = 2 * pi * s / segments;
      m.vertices.push_back(center + Vec3f(float(radius * std::sin(polar) * std::cos(azimuth)),
                                          float(radius * std::cos(polar)),
                                          float(radius * std::sin(polar) * std::sin(azimuth))));
    }
  }
  const std::uint32_t south = std::uint32_t(m.vertices.size());
  m.vertices.push_back(center - Vec3f(0, radius, 0));
  auto ring = [segments](std::uint32_t r, std::uint32_t s) {
    return 1 + (r - 1) * segments + s % segments;
  };
  // Azimuth grows from +x towards +z, so seen from outside (c, b) follows (a) clockwise unless the
  // order is (a, next, this): these windings make every normal point outwards.
  for (std::uint32_t s = 0; s < segments; ++s) {
    m.triangles.push_back({0, ring(1, s + 1), ring(1, s)});
    for (std::uint32_t r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s + 1)});
      m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r + 1, s)});
    }
    m.triangles.push_back({south, ring(rings - 1, s), ring(rings - 1, s + 1)});
  }
  m.validate("sphereMesh");
  return m;
}

}  // namespace simdphys

// Indexed triangle meshes: vertices and triangles as index triples, procedural meshes, and
// Wavefront OBJ loading. A mesh is plain data; mesh_bvh.hpp builds the structure that queries it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "simdphys/geometry3d/primitives.hpp"

namespace simdphys {

struct Mesh {
  std::vector<Vec3f> vertices;
  // Each triangle's vertex indices; its front face is counter-clockwise (primitives.hpp).
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t size() const { return triangles.size(); }
  Triangle triangle(std::size_t i) const {
    const auto& t = triangles[i];
    return {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
  }
  // Throws Error naming `where` and the element: a vertex not finite or outside the supported
  // range (|coordinate| <= kMaxCoordinate, math.hpp), an index out of range, or a
  // degenerate triangle (its normal, computed in double, exactly zero: the raycast never hits it,
  // so it could only hide mistakes).
  void validate(std::string_view where) const;
};

// A heightfield of columns x rows vertices over [x0, x1] x [z0, z1]: vertex (i, j) (i along x, j
// along z) has index j * columns + i, x = x0 + (x1 - x0) * i / (columns - 1) and likewise z (both
// computed in double, rounded once), y = height(x, z) with the rounded x and z, rounded once.
// Cell (i, j), j outer, i inner, gives the triangles (v(i,j), v(i+1,j), v(i+1,j+1)) and
// (v(i,j), v(i+1,j+1), v(i,j+1)): the layout of workload W2.
Mesh heightfieldMesh(std::uint32_t columns, std::uint32_t rows, double x0, double x1, double z0,
                     double z1, const std::function<double(double, double)>& height);
// The 12 triangles of a box's faces, facing out.
Mesh boxMesh(const Aabb& box);
// A UV sphere: `rings` bands of latitude (>= 2) and `segments` of longitude (>= 3), facing out.
Mesh sphereMesh(const Vec3f& center, float radius, std::uint32_t rings, std::uint32_t segments);

// Reads a Wavefront OBJ file's vertices and faces (polygons triangulated by tinyobjloader; normals,
// texture coordinates and materials are ignored). Throws Error naming the file and, where the
// parser tells, the line: a missing or unreadable file, a malformed line, an index out of range,
// and everything validate() rejects.
Mesh loadObj(const std::string& path);

}  // namespace simdphys

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
  // The vertices' box; a point at the origin for a mesh without vertices.
  Aabb bounds() const;
};

// Which triangle edges a body resting on the mesh may meet as edges (Jolt's active edges,
// Bullet's btInternalEdgeUtility): bit e of triangle i is set when its edge from vertex e to
// vertex e + 1 is on the boundary, shared by more than two triangles, or a convex crease (the
// neighbour falls away behind the triangle's plane) sharper than kActiveEdgeCosine between the
// two normals. Edges inside a flat or concave region are inactive: a box sliding over them meets
// the faces only, never a ghost edge between two coplanar triangles. Edges are matched by their
// vertex indices (a mesh that repeats a vertex is not welded).
inline constexpr float kActiveEdgeCosine = 0.999f;  // about 2.6 degrees
std::vector<std::uint8_t> activeEdges(const Mesh& mesh);

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

// Reads a Wavefront OBJ file's vertices and faces. The subset read: `v x y z` (optionally followed
// by w, or by a colour r g b, ignored), `f` with at least 3 corners of the forms v, v/vt, v//vn,
// v/vt/vn (1-based indices, or negative ones counting back from the last element defined),
// `vt` and `vn` (their indices are checked, their values ignored), comments (`#` to the end of
// the line), and o, g, s, usemtl, mtllib and l (ignored). A quad is cut along its shorter
// diagonal (the other one if only that lies inside it), a larger polygon is ear-clipped (a
// convex one becomes a fan around its first vertex).
// Throws Error naming the file and the line and saying what is wrong: a missing, unreadable or
// directory path, an unknown statement, a token that is not a number or an integer (whole), a
// value not finite or a coordinate beyond kMaxCoordinate (math.hpp), a wrong count of numbers, a
// face of fewer than 3 vertices, an index out of range, a NUL byte, a degenerate triangle or a
// polygon that cannot be triangulated; a file without faces is an error too.
Mesh loadObj(const std::string& path);
// The same for OBJ text in memory; errors name the function and `name` in place of the file.
Mesh parseObj(std::string_view text, std::string_view name);

}  // namespace simdphys

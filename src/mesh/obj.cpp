// Wavefront OBJ through tinyobjloader. Its parser reports unreadable files and malformed lines in
// its error text (with the line where it knows it); indices it accepts are checked here, since it
// does not bound them by the vertex count.
#include <tiny_obj_loader.h>

#include <fstream>
#include <string>

#include "simdphys/mesh.hpp"

namespace simdphys {

Mesh loadObj(const std::string& path) {
  const std::string where = "loadObj: " + path;
  if (!std::ifstream(path)) throw Error(where + ": cannot open the file");
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;  // polygons become triangles (a quad: along its shorter diagonal)
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config) || !reader.Error().empty()) {
    std::string message = reader.Error();
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw Error(where + ": " + (message.empty() ? "the parser failed" : message));
  }
  Mesh m;
  const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
  m.vertices.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    m.vertices.emplace_back(float(xyz[i]), float(xyz[i + 1]), float(xyz[i + 2]));
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    std::size_t next = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const unsigned corners = shape.mesh.num_face_vertices[f];
      if (corners != 3)
        throw Error(where + ": shape '" + shape.name + "' face " + std::to_string(f) + " has " +
                    std::to_string(corners) + " vertices after triangulation");
      std::array<std::uint32_t, 3> t{};
      for (unsigned k = 0; k < 3; ++k) {
        const int v = indices[next + k].vertex_index;
        if (v < 0 || std::size_t(v) >= m.vertices.size())
          throw Error(where + ": shape '" + shape.name + "' face " + std::to_string(f) +
                      ": vertex index " + std::to_string(v + 1) + " is out of range (" +
                      std::to_string(m.vertices.size()) + " vertices)");
        t[k] = std::uint32_t(v);
      }
      next += corners;
      m.triangles.push_back(t);
    }
  }
  m.validate(where);
  return m;
}

}  // namespace simdphys

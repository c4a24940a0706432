// Wavefront OBJ loading: a file's mesh, and errors that name the file and what is wrong.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "expect_error.hpp"
#include "simdphys/mesh.hpp"

namespace simdphys {
namespace {

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(LoadObj, ReadsVerticesAndTriangulatesPolygons) {
  const std::string path = writeFile("quad.obj",
                                     "# a unit quad and a triangle\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\n"
                                     "f 1 2 3 4\nf 1/1/1 2/2/2 5/3/3\n");
  const Mesh m = loadObj(path);
  ASSERT_EQ(m.vertices.size(), 5u);
  // The quad as two triangles (tinyobjloader cuts a quad along its shorter diagonal; both have
  // length sqrt(2) here, and it takes 2-4), then the triangle.
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 3}));
  EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{1, 2, 3}));
  EXPECT_EQ(m.triangles[2], (std::array<std::uint32_t, 3>{0, 1, 4}));
  EXPECT_EQ(m.vertices[2], Vec3f(1, 0, 1));
}

TEST(LoadObj, ErrorsNameTheFileAndTheProblem) {
  test::expectError([] { loadObj("/nonexistent/mesh.obj"); },
                    "loadObj: /nonexistent/mesh.obj: cannot open the file");
  const std::string range = writeFile("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  test::expectError([&] { loadObj(range); }, "range.obj");
  test::expectError([&] { loadObj(range); }, "out of range");
  const std::string flat = writeFile("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  test::expectError([&] { loadObj(flat); },
                    "flat.obj: triangle 0 (vertices 0, 1, 2) is degenerate");
  const std::string nan = writeFile("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n");
  test::expectError([&] { loadObj(nan); }, "nan.obj");
}

}  // namespace
}  // namespace simdphys

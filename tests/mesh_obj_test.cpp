// Wavefront OBJ loading: a file's mesh, and errors that name the file, the line and what is wrong.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "expect_error.hpp"
#include "simdphys/mesh.hpp"

namespace simdphys {
namespace {

using Tri = std::array<std::uint32_t, 3>;

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(LoadObj, ReadsVerticesAndTriangulatesPolygons) {
  const std::string path = writeFile("quad.obj",
                                     "# a unit quad and a triangle\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0 1 0\n"
                                     "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 1 0\nvn 0 0 1\nvn 1 0 0\n"
                                     "f 1 2 3 4\nf 1/1/1 2/2/2 5/3/3\n");
  const Mesh m = loadObj(path);
  ASSERT_EQ(m.vertices.size(), 5u);
  // The quad as two triangles, cut along its shorter diagonal; both have length sqrt(2) here, and
  // a tie takes 2-4 (as tinyobjloader, the loader before, did). Then the triangle.
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.triangles[0], (Tri{0, 1, 3}));
  EXPECT_EQ(m.triangles[1], (Tri{1, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Tri{0, 1, 4}));
  EXPECT_EQ(m.vertices[2], Vec3f(1, 0, 1));
}

TEST(LoadObj, ReadsEveryCornerFormNegativeIndicesAndCrlf) {
  const std::string path = writeFile("forms.obj",
                                     "o thing\r\ng part\r\ns off\r\nusemtl m\r\nmtllib a.mtl\r\n"
                                     "v 0 0 0 1\r\nv +1.5 0 0\r\nv 0 2e0 0 0.5 0.5 0.5\r\n"
                                     "v 0 0 3  # a comment after the data\r\n"
                                     "vt 0 0\r\nvt 1\r\nvn 0 0 1\r\n"
                                     "f 1/1 2/2 3/1\r\n"
                                     "f 1//1 2//1 4//1\r\n"
                                     "f -4/-2/-1 -2/-1/-1 -1/-2/-1\r\n"
                                     "l 1 2\r\n");
  const Mesh m = loadObj(path);
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[1], Vec3f(1.5f, 0, 0));  // '+' accepted, w and colour ignored
  EXPECT_EQ(m.vertices[2], Vec3f(0, 2, 0));
  EXPECT_EQ(m.vertices[3], Vec3f(0, 0, 3));
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.triangles[0], (Tri{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Tri{0, 1, 3}));
  EXPECT_EQ(m.triangles[2], (Tri{0, 2, 3}));  // -4, -2, -1 of 4 vertices
}

// The render example's house: quads (rectangles: equal diagonals, so each is cut along 2-4) and
// convex pentagons (fans around their first vertex). Expected triangles worked out by hand from
// the faces of the file, 0-based.
TEST(LoadObj, ReadsTheRenderExamplesHouse) {
  const Mesh m = loadObj(SIMDPHYS_SOURCE_DIR "/examples/render/house.obj");
  ASSERT_EQ(m.vertices.size(), 10u);
  EXPECT_EQ(m.vertices[8], Vec3f(-1, 2, 0));
  EXPECT_EQ(m.vertices[6], Vec3f(1, 1.2f, 1));
  const std::vector<Tri> expected = {
      {0, 1, 3}, {1, 2, 3},             // f 1 2 3 4
      {0, 4, 1}, {4, 5, 1},             // f 1 5 6 2
      {3, 2, 7}, {2, 6, 7},             // f 4 3 7 8
      {0, 3, 7}, {0, 7, 8}, {0, 8, 4},  // f 1 4 8 9 5
      {1, 5, 9}, {1, 9, 6}, {1, 6, 2},  // f 2 6 10 7 3
      {4, 8, 5}, {8, 9, 5},             // f 5 9 10 6
      {7, 6, 8}, {6, 9, 8},             // f 8 7 10 9
  };
  EXPECT_EQ(m.triangles, expected);
}

// A polygon that a fan would get wrong: an L whose first corner is next to the reflex one, and a
// dart (arrowhead) quad whose shorter diagonal lies outside it. Expected triangles by hand (ear
// clipping from the second corner on; the dart's inner diagonal); their areas must sum to the
// polygon's and all face +z, as the polygons do.
TEST(LoadObj, TriangulatesNonConvexPolygonsInside) {
  const Mesh l = loadObj(writeFile("ell.obj",
                                   "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\n"
                                   "f 1 2 3 4 5 6\n"));
  EXPECT_EQ(l.triangles, (std::vector<Tri>{{1, 2, 3}, {1, 3, 4}, {0, 1, 4}, {0, 4, 5}}));
  const Mesh dart = loadObj(writeFile("dart.obj",
                                      "v 0 -1 0\nv 4 0 0\nv 0 1 0\nv 1 0 0\n"
                                      "f 1 2 3 4\n"));
  EXPECT_EQ(dart.triangles, (std::vector<Tri>{{0, 1, 3}, {1, 2, 3}}));
  for (const auto& [m, area] : {std::pair{&l, 3.0f}, std::pair{&dart, 3.0f}}) {
    float sum = 0;
    for (std::size_t i = 0; i < m->size(); ++i) {
      const float z = m->triangle(i).normal().z();  // exact: small integer coordinates
      EXPECT_GT(z, 0) << "triangle " << i;
      sum += z / 2;
    }
    EXPECT_EQ(sum, area);
  }
}

// The supported range (math.hpp) ends at kMaxCoordinate = 1e18f: "1e18" and "-1e18" round to it
// and load; a value that rounds to a float past it does not (also "far.obj" and "big.obj" below).
TEST(LoadObj, CoordinatesUpToTheSupportedRangeLoad) {
  const Mesh m = parseObj("v -1e18 0 0\nv 1e18 0 0\nv 0 1e18 -1e18\nf 1 2 3\n", "edge");
  EXPECT_EQ(m.vertices[0], Vec3f(-kMaxCoordinate, 0, 0));
  EXPECT_EQ(m.vertices[2], Vec3f(0, kMaxCoordinate, -kMaxCoordinate));
  test::expectError([] { parseObj("v 1.0000001e18 0 0\n", "past"); },
                    "parseObj: past: line 1: x '1.0000001e18' is outside the supported range");
}

TEST(LoadObj, ParsesTextInMemory) {
  const Mesh m = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "memory");
  EXPECT_EQ(m.triangles, (std::vector<Tri>{{0, 1, 2}}));
  test::expectError([] { parseObj("v 0 0 0\nv 1 0 0\nf 1 2\n", "memory"); },
                    "parseObj: memory: line 3: a face needs at least 3 vertices, not 2");
}

// Every malformed file is an Error naming the file, the line and what is wrong (the reproducers
// of issue 11 first: tinyobjloader loaded each of them silently).
TEST(LoadObj, MalformedFilesAreErrorsNamingFileAndLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const struct {
    const char* name;
    std::string text;
    const char* error;
  } cases[] = {
      {"nan.obj", "v 0 0 0\nv nan 0 0\n", "nan.obj: line 2: x 'nan' is not finite"},
      {"inf.obj", "v inf 0 0\n", "inf.obj: line 1: x 'inf' is not finite"},
      {"abc.obj", "v abc 0 0\n", "abc.obj: line 1: x 'abc' is not a number"},
      {"two.obj", "v 1 2\n", "two.obj: line 1: a vertex needs x y z (then optionally w, or r g b)"},
      {"exp.obj", "v 0 1e2147483649 0\n", "exp.obj: line 1: y '1e2147483649' is out of range"},
      {"face1.obj", tri + "f 1\n", "face1.obj: line 4: a face needs at least 3 vertices, not 1"},
      {"face2.obj", tri + "f 1 2\n", "face2.obj: line 4: a face needs at least 3 vertices, not 2"},
      {"wrap.obj", tri + "f 1 2 4294967299\n",
       "wrap.obj: line 4: vertex index '4294967299' is out of range (3 defined so far)"},
      {"nul.obj", tri + std::string("f 1 2 3\0\nv 0 0 1\n", 17) + "f 1 2 4\n",
       "nul.obj: line 4: contains a NUL byte"},
      // The supported range (math.hpp): |coordinate| <= kMaxCoordinate = 1e18.
      {"far.obj", "v 0 0 -1.01e18\n",
       "far.obj: line 1: z '-1.01e18' is outside the supported range [-1e18, 1e18]"},
      {"big.obj", "v 0 0 1e39\n", "big.obj: line 1: z '1e39' is outside the supported range"},
      {"trail.obj", "v 0 0 1x\n", "trail.obj: line 1: z '1x' is not a number"},
      {"hex.obj", "v 0x10 0 0\n", "hex.obj: line 1: x '0x10' is not a number"},
      {"w.obj", "v 0 0 0 nan\n", "w.obj: line 1: w 'nan' is not finite"},
      {"many.obj", "v 0 0 0 1 1\n", "many.obj: line 1: a vertex needs x y z"},
      {"zero.obj", tri + "f 0 1 2\n", "zero.obj: line 4: vertex index '0' is out of range"},
      {"back.obj", tri + "f -1 -2 -4\n", "back.obj: line 4: vertex index '-4' is out of range"},
      {"later.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n",
       "later.obj: line 3: vertex index '3' is out of range (2 defined so far)"},
      {"int.obj", tri + "f 1 2 3.0\n", "int.obj: line 4: vertex index '3.0' is not an integer"},
      {"vt.obj", tri + "vt 0 0\nf 1/1 2/2 3/1\n",
       "vt.obj: line 5: texture coordinate index '2' is out of range (1 defined so far)"},
      {"vn.obj", tri + "f 1//1 2//1 3//1\n",
       "vn.obj: line 4: normal index '1' is out of range (0 defined so far)"},
      {"parts.obj", tri + "f 1/1/1/1 2 3\n",
       "parts.obj: line 4: face corner '1/1/1/1' has more than 3 parts"},
      {"vnbad.obj", "vn 0 0\n", "vnbad.obj: line 1: a normal needs 3 numbers, not 2"},
      {"stmt.obj", tri + "curv 0 1 1 2\n", "stmt.obj: line 4: unsupported statement 'curv'"},
      {"flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\n\nf 1 2 3\n",
       "flat.obj: line 5: the triangle of vertices 1, 2, 3 is degenerate: its vertices are "
       "collinear"},
      {"line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\nf 1 2 3 4 5\n",
       "line.obj: line 6: the polygon is degenerate: it encloses no area"},
      // A heptagon whose edges cross (found by a search over small integer polygons): no ear is
      // left to clip.
      {"cross.obj",
       "v 1 3 0\nv 3 4 0\nv 0 4 0\nv 2 2 0\nv 2 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3 4 5 6 7\n",
       "cross.obj: line 8: the polygon cannot be triangulated: it intersects itself"},
      {"empty.obj", "", "empty.obj: the file has no faces"},
      {"nofaces.obj", tri + "# nothing else\n", "nofaces.obj: the file has no faces"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = writeFile(c.name, c.text);
    test::expectError([&] { loadObj(path); }, "loadObj: " + path + ": ");
    test::expectError([&] { loadObj(path); }, c.error);
  }
}

TEST(LoadObj, UnreadablePathsAreErrors) {
  test::expectError([] { loadObj("/nonexistent/mesh.obj"); },
                    "loadObj: /nonexistent/mesh.obj: cannot open the file");
  const std::string dir = ::testing::TempDir() + "dir.obj";
  std::filesystem::create_directories(dir);
  test::expectError([&] { loadObj(dir); }, "loadObj: " + dir + ": is a directory");
}

}  // namespace
}  // namespace simdphys

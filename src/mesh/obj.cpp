// Wavefront OBJ: a strict parser for the subset a triangle mesh needs. Every line is checked as it
// is read (numbers with std::from_chars, whole tokens only; indices against the elements defined
// so far), so a malformed file is an Error naming the file, the line and the fault, never a mesh
// with silently dropped or zeroed parts.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "simdphys/geometry3d/raycast.hpp"  // triangleNormalWide: the raycast's degeneracy test
#include "simdphys/mesh.hpp"

namespace simdphys {
namespace {

using Corners = std::vector<std::uint32_t>;  // a face's vertex indices, 0-based
using Tri = std::array<std::uint32_t, 3>;

bool isBlank(char c) { return c == ' ' || c == '\t'; }

// A token as it may appear in a message: at most 32 bytes, unprintable bytes as '?'.
std::string quoted(std::string_view token) {
  std::string s = "'";
  for (char c : token.substr(0, 32)) s += (c >= 0x20 && c < 0x7f) ? c : '?';
  return s + (token.size() > 32 ? "...'" : "'");
}

class ObjParser {
 public:
  explicit ObjParser(std::string where) : where_(std::move(where)) {}

  Mesh parse(std::string_view text) {
    while (!text.empty()) {
      ++line_;
      const std::size_t end = std::min(text.find('\n'), text.size());
      parseLine(text.substr(0, end));
      text.remove_prefix(std::min(end + 1, text.size()));
    }
    if (mesh_.triangles.empty()) throw Error(where_ + ": the file has no faces");
    mesh_.validate(where_);  // already checked line by line; the mesh's own contract, restated
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(where_ + ": line " + std::to_string(line_) + ": " + what);
  }

  void parseLine(std::string_view s) {
    if (s.find('\0') != std::string_view::npos) fail("contains a NUL byte");
    s = s.substr(0, s.find('#'));  // a comment runs to the end of the line
    tokens_.clear();
    for (std::size_t i = 0; i < s.size();) {
      while (i < s.size() && (isBlank(s[i]) || s[i] == '\r')) ++i;
      const std::size_t start = i;
      while (i < s.size() && !isBlank(s[i]) && s[i] != '\r') ++i;
      if (i > start) tokens_.push_back(s.substr(start, i - start));
    }
    if (tokens_.empty()) return;
    const std::string_view keyword = tokens_[0];
    const std::span<const std::string_view> args(tokens_.data() + 1, tokens_.size() - 1);
    if (keyword == "v") {
      vertex(args);
    } else if (keyword == "vt") {
      numbers(args, 1, 3, "a texture coordinate");
      ++texcoords_;
    } else if (keyword == "vn") {
      numbers(args, 3, 3, "a normal");
      ++normals_;
    } else if (keyword == "f") {
      face(args);
    } else if (keyword != "o" && keyword != "g" && keyword != "s" && keyword != "usemtl" &&
               keyword != "mtllib" && keyword != "l") {
      // Names, smoothing groups, materials and polylines carry no surface; anything else (curves,
      // surfaces, a typo) would be dropped silently.
      fail("unsupported statement " + quoted(keyword));
    }
  }

  // A finite decimal number (an optional leading '+', as some writers emit, then what
  // std::from_chars reads), the whole token.
  double number(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
    double x = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
    if (ec == std::errc::result_out_of_range)
      fail(std::string(what) + " " + quoted(token) + " is out of range");
    if (ec != std::errc() || end != digits.data() + digits.size())
      fail(std::string(what) + " " + quoted(token) + " is not a number");
    if (!std::isfinite(x)) fail(std::string(what) + " " + quoted(token) + " is not finite");
    return x;
  }

  void numbers(std::span<const std::string_view> args, std::size_t least, std::size_t most,
               const char* what) const {
    if (args.size() < least || args.size() > most)
      fail(std::string(what) + " needs " + std::to_string(least) +
           (most > least ? " to " + std::to_string(most) : std::string()) + " numbers, not " +
           std::to_string(args.size()));
    for (std::string_view a : args) number(a, "the value");
  }

  // "v x y z", optionally followed by w or by a colour r g b (checked, then ignored).
  void vertex(std::span<const std::string_view> args) {
    if (args.size() != 3 && args.size() != 4 && args.size() != 6)
      fail("a vertex needs x y z (then optionally w, or r g b), not " +
           std::to_string(args.size()) + " numbers");
    Vec3f p;
    static constexpr const char* kAxis[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      p[k] = float(number(args[k], kAxis[k]));  // the range applies to the float ("1e18" is in)
      if (std::abs(p[k]) > kMaxCoordinate)
        fail(std::string(kAxis[k]) + " " + quoted(args[k]) +
             " is outside the supported range [-1e18, 1e18]");
    }
    for (std::size_t k = 3; k < args.size(); ++k) number(args[k], k == 3 ? "w" : "a colour");
    if (mesh_.vertices.size() == std::numeric_limits<std::uint32_t>::max())
      fail("more vertices than 32-bit indices can name");
    mesh_.vertices.push_back(p);
  }

  // An index of an element (1-based, or negative: relative to the last one defined so far),
  // checked against the `count` defined so far; returns it 0-based.
  std::uint32_t index(std::string_view token, std::size_t count, const char* kind) const {
    long long i = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), i);
    if (ec == std::errc::invalid_argument || end != token.data() + token.size())
      fail(std::string(kind) + " index " + quoted(token) + " is not an integer");
    const long long resolved = i > 0 ? i - 1 : (long long)count + i;  // i < 0 counts back
    if (ec == std::errc::result_out_of_range || i == 0 || resolved < 0 ||
        resolved >= (long long)count)
      fail(std::string(kind) + " index " + quoted(token) + " is out of range (" +
           std::to_string(count) + " defined so far)");
    return std::uint32_t(resolved);
  }

  // "f" and at least three corners, each v, v/vt, v//vn or v/vt/vn.
  void face(std::span<const std::string_view> args) {
    if (args.size() < 3)
      fail("a face needs at least 3 vertices, not " + std::to_string(args.size()));
    corners_.clear();
    for (std::string_view corner : args) {
      std::string_view part[3];
      int parts = 0;
      for (std::size_t start = 0;; ++parts) {
        const std::size_t slash = corner.find('/', start);
        if (parts == 3) fail("face corner " + quoted(corner) + " has more than 3 parts");
        part[parts] = corner.substr(start, slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
      }
      corners_.push_back(index(part[0], mesh_.vertices.size(), "vertex"));
      if (!part[1].empty()) index(part[1], texcoords_, "texture coordinate");
      if (!part[2].empty()) index(part[2], normals_, "normal");
    }
    triangulate();
  }

  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Tri t{a, b, c};
    if ((detail::rays::triangleNormalWide(triangleOf(t)).array() == 0).all())
      fail("the triangle of vertices " + std::to_string(a + 1) + ", " + std::to_string(b + 1) +
           ", " + std::to_string(c + 1) + " is degenerate: its vertices are collinear");
    mesh_.triangles.push_back(t);
  }

  Triangle triangleOf(const Tri& t) const {
    return {mesh_.vertices[t[0]], mesh_.vertices[t[1]], mesh_.vertices[t[2]]};
  }

  // A quad is cut along its shorter diagonal (compared in float, as tinyobjloader, which loaded
  // these files before, did), unless only the other one lies inside it (a dart). A larger polygon
  // is ear-clipped, each ear taken at the first remaining corner from the second on: a convex
  // polygon becomes a fan around its first vertex, as before.
  void triangulate() {
    const Corners& c = corners_;
    if (c.size() == 3) return addTriangle(c[0], c[1], c[2]);
    if (c.size() == 4) {
      auto sq = [&](std::uint32_t i, std::uint32_t j) {
        const Vec3f d = mesh_.vertices[j] - mesh_.vertices[i];
        return d.x() * d.x() + d.y() * d.y() + d.z() * d.z();
      };
      // The diagonal from corner s to s + 2 lies inside when the triangles on its two sides face
      // the same way.
      auto interior = [&](int s) {
        const Vec3d n0 = detail::rays::triangleNormalWide(triangleOf({c[s], c[s + 1], c[s + 2]}));
        const Vec3d n1 =
            detail::rays::triangleNormalWide(triangleOf({c[s], c[s + 2], c[(s + 3) % 4]}));
        return n0.dot(n1) > 0;
      };
      const bool shorter02 = sq(c[0], c[2]) < sq(c[1], c[3]);
      const bool use02 = shorter02 ? interior(0) || !interior(1) : interior(0) && !interior(1);
      if (use02) {
        addTriangle(c[0], c[1], c[2]);
        addTriangle(c[0], c[2], c[3]);
      } else {
        addTriangle(c[0], c[1], c[3]);
        addTriangle(c[1], c[2], c[3]);
      }
      return;
    }
    earClip();
  }

  void earClip() {
    // The polygon in the plane of its Newell normal, with the axis of its largest component
    // dropped; `sign` makes its winding counter-clockwise there.
    Vec3d normal = Vec3d::Zero();
    for (std::size_t i = 0; i < corners_.size(); ++i) {
      const Vec3d p = mesh_.vertices[corners_[i]].cast<double>();
      const Vec3d q = mesh_.vertices[corners_[(i + 1) % corners_.size()]].cast<double>();
      normal += Vec3d((p.y() - q.y()) * (p.z() + q.z()), (p.z() - q.z()) * (p.x() + q.x()),
                      (p.x() - q.x()) * (p.y() + q.y()));
    }
    int axis;
    const double largest = normal.cwiseAbs().maxCoeff(&axis);
    if (!(largest > 0)) fail("the polygon is degenerate: it encloses no area");
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    const double sign = normal[axis] > 0 ? 1 : -1;
    auto at = [&](std::uint32_t v) { return Vec2d(mesh_.vertices[v][u], mesh_.vertices[v][w]); };
    auto orient = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
      return sign * detail::rays::orient2d(at(p), at(q), at(r));
    };
    Corners& left = corners_;
    while (left.size() > 3) {
      const std::size_t n = left.size();
      std::size_t ear = n;
      for (std::size_t k = 1; k <= n && ear == n; ++k) {
        const std::size_t i = k % n;
        const std::uint32_t p = left[(i + n - 1) % n], q = left[i], r = left[(i + 1) % n];
        if (!(orient(p, q, r) > 0)) continue;  // a reflex or straight corner
        bool empty = true;                     // no other corner in the closed triangle
        for (std::size_t j = 0; j < n && empty; ++j) {
          const std::uint32_t o = left[j];
          if (o == p || o == q || o == r) continue;
          empty = !(orient(p, q, o) >= 0 && orient(q, r, o) >= 0 && orient(r, p, o) >= 0);
        }
        if (empty) ear = i;
      }
      if (ear == n) fail("the polygon cannot be triangulated: it intersects itself");
      addTriangle(left[(ear + n - 1) % n], left[ear], left[(ear + 1) % n]);
      left.erase(left.begin() + std::ptrdiff_t(ear));
    }
    addTriangle(left[0], left[1], left[2]);
  }

  std::string where_;
  std::size_t line_ = 0;
  std::size_t texcoords_ = 0, normals_ = 0;
  std::vector<std::string_view> tokens_;
  Corners corners_;
  Mesh mesh_;
};

}  // namespace

Mesh parseObj(std::string_view text, std::string_view name) {
  return ObjParser("parseObj: " + std::string(name)).parse(text);
}

Mesh loadObj(const std::string& path) {
  const std::string where = "loadObj: " + path;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(where + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(where + ": cannot open the file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw Error(where + ": cannot read the file");
  return ObjParser(where).parse(text);
}

}  // namespace simdphys

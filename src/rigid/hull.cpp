// HullShape (rigid/hull.hpp): the hull of a point set by incremental construction, its coplanar
// triangles merged into polygon faces, and its mass properties, all in double.
#include "simdphys/rigid/hull.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

#include "src/reference/validate-inl.hpp"

namespace simdphys {

namespace {

struct Triangle {
  int v[3];
  Vec3d n;
  double d;
  bool alive = true;
};

Triangle triangle(const std::vector<Vec3d>& p, int a, int b, int c) {
  Triangle t{{a, b, c},
             (p[std::size_t(b)] - p[std::size_t(a)])
                 .cross(p[std::size_t(c)] - p[std::size_t(a)])
                 .normalized(),
             0};
  t.d = t.n.dot(p[std::size_t(a)]);
  return t;
}

// The hull's triangles, outward, by adding one point at a time to a first tetrahedron: the faces
// a point sees go, and the edges between seen and unseen faces (the horizon) are joined to it.
// `eps`: how far from a line or plane the first tetrahedron's corners must be (else the points are
// flat).
std::vector<Triangle> hullTriangles(const std::vector<Vec3d>& p, double eps,
                                    const std::string& where) {
  const std::size_t n = p.size();
  const auto farthest = [&](auto distance) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (distance(p[i]) > distance(p[best])) best = i;
    return best;
  };
  const std::size_t i0 = farthest([&](const Vec3d& x) { return -x.x(); });
  const std::size_t i1 = farthest([&](const Vec3d& x) { return (x - p[i0]).squaredNorm(); });
  const Vec3d axis = (p[i1] - p[i0]).normalized();
  const auto offLine = [&](const Vec3d& x) { return (x - p[i0]).cross(axis).norm(); };
  const std::size_t i2 = farthest(offLine);
  const Vec3d normal = (p[i1] - p[i0]).cross(p[i2] - p[i0]).normalized();
  const auto offPlane = [&](const Vec3d& x) { return std::abs(normal.dot(x - p[i0])); };
  const std::size_t i3 = farthest(offPlane);
  if ((p[i1] - p[i0]).norm() <= eps || offLine(p[i2]) <= eps || offPlane(p[i3]) <= eps)
    throw Error(where + ": the points are flat (within " + std::to_string(eps) +
                " m of one plane), not a solid");

  const int a = int(i0), b = int(i1), c = int(i2), d = int(i3);
  std::vector<Triangle> tris;
  if (normal.dot(p[i3] - p[i0]) < 0)
    tris = {triangle(p, a, b, c), triangle(p, a, d, b), triangle(p, b, d, c), triangle(p, c, d, a)};
  else
    tris = {triangle(p, a, c, b), triangle(p, a, b, d), triangle(p, b, c, d), triangle(p, c, a, d)};

  // Farthest point first (as quickhull takes them). A point within a tenth of eps of every face's
  // plane (float input's rounding is well below that) adds nothing: it stays that near as the
  // hull grows, and is dropped from the candidates. Near-coplanar faces are merged afterwards.
  const double nearEnough = 0.1 * eps;
  std::vector<std::size_t> outside(n);
  for (std::size_t i = 0; i < n; ++i) outside[i] = i;
  std::vector<std::pair<int, int>> seenEdges;
  for (;;) {
    std::size_t best = n;
    double most = nearEnough;
    std::erase_if(outside, [&](std::size_t i) {
      double out = -std::numeric_limits<double>::infinity();
      for (const Triangle& t : tris) out = std::max(out, t.n.dot(p[i]) - t.d);
      if (out > most) most = out, best = i;
      return !(out > nearEnough);
    });
    if (best == n) break;
    seenEdges.clear();
    for (Triangle& t : tris)
      if (t.n.dot(p[best]) - t.d > 1e-9 * eps) {  // every face it sees, however little
        t.alive = false;
        for (int k = 0; k < 3; ++k) seenEdges.emplace_back(t.v[k], t.v[(k + 1) % 3]);
      }
    for (const auto& [u, v] : seenEdges)
      if (std::find(seenEdges.begin(), seenEdges.end(), std::pair(v, u)) == seenEdges.end())
        tris.push_back(triangle(p, u, v, int(best)));
    std::erase_if(tris, [](const Triangle& t) { return !t.alive; });
    if (tris.size() > 4 * std::size_t(HullShape::kMaxVertices))
      throw Error(where + ": the hull's vertex count is above 256");
  }
  return tris;
}

// The boundary of a set of triangles making one planar convex polygon, counter-clockwise around
// the normal, without the vertices that lie on a straight run of it; empty if the boundary is not
// one simple loop (slivers of a thin shape can pinch it), and the triangles then stay faces.
std::vector<int> boundary(const std::vector<Triangle>& tris, const std::vector<int>& group,
                          const std::vector<Vec3d>& p, double eps) {
  std::vector<std::pair<int, int>> edges;
  for (const int t : group)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(tris[std::size_t(t)].v[k], tris[std::size_t(t)].v[(k + 1) % 3]);
  std::map<int, int> next;  // the boundary: the edges whose reverse is not in the group
  std::size_t boundaryEdges = 0;
  for (const auto& [u, v] : edges)
    if (std::find(edges.begin(), edges.end(), std::pair(v, u)) == edges.end())
      next[u] = v, ++boundaryEdges;
  if (next.size() != boundaryEdges) return {};
  std::vector<int> loop{next.begin()->first};
  while (int(loop.size()) <= int(next.size())) {
    const auto it = next.find(loop.back());
    if (it == next.end() || it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  if (loop.size() != boundaryEdges) return {};
  std::vector<int> out;
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3d& prev = p[std::size_t(loop[(k + loop.size() - 1) % loop.size()])];
    const Vec3d& here = p[std::size_t(loop[k])];
    const Vec3d& after = p[std::size_t(loop[(k + 1) % loop.size()])];
    // Dropped only where it lies on the segment between its neighbours (within eps of it).
    const Vec3d run = after - prev;
    const double along = (here - prev).dot(run);
    const bool between = along >= 0 && along <= run.squaredNorm();
    if (!between || (here - prev).cross(run).norm() > eps * run.norm()) out.push_back(loop[k]);
  }
  return out;
}

}  // namespace

HullShape::HullShape(std::span<const Vec3f> points, const std::string& where) {
  using detail::require;
  require(points.size() >= 4 && points.size() <= std::size_t(kMaxPoints), points.size(), where,
          "point count", "must be in [4, 4096]");
  std::vector<Vec3d> p;
  p.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string field = "point " + std::to_string(i);
    detail::requireFiniteField(points[i], where, field.c_str());
    require(points[i].cwiseAbs().maxCoeff() <= 1e6f, points[i].cwiseAbs().maxCoeff(), where,
            field.c_str(), "must be within 1e6 m of the shape's origin");
    p.push_back(points[i].cast<double>());
  }
  Vec3d lo = p[0], hi = p[0];
  for (const Vec3d& x : p) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  // Float input is rounded at 6e-8 of its magnitude: well above that is a real feature.
  const double eps = 1e-5 * (hi - lo).maxCoeff();
  const std::vector<Triangle> tris = hullTriangles(p, eps, where);
  // Near-degenerate input (points almost collinear with an edge) can leave a sliver whose normal
  // is rounding: then some corner lies outside a face, and the hull is refused, not kept wrong.
  const auto refuse = [&](const char* what) {
    throw Error(where + ": the points make no proper solid (" + what + ", within rounding)");
  };
  std::vector<int> corners;
  for (const Triangle& t : tris) corners.insert(corners.end(), std::begin(t.v), std::end(t.v));
  for (const Triangle& t : tris) {
    if (!t.n.allFinite()) refuse("a face has no normal");
    for (const int v : corners)
      if (t.n.dot(p[std::size_t(v)]) - t.d > eps) refuse("a corner lies outside a face");
  }

  // Faces: triangles joined across edges while every vertex stays within eps of the first's plane.
  std::vector<bool> grouped(tris.size(), false);
  std::vector<std::vector<int>> polygons;
  for (std::size_t s = 0; s < tris.size(); ++s) {
    if (grouped[s]) continue;
    std::vector<int> group{int(s)};
    grouped[s] = true;
    for (std::size_t g = 0; g < group.size(); ++g)
      for (std::size_t t = 0; t < tris.size(); ++t) {
        if (grouped[t] || tris[t].n.dot(tris[s].n) < 0.5) continue;
        const Triangle& u = tris[std::size_t(group[g])];
        int shared = 0;
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) shared += tris[t].v[j] == u.v[k] ? 1 : 0;
        const bool flat = std::all_of(std::begin(tris[t].v), std::end(tris[t].v), [&](int v) {
          return std::abs(tris[s].n.dot(p[std::size_t(v)]) - tris[s].d) <= eps;
        });
        if (shared == 2 && flat) group.push_back(int(t)), grouped[t] = true;
      }
    std::vector<int> polygon = boundary(tris, group, p, eps);
    if (polygon.empty())
      for (const int t : group)
        polygons.push_back({tris[std::size_t(t)].v, tris[std::size_t(t)].v + 3});
    else
      polygons.push_back(std::move(polygon));
    if (polygons.back().size() < 3) refuse("a face has fewer than 3 corners");
  }

  // The vertices the faces use, renumbered in order of first use.
  std::vector<int> number(p.size(), -1);
  std::vector<Vec3d> used;
  for (std::vector<int>& poly : polygons) {
    require(int(poly.size()) <= kMaxFaceVertices, poly.size(), where, "a face's vertex count",
            "must be at most 64");
    for (int& v : poly) {
      if (number[std::size_t(v)] < 0)
        number[std::size_t(v)] = int(used.size()), used.push_back(p[std::size_t(v)]);
      v = number[std::size_t(v)];
    }
  }
  require(int(used.size()) <= kMaxVertices, used.size(), where, "the hull's vertex count",
          "must be at most 256");

  // Mass properties of the solid, from tetrahedra joining a point inside to each face's fan:
  // volume, centroid and second moments (Tonon 2004's canonical tetrahedron).
  Vec3d inside = Vec3d::Zero();
  for (const Vec3d& v : used) inside += v;
  inside /= double(used.size());
  double volume = 0;
  Vec3d moment = Vec3d::Zero();
  Mat3d second = Mat3d::Zero();
  Mat3d canonical;
  canonical << 2, 1, 1, 1, 2, 1, 1, 1, 2;
  canonical /= 120;
  for (const std::vector<int>& poly : polygons)
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      Mat3d A;
      A.col(0) = used[std::size_t(poly[0])] - inside;
      A.col(1) = used[std::size_t(poly[k])] - inside;
      A.col(2) = used[std::size_t(poly[k + 1])] - inside;
      const double det = A.determinant();
      volume += det / 6;
      moment += det / 24 * (A.col(0) + A.col(1) + A.col(2));
      second += det * A * canonical * A.transpose();
    }
  const Vec3d c = moment / volume;  // from `inside`
  second -= volume * c * c.transpose();
  const Mat3d inertia = (second.trace() * Mat3d::Identity() - second) / volume;
  if (!(volume > 0) || !inertia.allFinite()) refuse("no volume");
  const Eigen::SelfAdjointEigenSolver<Mat3d> principal(inertia);
  if (!(principal.eigenvalues().minCoeff() > 0)) refuse("no volume");
  Mat3d R = principal.eigenvectors();
  if (R.determinant() < 0) R.col(2) = -R.col(2);

  centre_ = (inside + c).cast<float>();
  rotation_ = Quatf(Quatd(R).normalized().cast<float>());
  volume_ = float(volume);
  inertia_ = principal.eigenvalues().cast<float>();
  for (const Vec3d& v : used) vertices_.push_back((R.transpose() * (v - inside - c)).cast<float>());
  for (const Vec3f& v : vertices_) half_ = half_.cwiseMax(v.cwiseAbs());
  faceStart_.push_back(0);
  for (const std::vector<int>& poly : polygons) {
    // Newell's normal of the polygon, in the shape's frame.
    Vec3d normal = Vec3d::Zero();
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec3d a = vertices_[std::size_t(poly[k])].cast<double>();
      const Vec3d b = vertices_[std::size_t(poly[(k + 1) % poly.size()])].cast<double>();
      normal += Vec3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                      (a.x() - b.x()) * (a.y() + b.y()));
    }
    normal.normalize();
    double offset = 0;
    for (const int v : poly)
      offset = std::max(offset, normal.dot(vertices_[std::size_t(v)].cast<double>()));
    normals_.push_back(normal.cast<float>());
    offsets_.push_back(float(offset));
    for (const int v : poly) faceIndices_.push_back(std::uint8_t(v));
    faceStart_.push_back(std::uint32_t(faceIndices_.size()));
  }
}

}  // namespace simdphys

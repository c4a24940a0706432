// The definitions of simdphys/geometry3d/epa.hpp (EPA's polytope and its run): included by epa.cpp,
// which instantiates them for float and double, and by any file of src/ that wants them inlined.
#pragma once

#include "simdphys/geometry3d/epa.hpp"
#include "src/reference/geometry3d/gjk-inl.hpp"
#include "src/reference/math-inl.hpp"

namespace simdphys {

namespace detail {

template <class T>
struct EpaFace {
  std::array<int, 3> v{};     // vertex indices, counter-clockwise seen from outside
  std::array<int, 3> adj{};   // the face across edge m = (v[m], v[m+1])
  std::array<int, 3> edge{};  // which edge of that face it is
  Vec3<T> normal = Vec3<T>::Zero();
  T dist = 0;  // signed distance of the plane from the origin
  bool alive = true;
};

// A unit vector perpendicular to e (non-zero).
template <class T>
Vec3<T> perpendicular(const Vec3<T>& e) {
  int axis = 0;
  e.cwiseAbs().minCoeff(&axis);
  return unitOrZero<T>(e.cross(Vec3<T>::Unit(axis)));
}

template <class T>
class Polytope {
 public:
  std::vector<SupportPoint<T>> vertices;
  std::vector<EpaFace<T>> faces;
  Vec3<T> inside = Vec3<T>::Zero();  // the first tetrahedron's centroid, inside for good

  // The face (a, b, c) with its outward normal; false if its area vanishes or the normal points
  // towards the inside point.
  bool makeFace(int a, int b, int c, T tol, EpaFace<T>& f) const {
    const Vec3<T>& wa = vertices[a].w;
    const Vec3<T> n = (vertices[b].w - wa).cross(vertices[c].w - wa);
    const T length = n.norm();
    const T edges = (vertices[b].w - wa).norm() * (vertices[c].w - wa).norm();
    if (!(length > kGjkFlatTolerance<T> * edges) || !(length > 0)) return false;
    f = EpaFace<T>{};
    f.v = {a, b, c};
    f.normal = n / length;
    f.dist = f.normal.dot(wa);
    return f.normal.dot(wa - inside) > -tol;
  }
};

template <class T>
EpaCoreResult<T> epaCore(const CorePair<T>& cores, const Vec3<T>& origin, const GjkRun<T>& run,
                         const Vec3<T>& towardB) {
  EpaCoreResult<T> result;
  T scale = run.scale;
  for (int m = 0; m < run.simplex.size; ++m) scale = std::max(scale, run.simplex.p[m].w.norm());
  auto grow = [&](const Vec3<T>& d) {
    SupportPoint<T> p = cores(d, origin, run.unit);
    scale = std::max(scale, p.w.norm());
    return p;
  };
  auto tolerance = [&] { return kEpaTolerance<T> * scale; };
  // A flat difference: its interior is empty, so the depth is 0 along `normal`, at GJK's point.
  auto flat = [&](Vec3<T> normal) {
    if (normal.dot(towardB) < 0) normal = -normal;
    result.normal = normal;
    result.depth = 0;
    result.pointA = run.pointA();
    result.pointB = run.pointB();
    return result;
  };
  // Blow GJK's simplex up to a tetrahedron: each new vertex is the simplex's own or a support
  // point, whichever lies farthest from the span of the ones before.
  std::array<SupportPoint<T>, 4> p;
  p[0] = run.simplex.p[0];
  std::vector<SupportPoint<T>> candidates(run.simplex.p.begin() + 1,
                                          run.simplex.p.begin() + run.simplex.size);
  auto pick = [&](auto&& distance, const std::vector<Vec3<T>>& directions, SupportPoint<T>& out) {
    T best = -1;
    for (const SupportPoint<T>& c : candidates)
      if (const T d = distance(c.w); d > best) best = d, out = c;
    if (best > tolerance()) return true;
    for (const Vec3<T>& dir : directions) {
      const SupportPoint<T> c = grow(dir);
      if (const T d = distance(c.w); d > best) best = d, out = c;
    }
    return best > tolerance();
  };
  const std::vector<Vec3<T>> axes = {Vec3<T>::UnitX(),  -Vec3<T>::UnitX(), Vec3<T>::UnitY(),
                                     -Vec3<T>::UnitY(), Vec3<T>::UnitZ(),  -Vec3<T>::UnitZ()};
  if (!pick([&](const Vec3<T>& w) { return (w - p[0].w).norm(); }, axes, p[1]))
    return flat(towardB.squaredNorm() > 0 ? unitOrZero<T>(towardB) : Vec3<T>::UnitX());
  const Vec3<T> e = unitOrZero<T>(Vec3<T>(p[1].w - p[0].w));
  const Vec3<T> u1 = perpendicular(e), u2 = e.cross(u1);
  const std::vector<Vec3<T>> around = {u1, -u1, u2, -u2, u1 + u2, u1 - u2, -u1 + u2, -u1 - u2};
  if (!pick([&](const Vec3<T>& w) { return (w - p[0].w).cross(e).norm(); }, around, p[2])) {
    const Vec3<T> side = towardB - e * e.dot(towardB);
    return flat(side.squaredNorm() > 0 ? unitOrZero<T>(side) : u1);
  }
  const Vec3<T> n = unitOrZero<T>(Vec3<T>((p[1].w - p[0].w).cross(p[2].w - p[0].w)));
  if (!pick([&](const Vec3<T>& w) { return std::abs(n.dot(w - p[0].w)); }, {n, -n}, p[3]))
    return flat(n);
  if ((p[1].w - p[0].w).dot((p[2].w - p[0].w).cross(p[3].w - p[0].w)) < 0) std::swap(p[1], p[2]);

  Polytope<T> poly;
  poly.vertices.assign(p.begin(), p.end());
  poly.inside = (p[0].w + p[1].w + p[2].w + p[3].w) / T(4);
  static constexpr int kTetra[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : kTetra) {
    EpaFace<T> f;
    if (!poly.makeFace(t[0], t[1], t[2], tolerance(), f)) return flat(n);  // a sliver
    poly.faces.push_back(f);
  }
  for (int f = 0; f < 4; ++f)  // adjacency: the face holding the reversed edge
    for (int m = 0; m < 3; ++m)
      for (int g = 0; g < 4; ++g)
        for (int k = 0; k < 3; ++k)
          if (poly.faces[g].v[k] == poly.faces[f].v[(m + 1) % 3] &&
              poly.faces[g].v[(k + 1) % 3] == poly.faces[f].v[m])
            poly.faces[f].adj[m] = g, poly.faces[f].edge[m] = k;

  std::vector<std::pair<int, int>> horizon;  // (kept face, its edge) around the visible region
  std::vector<int> removed;
  std::vector<EpaFace<T>> fresh;
  int closest = 0;
  for (int iteration = 0;; ++iteration) {
    closest = -1;
    for (int f = 0; f < int(poly.faces.size()); ++f)
      if (poly.faces[f].alive && (closest < 0 || poly.faces[f].dist < poly.faces[closest].dist))
        closest = f;
    result.iterations = iteration;
    if (iteration >= kEpaMaxIterations) break;
    const EpaFace<T> face = poly.faces[closest];
    const SupportPoint<T> q = grow(face.normal);
    if (face.normal.dot(q.w) - face.dist <= tolerance()) break;  // the face is on the boundary

    // The faces that see q (or nearly: a face q lies on is replaced too, so no new face is a
    // sliver along its edge), found by walking from the closest face; their outline is the
    // horizon.
    const T tol = tolerance();
    horizon.clear(), removed.clear();
    auto sees = [&](int f) {
      const EpaFace<T>& g = poly.faces[f];
      return g.normal.dot(q.w - poly.vertices[g.v[0]].w) > -tol;
    };
    auto walk = [&](auto&& self, int f, int arrivedBy) -> void {
      if (!poly.faces[f].alive) return;
      if (!sees(f)) {
        horizon.emplace_back(f, arrivedBy);
        return;
      }
      poly.faces[f].alive = false;
      removed.push_back(f);
      for (int m = 1; m < 3; ++m) {
        const int k = (arrivedBy + m) % 3;
        self(self, poly.faces[f].adj[k], poly.faces[f].edge[k]);
      }
    };
    poly.faces[closest].alive = false;
    removed.push_back(closest);
    for (int m = 0; m < 3; ++m) walk(walk, face.adj[m], face.edge[m]);

    // New faces (horizon edge reversed, q), chained so each one's edge 1 meets the next's edge 2;
    // the horizon must be one closed loop and every new face sound, or nothing changes.
    const int qi = int(poly.vertices.size());
    poly.vertices.push_back(q);
    fresh.clear();
    bool sound = horizon.size() >= 3;
    std::vector<int> order;
    if (sound) {
      order.push_back(0);
      std::vector<bool> used(horizon.size(), false);
      used[0] = true;
      auto endOf = [&](std::size_t h) {  // the new face's second vertex: the kept edge's start
        return poly.faces[horizon[h].first].v[horizon[h].second];
      };
      auto startOf = [&](std::size_t h) {
        return poly.faces[horizon[h].first].v[(horizon[h].second + 1) % 3];
      };
      while (sound && order.size() < horizon.size()) {
        const int want = endOf(std::size_t(order.back()));
        int next = -1;
        for (std::size_t h = 0; h < horizon.size(); ++h)
          if (!used[h] && startOf(h) == want) next = int(h);
        if (next < 0)
          sound = false;
        else
          used[std::size_t(next)] = true, order.push_back(next);
      }
      if (sound && endOf(std::size_t(order.back())) != startOf(0)) sound = false;
      for (std::size_t m = 0; sound && m < order.size(); ++m) {
        const auto [g, k] = horizon[std::size_t(order[m])];
        EpaFace<T> f;
        sound = poly.makeFace(poly.faces[g].v[(k + 1) % 3], poly.faces[g].v[k], qi, tol, f);
        fresh.push_back(f);
      }
    }
    if (!sound) {  // keep the polytope as it was and answer with the best face so far
      for (const int f : removed) poly.faces[std::size_t(f)].alive = true;
      poly.vertices.pop_back();
      result.iterations = iteration + 1;
      break;
    }
    const int first = int(poly.faces.size()), count = int(fresh.size());
    for (int m = 0; m < count; ++m) {
      EpaFace<T>& f = fresh[std::size_t(m)];
      const auto [g, k] = horizon[std::size_t(order[std::size_t(m)])];
      f.adj = {g, first + (m + 1) % count, first + (m + count - 1) % count};
      f.edge = {k, 2, 1};
      poly.faces[g].adj[k] = first + m;
      poly.faces[g].edge[k] = 0;
    }
    poly.faces.insert(poly.faces.end(), fresh.begin(), fresh.end());
  }

  // The origin's projection on the closest face, in barycentric weights, gives the witness
  // points. A face of the difference is often split into coplanar triangles of equal distance
  // and the projection lies in only one of them: among the faces tied with the closest (within
  // the tolerance, same normal), take the one whose weights are the least negative, then clamp
  // what rounding leaves.
  auto weights = [&](const EpaFace<T>& g, const Vec3<T>& q) {
    std::array<T, 3> l{};
    for (int m = 0; m < 3; ++m) {
      const Vec3<T>& b = poly.vertices[g.v[(m + 1) % 3]].w;
      const Vec3<T>& c = poly.vertices[g.v[(m + 2) % 3]].w;
      l[m] = g.normal.dot((b - q).cross(c - q));
    }
    const T sum = l[0] + l[1] + l[2];
    if (sum > 0)
      for (T& x : l) x /= sum;
    else
      l = {T(1) / 3, T(1) / 3, T(1) / 3};
    return l;
  };
  const Vec3<T> q = poly.faces[closest].normal * poly.faces[closest].dist;
  std::array<T, 3> l = weights(poly.faces[closest], q);
  const T tol = tolerance();
  for (int g = 0; g < int(poly.faces.size()) && std::min({l[0], l[1], l[2]}) < 0; ++g) {
    const EpaFace<T>& h = poly.faces[g];
    if (!h.alive || g == closest || h.dist > poly.faces[closest].dist + tol ||
        h.normal.dot(poly.faces[closest].normal) < 1 - kEpaTolerance<T>)
      continue;
    const std::array<T, 3> k = weights(h, q);
    if (std::min({k[0], k[1], k[2]}) > std::min({l[0], l[1], l[2]})) l = k, closest = g;
  }
  const EpaFace<T>& f = poly.faces[closest];
  T sum = 0;
  for (T& x : l) sum += (x = std::max(T(0), x));
  for (T& x : l) x /= sum;  // sum > 0: the weights summed to 1 before clamping
  result.normal = f.normal;
  result.depth = std::max(T(0), f.dist);
  result.pointA = result.pointB = Vec3<T>::Zero();
  for (int m = 0; m < 3; ++m) {
    result.pointA += l[m] * poly.vertices[f.v[m]].a;
    result.pointB += l[m] * poly.vertices[f.v[m]].b;
  }
  return result;
}

template <class T>
std::optional<PenetrationT<T>> epa(const Cores<T>& shapes) {
  const GjkSolution<T> g = solveGjk(shapes);
  if (!g.touching()) return std::nullopt;
  const GjkRun<T>& run = g.run;
  const T ra = g.ra, rb = g.rb, core = g.core;
  const Vec3<T>& origin = g.origin;
  PenetrationT<T> result;
  if (!run.overlap) {
    result.normal = -g.fromBToA();
    result.depth = std::max(T(0), ra + rb - core);
    result.pointA = g.pointA() + ra * result.normal + origin;
    result.pointB = g.pointB() - rb * result.normal + origin;
    return result;
  }
  // EPA runs in GJK's scaled coordinates (GjkRun::unit); its lengths are unscaled here.
  const EpaCoreResult<T> e = epaCore(shapes.pair, origin, run, g.towardB);
  result.normal = e.normal;
  result.depth = e.depth / run.unit + ra + rb;
  result.pointA = e.pointA / run.unit + ra * e.normal + origin;
  result.pointB = e.pointB / run.unit - rb * e.normal + origin;
  result.iterations = e.iterations;
  return result;
}

}  // namespace detail

}  // namespace simdphys

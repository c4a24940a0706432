// The definitions of simdphys/geometry3d/gjk.hpp (GJK's sub-algorithm and its run): included by
// gjk.cpp, which instantiates them for float and double, and by any file of src/ that wants them
// inlined.
#pragma once

#include "simdphys/geometry3d/gjk.hpp"
#include "src/reference/math-inl.hpp"

namespace simdphys {

namespace detail {

// The closest point to the origin of a sub-simplex, as a set of vertex indices and weights.
template <class T>
struct SubSimplex {
  std::array<int, 4> index{};
  std::array<T, 4> lambda{};
  int size = 0;
  Vec3<T> v = Vec3<T>::Zero();
  T vv = std::numeric_limits<T>::infinity();
};

template <class T>
bool sameSign(T a, T b) {
  return (a > 0 && b > 0) || (a < 0 && b < 0);
}

template <class T>
SubSimplex<T> vertexOnly(const std::array<Vec3<T>, 4>& p, int i) {
  SubSimplex<T> r;
  r.size = 1, r.index[0] = i, r.lambda[0] = 1, r.v = p[i], r.vv = p[i].squaredNorm();
  return r;
}

template <class T>
void keepCloser(SubSimplex<T>& best, const SubSimplex<T>& candidate) {
  if (candidate.vv < best.vv) best = candidate;
}

// Segment p[i] p[j]: the origin's projection on the line, kept if it falls strictly inside.
template <class T>
SubSimplex<T> closestOnSegment(const std::array<Vec3<T>, 4>& p, int i, int j) {
  const Vec3<T> t = p[j] - p[i];
  const T tt = t.squaredNorm();
  if (!(tt > 0)) return vertexOnly(p, j);  // a repeated point
  const T u = -p[i].dot(t) / tt;
  if (u <= 0) return vertexOnly(p, i);
  if (u >= 1) return vertexOnly(p, j);
  SubSimplex<T> r;
  r.size = 2, r.index = {i, j, 0, 0}, r.lambda = {1 - u, u, 0, 0};
  r.v = p[i] + u * t;
  r.vv = r.v.squaredNorm();
  return r;
}

// Triangle p[i] p[j] p[k] (Montanari et al., S2D): project the origin on the plane, then compare
// the signed areas of the three sub-triangles it makes with the whole one, in the coordinate
// plane where the triangle's projection is largest. An edge is searched only when the origin is
// beyond it (its sign differs). A flat (collinear or repeated) triangle is its edges.
template <class T>
SubSimplex<T> closestOnTriangle(const std::array<Vec3<T>, 4>& p, int i, int j, int k) {
  const Vec3<T> e1 = p[j] - p[i], e2 = p[k] - p[i];
  const Vec3<T> n = e1.cross(e2);
  const T nn = n.squaredNorm();
  const T flat = kGjkFlatTolerance<T> * kGjkFlatTolerance<T> * e1.squaredNorm() * e2.squaredNorm();
  std::array<T, 3> c{};
  const std::array<int, 3> idx{i, j, k};
  T mu = 0;
  if (nn > flat && nn > 0) {
    const Vec3<T> q = n * (n.dot(p[i]) / nn);  // the origin projected on the plane
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const int x = (axis + 1) % 3, y = (axis + 2) % 3;
    // Twice the signed area of (a, b, c) in the (x, y) plane; for the triangle itself it is
    // n[axis].
    auto area = [x, y](const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& cc) {
      return (b[x] - a[x]) * (cc[y] - a[y]) - (b[y] - a[y]) * (cc[x] - a[x]);
    };
    mu = n[axis];
    c = {area(q, p[j], p[k]), area(p[i], q, p[k]), area(p[i], p[j], q)};
    if (sameSign(mu, c[0]) && sameSign(mu, c[1]) && sameSign(mu, c[2])) {
      const T sum = c[0] + c[1] + c[2];
      SubSimplex<T> r;
      r.size = 3, r.index = {i, j, k, 0};
      r.lambda = {c[0] / sum, c[1] / sum, c[2] / sum, 0};
      // v is the projection itself: along the plane's normal to rounding, however close the
      // plane passes to the origin (a weighted sum of the vertices would carry their rounding,
      // eps |p|, across it and tilt the direction of a short v).
      r.v = q;
      r.vv = r.v.squaredNorm();
      return r;
    }
  }
  SubSimplex<T> best;
  for (int m = 0; m < 3; ++m) {
    if (mu != 0 && sameSign(mu, c[m])) continue;  // the origin is inside this edge's half-plane
    SubSimplex<T> e = closestOnSegment(p, idx[(m + 1) % 3], idx[(m + 2) % 3]);
    keepCloser(best, e);
  }
  return best;
}

// Tetrahedron p[0..3] (S3D): the signed volumes of the four tetrahedra made with the origin
// against the whole; all of the same sign means the origin is inside. A flat tetrahedron is its
// faces.
template <class T>
SubSimplex<T> closestOnTetrahedron(const std::array<Vec3<T>, 4>& p) {
  const Vec3<T> e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  const T mu = e1.dot(e2.cross(e3));
  const T scale = e1.norm() * e2.norm() * e3.norm();
  std::array<T, 4> c{};
  const bool solid = std::abs(mu) > kGjkFlatTolerance<T> * scale && mu != 0;
  if (solid) {
    // Each volume is a dot product with edge vectors of a vertex, not a determinant of the
    // vertices, so it stays accurate when the simplex is far from the origin.
    c[0] = p[1].dot((p[2] - p[1]).cross(p[3] - p[1]));
    c[1] = -p[0].dot(e2.cross(e3));
    c[2] = -p[0].dot(e3.cross(e1));
    c[3] = -p[0].dot(e1.cross(e2));
    if (sameSign(mu, c[0]) && sameSign(mu, c[1]) && sameSign(mu, c[2]) && sameSign(mu, c[3])) {
      const T sum = c[0] + c[1] + c[2] + c[3];
      SubSimplex<T> r;
      r.size = 4, r.index = {0, 1, 2, 3};
      for (int m = 0; m < 4; ++m) r.lambda[m] = c[m] / sum;
      r.v = Vec3<T>::Zero();
      r.vv = 0;
      return r;
    }
  }
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  SubSimplex<T> best;
  for (int m = 0; m < 4; ++m) {
    if (solid && sameSign(mu, c[m])) continue;  // the origin is on the inner side of this face
    keepCloser(best, closestOnTriangle(p, kFace[m][0], kFace[m][1], kFace[m][2]));
  }
  return best;
}

// Replaces the simplex by the smallest sub-simplex holding its point closest to the origin.
template <class T>
SubSimplex<T> reduce(Simplex<T>& s) {
  std::array<Vec3<T>, 4> w;
  for (int m = 0; m < s.size; ++m) w[m] = s.p[m].w;
  SubSimplex<T> r;
  switch (s.size) {
    case 1:
      r = vertexOnly(w, 0);
      break;
    case 2:
      r = closestOnSegment(w, 0, 1);
      break;
    case 3:
      r = closestOnTriangle(w, 0, 1, 2);
      break;
    default:
      r = closestOnTetrahedron(w);
      break;
  }
  Simplex<T> out;
  out.size = r.size;
  for (int m = 0; m < r.size; ++m) out.p[m] = s.p[r.index[m]], out.lambda[m] = r.lambda[m];
  s = out;
  return r;
}

template <class T>
GjkRun<T> runGjk(const CorePair<T>& cores, const Vec3<T>& origin, Vec3<T> towardB) {
  GjkRun<T> run;
  if (!(towardB.squaredNorm() > 0)) towardB = Vec3<T>::UnitX();
  run.simplex.size = 1;
  run.simplex.p[0] = cores(towardB, origin, T(1));
  run.rescale(inversePowerOfTwo(run.simplex.p[0].w.cwiseAbs().maxCoeff()));
  run.simplex.lambda[0] = 1;
  run.v = run.simplex.p[0].w;
  run.vv = run.v.squaredNorm();
  run.scale = run.v.norm();
  run.iterations = 1;
  for (;;) {
    const T touch = kTouchTolerance<T> * run.scale;
    if (run.vv <= touch * touch) {
      run.overlap = true;
      break;
    }
    if (run.iterations >= kGjkMaxIterations) break;
    SupportPoint<T> w = cores(Vec3<T>(-run.v), origin, run.unit);
    ++run.iterations;
    // A support point far larger than the run's size so far, or all of them far below 1 (the
    // first was zero): scale back to near 1.
    const T m = std::max(w.w.cwiseAbs().maxCoeff(), run.scale);
    if (m > T(65536) || (m > 0 && m < T(1) / T(65536))) {
      const T f = inversePowerOfTwo(m);
      run.rescale(f);
      w.w *= f, w.a *= f, w.b *= f;
    }
    run.scale = std::max(run.scale, w.w.norm());
    // |v| is an upper bound of the distance, v.w / |v| a lower one: stop when they agree.
    const T gap = run.vv - run.v.dot(w.w);
    if (gap <= kGjkTolerance<T> * std::sqrt(run.vv) * run.scale) break;
    Simplex<T> grown = run.simplex;
    grown.p[grown.size++] = w;
    const SubSimplex<T> r = reduce(grown);
    if (r.size == 4) {  // the origin is inside the tetrahedron
      run.simplex = grown;
      run.v = Vec3<T>::Zero();
      run.vv = 0;
      run.overlap = true;
      break;
    }
    if (!(r.vv < run.vv)) break;  // no progress: rounding has taken over, keep the old simplex
    run.simplex = grown;
    run.v = r.v;
    run.vv = r.vv;
  }
  return run;
}

// GJK from the shapes' reference points, with what both gjkDistance and epa read of it.
template <class T>
struct GjkSolution {
  Vec3<T> origin, towardB;  // a point of A (the local origin); B's reference point from it
  GjkRun<T> run;
  T ra = 0, rb = 0;  // the radii around the cores
  T core = 0;        // the cores' distance (0 when they overlap), unscaled
  T size = 0;        // run.scale unscaled
  // The shapes are within the touching tolerance of each other, or overlap.
  bool touching() const { return core - ra - rb <= kTouchTolerance<T> * (size + ra + rb); }
  // The cores' closest points in local coordinates (unscaled), and the unit vector from B's to A's.
  Vec3<T> pointA() const { return run.pointA() / run.unit; }
  Vec3<T> pointB() const { return run.pointB() / run.unit; }
  Vec3<T> fromBToA() const { return run.v / std::sqrt(run.vv); }
};
template <class T>
GjkSolution<T> solveGjk(const Cores<T>& shapes) {
  GjkSolution<T> g;
  g.origin = shapes.referenceA;
  g.towardB = shapes.referenceB - g.origin;
  g.run = runGjk(shapes.pair, g.origin, g.towardB);
  g.ra = shapes.ra, g.rb = shapes.rb;
  g.core = g.run.overlap ? T(0) : std::sqrt(g.run.vv) / g.run.unit;
  g.size = g.run.scale / g.run.unit;
  return g;
}

template <class T>
GjkResultT<T> gjkDistance(const Cores<T>& shapes) {
  const GjkSolution<T> g = solveGjk(shapes);
  const GjkRun<T>& run = g.run;
  const T ra = g.ra, rb = g.rb, core = g.core;
  const Vec3<T>& origin = g.origin;
  const Vec3<T> ca = g.pointA(), cb = g.pointB();
  GjkResultT<T> result;
  result.iterations = run.iterations;
  const T distance = core - ra - rb;
  if (g.touching()) {
    result.intersecting = true;
    result.distance = 0;
    // A common point: where the cores meet, or on the segment between the cores' closest
    // points, at a distance t from B's within rb and from A's within ra (the middle of
    // [core - ra, rb] clipped to the segment).
    Vec3<T> p = (ca + cb) / T(2);
    if (!run.overlap) {
      const T lo = std::max(T(0), core - ra), hi = std::min(core, rb);
      p = cb + (ca - cb) * (std::min(std::max((lo + hi) / 2, T(0)), core) / core);
    }
    result.pointA = result.pointB = p + origin;
    return result;
  }
  const Vec3<T> n = g.fromBToA();
  result.distance = distance;
  result.pointA = ca - ra * n + origin;
  result.pointB = cb + rb * n + origin;
  return result;
}

}  // namespace detail

}  // namespace simdphys

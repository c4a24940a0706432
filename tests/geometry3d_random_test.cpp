// Properties of include/simdphys/geometry3d/point_tests.hpp and intersect.hpp on random inputs
// from fixed seeds: closest points against dense sampling, intersections against the
// double-precision oracles written here and against point sampling, both argument orders;
// and the hard cases that need the oracles. Tolerances as in geometry3d_point_test.cpp.
#include "geometry3d_cases.hpp"

namespace simdphys {
namespace {

using namespace test;

// =============================================================================================
// Random inputs and oracles
// =============================================================================================

// Draws from workloads::Random (fixed seeds), in float; the same draws feed both scalar types.
struct Draw {
  workloads::Random r;
  explicit Draw(std::uint64_t seed) : r(seed) {}
  double uniform(double a, double b) { return r.uniform(float(a), float(b)); }
  template <class T>
  Vec3<T> vec(double a, double b) {
    return v3<T>(uniform(a, b), uniform(a, b), uniform(a, b));
  }
  template <class T>
  Mat3<T> rotation() {
    const Vec3f axis = r.unitDirection();
    return axisAngle(axis.template cast<T>(), T(uniform(0, 3.14159)));
  }
  // Log-uniform in [a, b].
  double logUniform(double a, double b) { return a * std::pow(b / a, uniform(0, 1)); }
};

template <class T>
SphereT<T> randomSphere(Draw& d) {
  return {d.vec<T>(-2, 2), T(d.uniform(0.05, 1.5))};
}
template <class T>
AabbT<T> randomAabb(Draw& d) {
  const Vec3<T> c = d.vec<T>(-2, 2), h = d.vec<T>(0.05, 1.5);
  return {c - h, c + h};
}
template <class T>
ObbT<T> randomObb(Draw& d) {
  return {d.vec<T>(-2, 2), d.vec<T>(0.05, 1.5), d.rotation<T>()};
}
template <class T>
TriangleT<T> randomTriangle(Draw& d) {
  const Vec3<T> c = d.vec<T>(-2, 2);
  return {c + d.vec<T>(-1.5, 1.5), c + d.vec<T>(-1.5, 1.5), c + d.vec<T>(-1.5, 1.5)};
}
template <class T>
PlaneT<T> randomPlane(Draw& d) {
  // Normalised in T, so that the double normal is unit to double precision.
  const Vec3<T> n = d.r.unitDirection().template cast<T>().normalized();
  return {n, T(d.uniform(-3, 3))};
}

// ---- double-precision oracles (independent formulations, normalised axes, no tolerances) ----

struct OracleBox {
  Vec3d c, h;
  Mat3d u;
};
template <class T>
OracleBox oracle(const AabbT<T>& b) {
  const Vec3d lo = b.min.template cast<double>(), hi = b.max.template cast<double>();
  return {(lo + hi) / 2, (hi - lo) / 2, Mat3d::Identity()};
}
template <class T>
OracleBox oracle(const ObbT<T>& b) {
  return {b.center.template cast<double>(), b.halfExtents.template cast<double>(),
          b.axes.template cast<double>()};
}
template <class T>
std::array<Vec3d, 3> oracle(const TriangleT<T>& t) {
  return {t.a.template cast<double>(), t.b.template cast<double>(), t.c.template cast<double>()};
}

// The signed gap of two intervals on a unit axis: > 0 apart by that much, <= 0 overlapping.
double gapOf(double minA, double maxA, double minB, double maxB) {
  return std::max(minB - maxA, minA - maxB);
}
std::pair<double, double> projection(const OracleBox& b, const Vec3d& axis) {
  const double c = b.c.dot(axis);
  double r = 0;
  for (int i = 0; i < 3; ++i) r += b.h[i] * std::abs(b.u.col(i).dot(axis));
  return {c - r, c + r};
}
std::pair<double, double> projection(const std::array<Vec3d, 3>& v, const Vec3d& axis) {
  const double p0 = v[0].dot(axis), p1 = v[1].dot(axis), p2 = v[2].dot(axis);
  return {std::min({p0, p1, p2}), std::max({p0, p1, p2})};
}
// The face normals of a box as a parallelepiped: the cross products of pairs of its axes (for
// orthonormal axes, the axes themselves).
std::array<Vec3d, 3> faceNormals(const OracleBox& b) {
  return {b.u.col(1).cross(b.u.col(2)).normalized(), b.u.col(2).cross(b.u.col(0)).normalized(),
          b.u.col(0).cross(b.u.col(1)).normalized()};
}

// The largest gap over a list of candidate directions (normalised here; shorter than 1e-12 of
// their factors' lengths skipped as parallel).
template <class A, class B>
double maxGap(const A& a, const B& b, const std::vector<Vec3d>& axes) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec3d& axis : axes) {
    const auto [minA, maxA] = projection(a, axis);
    const auto [minB, maxB] = projection(b, axis);
    best = std::max(best, gapOf(minA, maxA, minB, maxB));
  }
  return best;
}
void addAxis(std::vector<Vec3d>& axes, const Vec3d& axis, double length) {
  if (axis.norm() > 1e-12 * length) axes.push_back(axis.normalized());
}

// Box-box separating-axis gap: > 0 means separated by at least that distance; <= 0 means they
// intersect (the 15 axes are complete for two boxes).
double boxGap(const OracleBox& a, const OracleBox& b) {
  std::vector<Vec3d> axes;
  for (const auto& n : faceNormals(a)) axes.push_back(n);
  for (const auto& n : faceNormals(b)) axes.push_back(n);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) addAxis(axes, a.u.col(i).cross(b.u.col(j)), 1);
  return maxGap(a, b, axes);
}

// Triangle-box gap: box faces, triangle normal, box axis x edge, and the in-plane normals.
double triangleBoxGap(const std::array<Vec3d, 3>& v, const OracleBox& b) {
  std::vector<Vec3d> axes;
  for (const auto& n : faceNormals(b)) axes.push_back(n);
  const std::array<Vec3d, 3> e{v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  const Vec3d n = e[0].cross(e[1]);
  addAxis(axes, n, e[0].norm() * e[1].norm());
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) addAxis(axes, b.u.col(i).cross(e[j]), e[j].norm());
    addAxis(axes, n.cross(e[j]), n.norm() * e[j].norm());
  }
  return maxGap(v, b, axes);
}

// Distance from a segment to a triangle: the minimum over the segment's endpoints against the
// triangle, the segment against the triangle's edges, and the point where it crosses the plane.
// (The distance is convex along the segment; its minimum is at an endpoint, where the segment
// meets the plane, or where the closest triangle point is on an edge.) Built on closestPoint and
// closestPoints in double, which the properties below check against dense sampling.
// When the segment pierces the triangle (crosses its plane at a point whose barycentric weights
// are all positive) the result is negative instead, minus the smallest weight times the longest
// edge: a certificate of intersection that does not rely on a distance of ~1e-17 being "zero".
double segmentTriangleDistance(const Vec3d& p, const Vec3d& q, const std::array<Vec3d, 3>& v) {
  const TriangleT<double> t{v[0], v[1], v[2]};
  double best = std::min((p - closestPoint(t, p)).norm(), (q - closestPoint(t, q)).norm());
  for (int i = 0; i < 3; ++i)
    best = std::min(best, closestPoints(SegmentT<double>{p, q}, {v[i], v[(i + 1) % 3]}).distance);
  const Vec3d n = (v[1] - v[0]).cross(v[2] - v[0]);
  const double sp = n.dot(p - v[0]), sq = n.dot(q - v[0]);
  if ((sp <= 0 && sq >= 0) || (sp >= 0 && sq <= 0)) {
    if (sp != sq) {
      const Vec3d x = p + (q - p) * (sp / (sp - sq));
      const Vec3d w = barycentric(t, x);
      if (sp != 0 && sq != 0 && w.minCoeff() > 0)
        return -w.minCoeff() * std::max({(v[1] - v[0]).norm(), (v[2] - v[0]).norm()});
      best = std::min(best, (x - closestPoint(t, x)).norm());
    }
  }
  return best;
}
// Two triangles intersect exactly when an edge of one meets the other; negative when an edge
// pierces the other triangle.
double triangleDistance(const std::array<Vec3d, 3>& a, const std::array<Vec3d, 3>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, segmentTriangleDistance(a[i], a[(i + 1) % 3], b));
    best = std::min(best, segmentTriangleDistance(b[i], b[(i + 1) % 3], a));
  }
  return best;
}

// The separation the oracles report for a pair, > 0 apart (a lower bound on the distance for the
// separating-axis oracles, the distance for the others), <= 0 intersecting.
template <class T>
double separation(const SphereT<T>& s, const SphereT<T>& o) {
  return (s.center.template cast<double>() - o.center.template cast<double>()).norm() -
         double(s.radius) - double(o.radius);
}
template <class T, class Shape>
double sphereSeparation(const SphereT<T>& s, const Shape& shape) {
  const Vec3d c = s.center.template cast<double>();
  return (c - closestPoint(cast<double>(shape), c)).norm() - double(s.radius);
}
template <class T>
double separation(const SphereT<T>& s, const AabbT<T>& b) {
  return sphereSeparation(s, b);
}
template <class T>
double separation(const SphereT<T>& s, const ObbT<T>& b) {
  return sphereSeparation(s, b);
}
template <class T>
double separation(const SphereT<T>& s, const TriangleT<T>& t) {
  return sphereSeparation(s, t);
}
template <class T>
double separation(const SphereT<T>& s, const PlaneT<T>& p) {
  return std::abs(cast<double>(p).signedDistance(s.center.template cast<double>())) -
         double(s.radius);
}
// Boxes and triangles against a plane: the signed distances of the corners; apart by the
// smallest |distance| when all have one sign.
template <class T>
double planeSeparation(const std::vector<Vec3d>& points, const PlaneT<T>& p) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3d& x : points) {
    const double s = cast<double>(p).signedDistance(x);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return std::max(lo, -hi);
}
std::vector<Vec3d> corners(const OracleBox& b) {
  std::vector<Vec3d> out;
  for (int k = 0; k < 8; ++k)
    out.push_back(b.c + b.u * Vec3d(k & 1 ? b.h[0] : -b.h[0], k & 2 ? b.h[1] : -b.h[1],
                                    k & 4 ? b.h[2] : -b.h[2]));
  return out;
}
template <class T>
double separation(const AabbT<T>& b, const PlaneT<T>& p) {
  return planeSeparation(corners(oracle(b)), p);
}
template <class T>
double separation(const ObbT<T>& b, const PlaneT<T>& p) {
  return planeSeparation(corners(oracle(b)), p);
}
template <class T>
double separation(const TriangleT<T>& t, const PlaneT<T>& p) {
  const auto v = oracle(t);
  return planeSeparation({v[0], v[1], v[2]}, p);
}
template <class T>
double separation(const AabbT<T>& a, const AabbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const AabbT<T>& a, const ObbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const ObbT<T>& a, const ObbT<T>& b) {
  return boxGap(oracle(a), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& t, const AabbT<T>& b) {
  return triangleBoxGap(oracle(t), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& t, const ObbT<T>& b) {
  return triangleBoxGap(oracle(t), oracle(b));
}
template <class T>
double separation(const TriangleT<T>& a, const TriangleT<T>& b) {
  return triangleDistance(oracle(a), oracle(b));
}

// Moving a shape: translate by an offset.
template <class T>
SphereT<T> moved(SphereT<T> s, const Vec3<T>& o) {
  s.center += o;
  return s;
}
template <class T>
AabbT<T> moved(AabbT<T> b, const Vec3<T>& o) {
  return {b.min + o, b.max + o};
}
template <class T>
ObbT<T> moved(ObbT<T> b, const Vec3<T>& o) {
  b.center += o;
  return b;
}
template <class T>
TriangleT<T> moved(TriangleT<T> t, const Vec3<T>& o) {
  return {t.a + o, t.b + o, t.c + o};
}
template <class T>
PlaneT<T> moved(PlaneT<T> p, const Vec3<T>& o) {
  p.d -= p.normal.dot(o);
  return p;
}

// A point of each shape, used to aim the near-touching search.
template <class T>
Vec3d anchor(const SphereT<T>& s) {
  return s.center.template cast<double>();
}
template <class T>
Vec3d anchor(const AabbT<T>& b) {
  return oracle(b).c;
}
template <class T>
Vec3d anchor(const ObbT<T>& b) {
  return b.center.template cast<double>();
}
template <class T>
Vec3d anchor(const TriangleT<T>& t) {
  return (t.a + t.b + t.c).template cast<double>() / 3;
}
template <class T>
Vec3d anchor(const PlaneT<T>& p) {
  return -double(p.d) * p.normal.template cast<double>();
}

// The size that scales the tolerances of a pair: the largest distance of the pair's defining
// points from the origin, 1 or more for the random scenes here.
double sizeOf(double x) { return std::max(1.0, x); }

// The band around touching where either answer is accepted, relative to the scene's size. The
// separating-axis tests can miss separations of up to about sqrt(eps) times the size where edges
// are nearly parallel (intersect.hpp); 1e-3 in float and 1e-7 in double are three and seven
// times that. The other tests are within their tolerance, 16 eps, well inside these bands.
template <class T>
constexpr double kBand = std::is_same_v<T, float> ? 1e-3 : 1e-7;

struct Tally {
  int mustIntersect = 0, mustNotIntersect = 0, inBand = 0;
};

// The scene size of a pair.
template <class A, class B>
double pairSize(const A& a, const B& b) {
  return sizeOf(anchor(a).norm() + anchor(b).norm());
}

// Checks one pair against the oracle: an intersecting or touching pair must be reported (the
// tolerance only ever adds touching pairs, never drops one), a pair separated by more than the
// band must not, and both argument orders must agree. "Touching" is a separation up to a quarter
// of the smallest tolerance any of the tests can use here, tol * 0.05 / 4: each test's scale is
// at least the size of one of its shapes, and 0.05 is the smallest size drawn. (The distance
// oracles never go below 0 and return ~1e-17 for intersecting pairs; a separating-axis
// implementation testing the oracle's axes finds no gap larger than the oracle's plus its
// rounding, below another quarter of its tolerance.)
// AABB-AABB has no tolerance (it is exact), so only separation <= 0 counts as touching there.
template <class T, class A, class B>
double contact() {
  return std::is_same_v<A, AabbT<T>> && std::is_same_v<B, AabbT<T>> ? 0 : kTol<T> * 0.05 / 4;
}

template <class T, class A, class B>
void checkPair(const A& a, const B& b, Tally& tally) {
  const double sep = separation(a, b);
  const bool ab = intersects(a, b), ba = intersects(b, a);
  ASSERT_EQ(ab, ba) << "not symmetric, separation " << sep;
  const double size = pairSize(a, b);
  if (sep <= contact<T, A, B>()) {
    ++tally.mustIntersect;
    EXPECT_TRUE(ab) << "separation " << sep;
  } else if (sep > kBand<T> * size) {
    ++tally.mustNotIntersect;
    EXPECT_FALSE(ab) << "separation " << sep;
  } else {
    ++tally.inBand;
  }
}

// Random pairs, and the same pairs slid along the line through their anchors (along the plane's
// normal for planes) to the touching position found by bisection on the oracle, then moved by
// +-delta with delta log-uniform in [1e-9, 1e-1]: many pairs on both sides of touching, a few
// inside the band.
template <class T, class A, class B, class MakeA, class MakeB>
Tally checkRandomPairs(std::uint64_t seed, int count, MakeA makeA, MakeB makeB) {
  Draw d(seed);
  Tally tally;
  for (int n = 0; n < count; ++n) {
    const A a = makeA(d);
    const B b = makeB(d);
    checkPair<T>(a, b, tally);
    Vec3d dir = anchor(b) - anchor(a);
    if constexpr (std::is_same_v<A, PlaneT<T>>) dir = a.normal.template cast<double>();
    if constexpr (std::is_same_v<B, PlaneT<T>>) dir = b.normal.template cast<double>();
    if (!(dir.norm() > 1e-6)) dir = Vec3d(1, 0, 0);
    dir.normalize();
    // b with its anchor at anchor(a) + t dir.
    const Vec3d from = anchor(b);
    const auto place = [&](double t) {
      return moved(b, Vec3<T>((anchor(a) + t * dir - from).template cast<T>()));
    };
    // Intersecting at 0 (a shared anchor point), apart at 20 (sizes <= ~5); "apart" is a
    // separation above the oracles' own rounding, 1e-13 of the size.
    const auto apart = [&](double t) { return separation(a, place(t)) > 1e-13 * pairSize(a, b); };
    double lo = 0, hi = 20;
    if (apart(lo) || !apart(hi)) continue;
    for (int i = 0; i < 60; ++i) {
      const double mid = (lo + hi) / 2;
      (apart(mid) ? hi : lo) = mid;
    }
    const double delta = (n % 8 == 0) ? 0 : d.logUniform(1e-9, 1e-1) * (n % 2 ? 1 : -1);
    checkPair<T>(a, place(hi + delta), tally);
  }
  // Not vacuous: both sides are well represented.
  EXPECT_GT(tally.mustIntersect, count / 4);
  EXPECT_GT(tally.mustNotIntersect, count / 4);
  return tally;
}

#define PAIR_PROPERTY(Name, A, B, makeA, makeB, seed)                                          \
  TYPED_TEST(Properties, Name) {                                                               \
    using T = TypeParam;                                                                       \
    const Tally t = checkRandomPairs<T, A<T>, B<T>>(                                           \
        seed, 1500, [](Draw& d) { return makeA<T>(d); }, [](Draw& d) { return makeB<T>(d); }); \
    this->RecordProperty("in_band", t.inBand);                                                 \
  }

PAIR_PROPERTY(SphereSphereAgreesWithTheOracle, SphereT, SphereT, randomSphere, randomSphere, 101)
PAIR_PROPERTY(SphereAabbAgreesWithTheOracle, SphereT, AabbT, randomSphere, randomAabb, 102)
PAIR_PROPERTY(SphereObbAgreesWithTheOracle, SphereT, ObbT, randomSphere, randomObb, 103)
PAIR_PROPERTY(SpherePlaneAgreesWithTheOracle, SphereT, PlaneT, randomSphere, randomPlane, 104)
PAIR_PROPERTY(AabbAabbAgreesWithTheOracle, AabbT, AabbT, randomAabb, randomAabb, 105)
PAIR_PROPERTY(AabbObbAgreesWithTheOracle, AabbT, ObbT, randomAabb, randomObb, 106)
PAIR_PROPERTY(AabbPlaneAgreesWithTheOracle, AabbT, PlaneT, randomAabb, randomPlane, 107)
PAIR_PROPERTY(ObbObbAgreesWithTheOracle, ObbT, ObbT, randomObb, randomObb, 108)
PAIR_PROPERTY(ObbPlaneAgreesWithTheOracle, ObbT, PlaneT, randomObb, randomPlane, 109)
PAIR_PROPERTY(SphereTriangleAgreesWithTheOracle, SphereT, TriangleT, randomSphere, randomTriangle,
              110)
PAIR_PROPERTY(TriangleAabbAgreesWithTheOracle, TriangleT, AabbT, randomTriangle, randomAabb, 111)
PAIR_PROPERTY(TriangleObbAgreesWithTheOracle, TriangleT, ObbT, randomTriangle, randomObb, 112)
PAIR_PROPERTY(TrianglePlaneAgreesWithTheOracle, TriangleT, PlaneT, randomTriangle, randomPlane, 113)
PAIR_PROPERTY(TriangleTriangleAgreesWithTheOracle, TriangleT, TriangleT, randomTriangle,
              randomTriangle, 114)

// Planes: random pairs are almost never parallel, so parallel ones are made on purpose (the same
// normal or its opposite, offsets from a small set so that some coincide). Symmetric always.
TYPED_TEST(Properties, PlanePlaneAgreesWithParallelism) {
  using T = TypeParam;
  Draw d(115);
  int parallel = 0, coincident = 0;
  for (int n = 0; n < 1000; ++n) {
    const PlaneT<T> a = randomPlane<T>(d);
    PlaneT<T> b = randomPlane<T>(d);
    if (n % 2) {
      const double sign = n % 4 == 1 ? 1 : -1;
      b = {a.normal * T(sign), T(sign * double(a.d) + (n % 3 == 0 ? 0 : d.uniform(-1, 1)))};
      ++parallel;
      // A distinct parallel plane (|offset| >= ~1e-7 here, above tol * (|d1| + |d2|) in double;
      // in float, offsets below 16 eps * 6 = 1.1e-5 count as coincident).
      const double offset = std::abs(double(a.d) - sign * double(b.d));
      const bool same = offset <= kTol<T> * (std::abs(double(a.d)) + std::abs(double(b.d)));
      coincident += same;
      EXPECT_EQ(intersects(a, b), same) << "offset " << offset;
    } else {
      EXPECT_TRUE(intersects(a, b));  // not parallel (random unit normals)
    }
    EXPECT_EQ(intersects(a, b), intersects(b, a));
  }
  EXPECT_GT(parallel, 400);
  EXPECT_GT(coincident, 100);
}

// Every closest point is contained by its shape (within the stated tolerances), and no point
// of a dense sample of the shape is closer to the query point, up to the rounding of the
// computed point: slack tol * (|p| + the shape's size), computed in double.
template <class T, class Shape, class Make, class Sample>
void checkClosestPoints(std::uint64_t seed, Make make, Sample sample) {
  Draw d(seed);
  for (int n = 0; n < 150; ++n) {
    const Shape shape = make(d);
    const Vec3<T> p = d.vec<T>(-5, 5);
    const Vec3<T> q = closestPoint(shape, p);
    ASSERT_TRUE(q.allFinite());
    EXPECT_TRUE(contains(shape, q)) << "closest point " << q.transpose() << " of " << p.transpose();
    const Vec3d pd = p.template cast<double>(), qd = q.template cast<double>();
    const std::vector<Vec3d> samples = sample(cast<double>(shape), d);
    double nearest = std::numeric_limits<double>::infinity(), size = 0;
    for (const Vec3d& s : samples) {
      nearest = std::min(nearest, (pd - s).norm());
      size = std::max(size, s.norm());
    }
    EXPECT_LE((pd - qd).norm(), nearest + kTol<T> * (pd.norm() + size))
        << "a sampled point is closer than " << q.transpose();
    // Idempotent: the closest point of a closest point is itself (to rounding).
    EXPECT_TRUE(closeTo(closestPoint(shape, q), q, kTol<T> * (pd.norm() + size)));
  }
}

std::vector<Vec3d> sampleBox(const OracleBox& b, Draw& d) {
  std::vector<Vec3d> out;
  for (int i = 0; i < 3000; ++i) {
    Vec3d local(d.uniform(-1, 1), d.uniform(-1, 1), d.uniform(-1, 1));
    if (i % 2) local[i % 3] = (i % 4 == 1) ? 1 : -1;  // half on the faces
    out.push_back(b.c + b.u * local.cwiseProduct(b.h));
  }
  return out;
}

TYPED_TEST(Properties, ClosestPointOfSphere) {
  using T = TypeParam;
  checkClosestPoints<T, SphereT<T>>(201, randomSphere<T>, [](const SphereT<double>& s, Draw& d) {
    std::vector<Vec3d> out;
    for (int i = 0; i < 3000; ++i) {
      const Vec3d dir = d.r.unitDirection().cast<double>();
      out.push_back(s.center + dir * s.radius * (i % 2 ? 1.0 : std::cbrt(d.uniform(0, 1))));
    }
    return out;
  });
}
TYPED_TEST(Properties, ClosestPointOfAabb) {
  using T = TypeParam;
  checkClosestPoints<T, AabbT<T>>(
      202, randomAabb<T>, [](const AabbT<double>& b, Draw& d) { return sampleBox(oracle(b), d); });
}
TYPED_TEST(Properties, ClosestPointOfObb) {
  using T = TypeParam;
  checkClosestPoints<T, ObbT<T>>(
      203, randomObb<T>, [](const ObbT<double>& b, Draw& d) { return sampleBox(oracle(b), d); });
}
TYPED_TEST(Properties, ClosestPointOfPlane) {
  using T = TypeParam;
  checkClosestPoints<T, PlaneT<T>>(204, randomPlane<T>, [](const PlaneT<double>& p, Draw& d) {
    // Points of the plane within 8 of its foot point from the origin, in a random in-plane frame.
    const Vec3d t1 = p.normal.unitOrthogonal(), t2 = p.normal.cross(t1);
    const Vec3d foot = -p.d * p.normal;
    std::vector<Vec3d> out;
    for (int i = 0; i < 3000; ++i)
      out.push_back(foot + d.uniform(-8, 8) * t1 + d.uniform(-8, 8) * t2);
    return out;
  });
}
TYPED_TEST(Properties, ClosestPointOfSegment) {
  using T = TypeParam;
  checkClosestPoints<T, SegmentT<T>>(
      205,
      [](Draw& d) {
        const Vec3<T> a = d.vec<T>(-3, 3);
        // Every fourth one degenerate (a point).
        return SegmentT<T>{a, d.r.uniform(0, 1) < 0.25f ? a : Vec3<T>(d.vec<T>(-3, 3))};
      },
      [](const SegmentT<double>& s, Draw&) {
        std::vector<Vec3d> out;
        for (int i = 0; i <= 2000; ++i) out.push_back(s.start + (i / 2000.0) * (s.end - s.start));
        return out;
      });
}
TYPED_TEST(Properties, ClosestPointOfRay) {
  using T = TypeParam;
  checkClosestPoints<T, RayT<T>>(
      206,
      [](Draw& d) {
        return RayT<T>{d.vec<T>(-3, 3), d.r.unitDirection().template cast<T>().normalized()};
      },
      [](const RayT<double>& r, Draw&) {
        std::vector<Vec3d> out;
        for (int i = 0; i <= 4000; ++i) out.push_back(r.origin + (i / 200.0) * r.direction);
        return out;
      });
}
TYPED_TEST(Properties, ClosestPointOfTriangle) {
  using T = TypeParam;
  checkClosestPoints<T, TriangleT<T>>(
      207,
      [](Draw& d) {
        TriangleT<T> t = randomTriangle<T>(d);
        // Every fifth one degenerate: c on the line through a and b.
        if (d.r.uniform(0, 1) < 0.2f) t.c = t.a + T(d.uniform(-1, 2)) * (t.b - t.a);
        return t;
      },
      [](const TriangleT<double>& t, Draw& d) {
        std::vector<Vec3d> out;
        const int k = 60;  // a barycentric grid with edges and vertices, plus random points
        for (int i = 0; i <= k; ++i)
          for (int j = 0; i + j <= k; ++j)
            out.push_back(t.a + (double(i) / k) * (t.b - t.a) + (double(j) / k) * (t.c - t.a));
        for (int i = 0; i < 1000; ++i) {
          double u = d.uniform(0, 1), v = d.uniform(0, 1);
          if (u + v > 1) u = 1 - u, v = 1 - v;
          out.push_back(t.a + u * (t.b - t.a) + v * (t.c - t.a));
        }
        return out;
      });
}

// Barycentric coordinates rebuild the projection of p onto the plane, and sum to 1. Their error
// grows as the triangle thins: tolerance 16 eps * scale * L^2 / |n| (L the longest edge, |n| twice
// the area), the condition of the 2x2 system they solve.
TYPED_TEST(Properties, BarycentricRebuildsTheProjection) {
  using T = TypeParam;
  Draw d(208);
  for (int n = 0; n < 2000; ++n) {
    const TriangleT<T> t = randomTriangle<T>(d);
    const Vec3<T> p = d.vec<T>(-5, 5);
    const Vec3d w = barycentric(t, p).template cast<double>();
    const auto v = oracle(t);
    const Vec3d normal = (v[1] - v[0]).cross(v[2] - v[0]);
    const double longest =
        std::max({(v[1] - v[0]).norm(), (v[2] - v[0]).norm(), (v[2] - v[1]).norm()});
    const Vec3d pd = p.template cast<double>();
    const Vec3d projection = pd - normal * (normal.dot(pd - v[0]) / normal.squaredNorm());
    const double scale = pd.norm() + longest;
    const double condition = longest * longest / normal.norm();
    EXPECT_TRUE(closeTo(w[0] * v[0] + w[1] * v[1] + w[2] * v[2], projection,
                        16 * kEps<T> * scale * condition));
    EXPECT_TRUE(closeTo(w.sum(), 1.0, 16 * kEps<T> * condition * scale / longest));
  }
}

// closestPoints of two segments: on the segments, at the reported distance, and no pair of a
// 101 x 101 parameter grid is closer. A third of the pairs are parallel (the second a translate
// of the first), a tenth nearly parallel (1e-4 rad), some degenerate.
TYPED_TEST(SegmentPairs, ClosestPointsAgreeWithAGrid) {
  using T = TypeParam;
  Draw d(209);
  for (int n = 0; n < 400; ++n) {
    SegmentT<T> a{d.vec<T>(-2, 2), d.vec<T>(-2, 2)};
    SegmentT<T> b{d.vec<T>(-2, 2), d.vec<T>(-2, 2)};
    if (n % 3 == 0) {
      const Vec3<T> o = d.vec<T>(-1, 1);
      b = {a.start + o, a.end + o};
      if (n % 2) std::swap(b.start, b.end);
    } else if (n % 10 == 1) {
      const Vec3<T> o = d.vec<T>(-1, 1);
      const Mat3<T> tilt = axisAngle(d.r.unitDirection().template cast<T>(), T(1e-4));
      b = {a.start + o, a.start + o + tilt * (a.end - a.start) * T(d.uniform(0.2, 2))};
    } else if (n % 10 == 2) {
      b.end = b.start;  // a point
    } else if (n % 10 == 5) {
      a.end = a.start;  // both points
      b.end = b.start;
    }
    const auto c = closestPoints(a, b);
    ASSERT_TRUE(c.first.allFinite() && c.second.allFinite());
    ASSERT_GE(c.s, T(0));
    ASSERT_LE(c.s, T(1));
    ASSERT_GE(c.t, T(0));
    ASSERT_LE(c.t, T(1));
    const SegmentT<double> ad = cast<double>(a), bd = cast<double>(b);
    const double scale = 8;  // the coordinates are within [-3, 3]
    // The reported points are the reported parameters' points, and distance their distance (to
    // a few roundings of the scale).
    EXPECT_TRUE(
        closeTo(c.first, ad.start + double(c.s) * (ad.end - ad.start), 4 * kEps<T> * scale));
    EXPECT_TRUE(
        closeTo(c.second, bd.start + double(c.t) * (bd.end - bd.start), 4 * kEps<T> * scale));
    const double distance =
        (c.first.template cast<double>() - c.second.template cast<double>()).norm();
    EXPECT_TRUE(closeTo(double(c.distance), distance, 16 * kEps<T> * scale));
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; j <= 100; ++j) {
        const Vec3d p = ad.start + (i / 100.0) * (ad.end - ad.start);
        const Vec3d q = bd.start + (j / 100.0) * (bd.end - bd.start);
        nearest = std::min(nearest, (p - q).norm());
      }
    EXPECT_LE(double(c.distance), nearest + kTol<T> * scale) << "pair " << n;
  }
}

// Scaling every input by 2^-20 (about 1e-6) scales every product and sum exactly (no underflow in
// either type at these sizes), and every tolerance is relative: each answer is unchanged and each
// closest point is the scaled one, bit for bit.
TYPED_TEST(HardCases, TinyShapesAnswerAsTheirScaledUpCopies) {
  using T = TypeParam;
  const T k = std::ldexp(T(1), -20);
  Draw d(210);
  const auto sc = [&](auto shape) {
    using S = decltype(shape);
    if constexpr (std::is_same_v<S, SphereT<T>>) return S{shape.center * k, shape.radius * k};
    if constexpr (std::is_same_v<S, AabbT<T>>) return S{shape.min * k, shape.max * k};
    if constexpr (std::is_same_v<S, ObbT<T>>)
      return S{shape.center * k, shape.halfExtents * k, shape.axes};
    if constexpr (std::is_same_v<S, PlaneT<T>>) return S{shape.normal, shape.d * k};
    if constexpr (std::is_same_v<S, TriangleT<T>>) return S{shape.a * k, shape.b * k, shape.c * k};
  };
  for (int n = 0; n < 500; ++n) {
    const SphereT<T> s = randomSphere<T>(d);
    const AabbT<T> a = randomAabb<T>(d);
    const ObbT<T> o = randomObb<T>(d), o2 = randomObb<T>(d);
    const PlaneT<T> p = randomPlane<T>(d);
    const TriangleT<T> t = randomTriangle<T>(d), t2 = randomTriangle<T>(d);
    EXPECT_EQ(intersects(s, a), intersects(sc(s), sc(a)));
    EXPECT_EQ(intersects(s, o), intersects(sc(s), sc(o)));
    EXPECT_EQ(intersects(a, o), intersects(sc(a), sc(o)));
    EXPECT_EQ(intersects(o, o2), intersects(sc(o), sc(o2)));
    EXPECT_EQ(intersects(o, p), intersects(sc(o), sc(p)));
    EXPECT_EQ(intersects(t, s), intersects(sc(t), sc(s)));
    EXPECT_EQ(intersects(t, a), intersects(sc(t), sc(a)));
    EXPECT_EQ(intersects(t, o), intersects(sc(t), sc(o)));
    EXPECT_EQ(intersects(t, t2), intersects(sc(t), sc(t2)));
    const Vec3<T> q = d.vec<T>(-3, 3);
    EXPECT_EQ(closestPoint(t, q) * k, closestPoint(sc(t), Vec3<T>(q * k)));
    EXPECT_EQ(closestPoint(o, q) * k, closestPoint(sc(o), Vec3<T>(q * k)));
    EXPECT_EQ(closestPoint(s, q) * k, closestPoint(sc(s), Vec3<T>(q * k)));
    EXPECT_EQ(contains(t, closestPoint(t, q)), contains(sc(t), Vec3<T>(closestPoint(t, q) * k)));
  }
}

// Symmetry where it is not automatic: computed relative to A's center and relative to B's, the
// box-box test rounds differently, so right at the touching tolerance the two orders of the raw
// computation can disagree. Such pairs are found by bisecting the offset of B along a random
// direction down to adjacent floating-point positions and comparing the two raw orders there;
// intersects() works from the two centres' midpoint (boxes) or orders the pair canonically first
// (triangles), so both its orders must still agree. The same for triangles (relative to either
// triangle's first vertex). Needs at least 3 such pairs of each
// kind, so that the test can fail.
TYPED_TEST(HardCases, SymmetricWhereTheTwoOrdersRoundDifferently) {
  using T = TypeParam;
  Draw d(212);
  const auto boxes = [](const ObbT<T>& a, const ObbT<T>& b) {
    return detail::boxesIntersect(detail::SatBox<T>{Vec3<T>::Zero(), a.halfExtents, a.axes},
                                  detail::SatBox<T>{b.center - a.center, b.halfExtents, b.axes});
  };
  const auto triangles = [](const TriangleT<T>& a, const TriangleT<T>& b) {
    return detail::trianglesIntersect(detail::relative(a, a.a), detail::relative(b, a.a));
  };
  int boxPairs = 0, trianglePairs = 0;
  for (int n = 0; n < 400 && (boxPairs < 3 || trianglePairs < 3); ++n) {
    const Vec3<T> dir = d.r.unitDirection().template cast<T>().normalized();
    const auto search = [&](const auto& a, auto b, const auto& raw, int& found) {
      const auto place = [&](T t) {
        return moved(b, Vec3<T>(t * dir - Vec3<T>(anchor(b).template cast<T>()) +
                                Vec3<T>(anchor(a).template cast<T>())));
      };
      T lo = 0, hi = 20;
      if (!raw(a, place(lo)) || raw(a, place(hi))) return;
      for (;;) {
        const T mid = (lo + hi) / 2;
        if (mid == lo || mid == hi) break;
        (raw(a, place(mid)) ? lo : hi) = mid;
      }
      for (const T t : {lo, hi}) {
        const auto c = place(t);
        if (raw(a, c) == raw(c, a)) continue;
        ++found;
        EXPECT_EQ(intersects(a, c), intersects(c, a)) << "offset " << t;
      }
    };
    search(randomObb<T>(d), randomObb<T>(d), boxes, boxPairs);
    search(randomTriangle<T>(d), randomTriangle<T>(d), triangles, trianglePairs);
  }
  EXPECT_GE(boxPairs, 3);
  EXPECT_GE(trianglePairs, 3);
}

// Float against double near 1e5 with sizes of about 1e-2: random pairs within 0.05 of
// (1e5, 1e5, 1e5), drawn in float; the double oracle runs on the same (cast) shapes. Because the
// tests work on offsets from one shape, the float answers agree with the double oracle except
// within a band of 1e-3 of the local scale 0.05 (the separating-axis bound above): 5e-5, while an
// ulp of 1e5 is 7.8e-3. Planes are the exception: n.p + d at 1e5 is only accurate to about
// 2 eps (|p| + |d|) = 0.08 in float, and the plane tests' tolerance is 16 eps (|p| + |d| + size)
// = 0.66: their band is the sum of the two.
TEST(LargeCoordinates, FloatAgreesWithDoubleAwayFromTouching) {
  using T = float;
  Draw d(211);
  const double base = 1e5;
  const auto near = [&](double spread) {
    return v3<T>(base + d.uniform(-spread, spread), base + d.uniform(-spread, spread),
                 base + d.uniform(-spread, spread));
  };
  const auto size = [&] { return T(d.uniform(0.002, 0.02)); };
  const auto axes = [&] { return d.rotation<T>(); };
  int decided[2] = {}, undecided[2] = {};  // [0] solids and triangles, [1] planes
  const auto check = [&](bool got, double sep, double band, int kind = 0) {
    if (sep <= 0) {
      EXPECT_TRUE(got) << "separation " << sep;
      ++decided[kind];
    } else if (sep > band) {
      EXPECT_FALSE(got) << "separation " << sep;
      ++decided[kind];
    } else {
      ++undecided[kind];
    }
  };
  const double band = 1e-3 * 0.05;
  for (int n = 0; n < 3000; ++n) {
    const SphereT<T> s{near(0.03), size()};
    const Vec3<T> c = near(0.03), h = Vec3<T>(size(), size(), size());
    const AabbT<T> a{c - h, c + h};
    const ObbT<T> o{near(0.03), Vec3<T>(size(), size(), size()), axes()};
    const ObbT<T> o2{near(0.03), Vec3<T>(size(), size(), size()), axes()};
    const Vec3<T> tc = near(0.03);
    const TriangleT<T> t{tc + d.vec<T>(-0.02, 0.02), tc + d.vec<T>(-0.02, 0.02),
                         tc + d.vec<T>(-0.02, 0.02)};
    const Vec3<T> uc = near(0.03);
    const TriangleT<T> t2{uc + d.vec<T>(-0.02, 0.02), uc + d.vec<T>(-0.02, 0.02),
                          uc + d.vec<T>(-0.02, 0.02)};
    check(intersects(s, a), separation(s, a), band);
    check(intersects(s, o), separation(s, o), band);
    check(intersects(a, o), separation(a, o), band);
    check(intersects(o, o2), separation(o, o2), band);
    check(intersects(t, s), separation(s, t), band);
    check(intersects(t, a), separation(t, a), band);
    check(intersects(t, o), separation(t, o), band);
    check(intersects(t, t2), separation(t, t2), band);
    // A plane through a point within 10 of the shapes. Its band is the plane tests' own
    // tolerance, 16 eps (|c| + |d| + size), plus the rounding error of n.c + d in float, up to
    // 2 eps (|c| + |d|) (n.c + d is absolute): up to 18 eps * 3.5e5 = 0.75 here.
    const Vec3<T> normal = d.r.unitDirection().normalized();
    const PlaneT<T> p{normal, -normal.dot(near(10))};
    const double planeBand =
        (kTol<T> + 2 * kEps<T>)*(std::sqrt(3.0) * base + std::abs(double(p.d)) + 0.1);
    check(intersects(s, p), separation(s, p), planeBand, 1);
    check(intersects(o, p), separation(o, p), planeBand, 1);
    // Closest points: the float point is the double one rounded to the float grid near 1e5
    // (half an ulp, 2^-8, per component) plus the computation's error (tol * 0.1).
    const Vec3<T> q = near(0.05);
    const Vec3d qd = q.cast<double>();
    const double bound = std::ldexp(1.0, -8) + kTol<T> * 0.1;
    EXPECT_TRUE(closeTo(closestPoint(o, q), closestPoint(cast<double>(o), qd), bound));
    EXPECT_TRUE(closeTo(closestPoint(t, q), closestPoint(cast<double>(t), qd), bound));
    EXPECT_TRUE(closeTo(closestPoint(s, q), closestPoint(cast<double>(s), qd), bound));
  }
  EXPECT_GT(decided[0], 20000);
  EXPECT_LT(undecided[0], decided[0] / 20);
  EXPECT_GT(decided[1], 4000);
  EXPECT_LT(undecided[1], decided[1] / 4);
}

}  // namespace
}  // namespace simdphys

// The particle step (particles.hpp) over the particle streams, a particle per lane: the push out
// of obstacles a particle starts in (a pass of its own, when one may be), forces, damping, the
// integrator, and the collision of
// the path travelled with every obstacle row, bounce after bounce (or resting contact) while any
// lane still meets one. A row whose box no live lane's path comes near is skipped for the vector:
// a cull with a margin far above rounding, so it changes no result.
// The arithmetic is the scalar reference's (src/reference/particles/step-inl.hpp and the ray hits
// of src/reference/geometry3d/raycast-inl.hpp) operation for operation: Eigen's x + (y + z) sums,
// the same products and quotients in the same order, IEEE square roots and divisions, no
// contraction, std::max's and std::signbit's rules as selects. So every lane ends bit for bit where
// the float reference leaves its particle, and the counters agree exactly. Branches of the
// reference become selects; a lane that has left the bounce loop is masked, not moved.
//
// The step is written once for a lane type: a Highway vector (the kernel) or one float (the
// plain-loop baseline, a particle at a time, left to the compiler).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/particles.cpp"
#include <hwy/aligned_allocator.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <span>
#include <vector>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

// The step calls Highway's operations unqualified: for vectors argument-dependent lookup finds
// Highway's, for one float core/scalar_lanes-inl.hpp's (the baseline's lane, ScalarLane).
#include "core/scalar_lanes-inl.hpp"

// std::signbit lane-wide: the sign of the bits as an integer, so -0 counts as negative.
inline bool SignBit(ScalarLane, float x) { return std::signbit(x); }
template <class D, class V>
HWY_INLINE auto SignBit(D d, V x) {
  const hn::RebindToSigned<D> di;
  return hn::RebindMask(d, hn::Lt(hn::BitCast(di, x), hn::Zero(di)));
}

// ---- 3-vectors of lanes ------------------------------------------------------------------------
template <class V>
struct Vec3L {
  V c[3];
  const V& operator[](int k) const { return c[k]; }
  V& operator[](int k) { return c[k]; }
};

template <class V>
HWY_INLINE Vec3L<V> operator+(const Vec3L<V>& a, const Vec3L<V>& b) {
  return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
}
template <class V>
HWY_INLINE Vec3L<V> operator-(const Vec3L<V>& a, const Vec3L<V>& b) {
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
template <class V>
HWY_INLINE Vec3L<V> operator*(const Vec3L<V>& a, V s) {
  return {{a[0] * s, a[1] * s, a[2] * s}};
}
template <class V>
HWY_INLINE Vec3L<V> operator/(const Vec3L<V>& a, V s) {
  return {{a[0] / s, a[1] / s, a[2] / s}};
}
template <class V>
HWY_INLINE Vec3L<V> Neg(const Vec3L<V>& a) {
  return {{Neg(a[0]), Neg(a[1]), Neg(a[2])}};
}
// Eigen's 3-vector dot product (and squared norm): x + (y + z), its unrolled reduction's order.
template <class V>
HWY_INLINE V dot(const Vec3L<V>& a, const Vec3L<V>& b) {
  return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]);
}
template <class M, class V>
HWY_INLINE Vec3L<V> IfThenElse(M m, const Vec3L<V>& a, const Vec3L<V>& b) {
  return {{IfThenElse(m, a[0], b[0]), IfThenElse(m, a[1], b[1]), IfThenElse(m, a[2], b[2])}};
}
template <class D>
HWY_INLINE auto splat3(D d, const float* v) {
  using V = decltype(Set(d, 0.0f));
  return Vec3L<V>{{Set(d, v[0]), Set(d, v[1]), Set(d, v[2])}};
}
// An OBB row's local frame: axes.transpose() * p, each coordinate a column's dot with p.
template <class V>
HWY_INLINE Vec3L<V> toLocal(const Vec3L<V> (&axes)[3], const Vec3L<V>& p) {
  return {{dot(axes[0], p), dot(axes[1], p), dot(axes[2], p)}};
}

template <class D>
using LaneOf = decltype(Set(D(), 0.0f));
template <class D>
using MaskOf = decltype(Lt(LaneOf<D>(), LaneOf<D>()));

// ---- the reference's pieces, lane-wide ---------------------------------------------------------
// The step's constants, broadcast once.
template <class D>
struct Params {
  using V = LaneOf<D>;
  std::uint32_t integrator;
  Vec3L<V> gravity;
  V dt, damping, drag, restitution, friction, threshold, skin, twoSkins, limit;
  V zero, one, half, inf, slackScale;
  int maxBounces;
  bool forces, pushOutFirst;

  Params(D d, const core::ParticleStepParams& p)
      : integrator(p.integrator),
        gravity(splat3(d, p.gravity)),
        dt(Set(d, p.dt)),
        damping(Set(d, p.damping)),
        drag(Set(d, p.drag)),
        restitution(Set(d, p.restitution)),
        friction(Set(d, p.friction)),
        threshold(Set(d, p.threshold)),
        skin(Set(d, p.skin)),
        twoSkins(Set(d, 2 * p.skin)),
        limit(Set(d, p.limit)),
        zero(Set(d, 0.0f)),
        one(Set(d, 1.0f)),
        half(Set(d, 0.5f)),
        inf(Set(d, std::numeric_limits<float>::infinity())),
        slackScale(Set(d, 1e-4f)),
        maxBounces(p.maxBounces),
        forces(p.forces),
        pushOutFirst(p.pushOutFirst) {}
};

#include "core/particle_integrate-inl.hpp"

// integrate() with a constant acceleration a.
template <class D, class V = LaneOf<D>>
HWY_INLINE void integrate(const Params<D>& p, Vec3L<V>& x, Vec3L<V>& v, V dt, const Vec3L<V>& a) {
  integrateStep(p.integrator, x, v, dt, p.half, [&](const Vec3L<V>&) { return a; });
}

// A path's box, widened by a slack far above the rounding of the exact tests where the
// coordinates are large (1e-4 of their magnitudes, where the tests round at some 1e-6 of them),
// for the rows' culls: a NaN or infinite coordinate makes the slack NaN or infinite, and such a
// lane is never culled.
template <class V>
struct PathBox {
  Vec3L<V> lo, hi;
};
template <class D, class V = LaneOf<D>>
HWY_INLINE PathBox<V> pathBox(const Params<D>& p, const Vec3L<V>& from, const Vec3L<V>& to) {
  const V slack =
      (Abs(from[0]) + Abs(from[1]) + Abs(from[2]) + Abs(to[0]) + Abs(to[1]) + Abs(to[2])) *
      p.slackScale;
  PathBox<V> box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = Min(from[k], to[k]) - slack;
    box.hi[k] = Max(from[k], to[k]) + slack;
  }
  return box;
}

// A surface met: in which lanes, where (the fraction s of the path, or the exit point), its
// outward normal.
template <class D>
struct Surface {
  using V = LaneOf<D>;
  MaskOf<D> hit;
  V s;
  Vec3L<V> point, normal;
};

// One obstacle row as the step reads it, prepared once per call: its values, its grown box, and
// for an OBB its columns normalized() as Eigen does (v / sqrt(|v|^2) when |v|^2 > 0, else v),
// hitObb's normal.
struct RowData {
  core::ObstacleRow::Kind kind;
  float v[15];
  float units[9];
  float lo[3], hi[3];

  explicit RowData(const core::ObstacleRow& r) : kind(r.kind), units{} {
    for (int k = 0; k < 15; ++k) v[k] = r.v[k];
    for (int k = 0; k < 3; ++k) lo[k] = r.lo[k], hi[k] = r.hi[k];
    for (int c = 0; c < 3; ++c) {
      const float* col = r.v + 6 + 3 * c;
      const float n2 = col[0] * col[0] + (col[1] * col[1] + col[2] * col[2]);
      for (int k = 0; k < 3; ++k) units[3 * c + k] = n2 > 0 ? col[k] / std::sqrt(n2) : col[k];
    }
  }
};

// A row broadcast to every lane (on the stack, where vectors are aligned).
template <class D>
struct Row {
  using V = LaneOf<D>;
  core::ObstacleRow::Kind kind;
  Vec3L<V> a, b;  // plane: normal, (d); sphere: centre, (radius); boxes: min / centre, max / half
  V w;            // plane: d; sphere: radius
  Vec3L<V> axes[3];   // OBB: the columns
  Vec3L<V> units[3];  // OBB: the columns normalized
  Vec3L<V> lo, hi;    // RowData's box

  HWY_INLINE Row(D d, const RowData& r)
      : kind(r.kind),
        a(splat3(d, r.v)),
        b(splat3(d, r.v + 3)),
        w(Set(d, r.v[3])),
        lo(splat3(d, r.lo)),
        hi(splat3(d, r.hi)) {
    if (kind != core::ObstacleRow::kObb) return;
    for (int c = 0; c < 3; ++c) {
      axes[c] = splat3(d, r.v + 6 + 3 * c);
      units[c] = splat3(d, r.units + 3 * c);
    }
  }

  // The lanes whose path may come near the row's solid: those not wholly beyond one face of its
  // box (a NaN compares false: such a lane is tested). The reference's mayMeet, lane-wide.
  HWY_INLINE MaskOf<D> near(const PathBox<V>& path) const {
    auto away = Lt(lo[0], lo[0]);  // none
    for (int k = 0; k < 3; ++k) away = Or(away, Or(Lt(path.hi[k], lo[k]), Gt(path.lo[k], hi[k])));
    return Not(away);
  }
};

// The rows broadcast once per call, in memory aligned for vectors, and with kCalls the caller's
// queries: the tree that finds the rows near a vector's paths when there are many, the meshes'
// triangle tests. (A step with their calls in it, even untaken, keeps fewer vectors in registers:
// the step is compiled once without them.)
template <class D, bool kCalls>
class Rows {
 public:
  Rows(D d, const core::ObstacleRow* rows, std::size_t n, const core::ObstacleQueries* queries)
      : rows_(hwy::AllocateAligned<Row<D>>(n > 0 ? n : 1)),
        queries_(queries),
        all_(n),
        width_(Lanes(d)),
        lanes_(hwy::AllocateAligned<float>(kLaneFields * Lanes(d))) {
    for (std::size_t i = 0; i < n; ++i) new (&rows_[i]) Row<D>(d, RowData(rows[i]));
    for (std::size_t i = 0; i < n; ++i) all_[i] = std::uint32_t(i);
  }

  const Row<D>& operator[](std::uint32_t i) const { return rows_[i]; }

  // The rows, in order, that some lane of `live` may come near on `path`, a superset: every row,
  // or with a tree those whose boxes meet a lane's (a lane whose box is not finite meets all).
  // The caller culls each lane with Row::near, as the reference's ObstacleSetT::near does.
  template <class V = LaneOf<D>>
  HWY_INLINE std::span<const std::uint32_t> near(D d, MaskOf<D> live, const PathBox<V>& path) {
    if (!kCalls || !queries_->near) return all_;
    const V inf = Set(d, kInf);
    auto finite = Not(live);
    for (int k = 0; k < 3; ++k) {
      finite = Or(finite, And(Lt(Abs(path.lo[k]), inf), Lt(Abs(path.hi[k]), inf)));
      Store(IfThenElse(live, path.lo[k], inf), d, lane(k));
      Store(IfThenElse(live, path.hi[k], Neg(inf)), d, lane(3 + k));
    }
    if (!AllTrue(d, finite)) return all_;
    queries_->near(queries_->context, lane(0), lane(3), Lanes(d), ids_);
    return ids_;
  }

  // Whether the rows come from the tree (ObstacleSetT::near's rule then holds for push-outs).
  bool tree() const { return kCalls && queries_->near; }

  // The first entry of the lanes of `live` into mesh row i: the caller's test, lane by lane.
  template <class V = LaneOf<D>>
  HWY_NOINLINE Surface<D> meshEntry(D d, std::uint32_t i, MaskOf<D> live, const Vec3L<V>& x0,
                                    const Vec3L<V>& dir) {
    const V zero = Zero(d), one = Set(d, 1.0f);
    for (int k = 0; k < 3; ++k) Store(x0[k], d, lane(k)), Store(dir[k], d, lane(3 + k));
    Store(IfThenElse(live, one, zero), d, lane(6));
    queries_->meshEntry(queries_->context, i, Lanes(d), lane(0), lane(3), lane(6), lane(7), lane(8),
                        lane(11));
    Surface<D> e;
    e.hit = And(live, Gt(Load(d, lane(11)), zero));
    e.s = IfThenElse(e.hit, Load(d, lane(7)), zero);
    for (int k = 0; k < 3; ++k) e.normal[k] = IfThenElse(e.hit, Load(d, lane(8 + k)), zero);
    return e;
  }

 private:
  static constexpr float kInf = std::numeric_limits<float>::infinity();
  // Lanes handed to the queries: a box (lo x, y, z, hi x, y, z) or a path (x0, dir, live) and
  // its entry (s, normal, hit).
  static constexpr std::size_t kLaneFields = 12;
  float* lane(std::size_t k) { return lanes_.get() + k * width_; }
  hwy::AlignedFreeUniquePtr<Row<D>[]> rows_;
  const core::ObstacleQueries* queries_;
  std::vector<std::uint32_t> all_, ids_;
  std::size_t width_;  // Lanes(d)
  hwy::AlignedFreeUniquePtr<float[]> lanes_;
};

// The unit vector along `axis` (a lane's 0, 1 or 2) of three, with the sign of `positive`.
template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> onAxis(D d, V axis, const Vec3L<V> (&columns)[3], MaskOf<D> positive) {
  Vec3L<V> n = IfThenElse(Eq(axis, Set(d, 1.0f)), columns[1], columns[0]);
  n = IfThenElse(Eq(axis, Set(d, 2.0f)), columns[2], n);
  return IfThenElse(positive, n, Neg(n));
}

// exitOf(): where a point strictly inside the row's solid leaves it by the shortest way, in the
// lanes of `live` (e.hit). The exit is worked out only if some lane is inside: most are not.
template <class D, class V = LaneOf<D>>
HWY_INLINE Surface<D> exitOf(D d, const Params<D>& p, const Row<D>& row, MaskOf<D> live,
                             const Vec3L<V>& x) {
  Surface<D> e;
  switch (row.kind) {
    case core::ObstacleRow::kMesh:  // a surface: nothing is inside
      e.hit = Lt(p.one, p.zero);
      break;
    case core::ObstacleRow::kPlane: {
      const V f = dot(row.a, x) + row.w;
      e.hit = And(live, Lt(f, p.zero));
      e.point = x - row.a * f;
      e.normal = row.a;
      break;
    }
    case core::ObstacleRow::kSphere: {
      const Vec3L<V> r = x - row.a;
      const V r2 = dot(r, r);
      e.hit = And(live, Lt(r2, row.w * row.w));
      if (AllFalse(d, e.hit)) break;
      const Vec3L<V> up{{p.zero, p.one, p.zero}};  // at the very centre: +y, as documented
      e.normal = IfThenElse(Gt(r2, p.zero), r / Sqrt(r2), up);
      e.point = row.a + e.normal * row.w;
      break;
    }
    case core::ObstacleRow::kAabb: {
      e.hit = live;
      for (int k = 0; k < 3; ++k)
        e.hit = And(e.hit, And(Gt(x[k] - row.a[k], p.zero), Gt(row.b[k] - x[k], p.zero)));
      if (AllFalse(d, e.hit)) break;
      // The face of least depth, ties to the lowest axis and its min face.
      V depth = p.inf, axis = p.zero;
      auto toMax = Lt(p.one, p.zero);
      for (int k = 0; k < 3; ++k) {
        const V below = x[k] - row.a[k], above = row.b[k] - x[k];
        const auto byBelow = Lt(below, depth);
        depth = IfThenElse(byBelow, below, depth);
        axis = IfThenElse(byBelow, Set(d, float(k)), axis);
        toMax = And(toMax, Not(byBelow));
        const auto byAbove = Lt(above, depth);
        depth = IfThenElse(byAbove, above, depth);
        axis = IfThenElse(byAbove, Set(d, float(k)), axis);
        toMax = Or(toMax, byAbove);
      }
      for (int k = 0; k < 3; ++k) {
        const auto on = Eq(axis, Set(d, float(k)));
        e.point[k] = IfThenElse(on, IfThenElse(toMax, row.b[k], row.a[k]), x[k]);
        e.normal[k] = IfThenElse(on, IfThenElse(toMax, p.one, Neg(p.one)), p.zero);
      }
      break;
    }
    case core::ObstacleRow::kObb: {
      const Vec3L<V> q = toLocal(row.axes, x - row.a);
      e.hit = live;
      for (int k = 0; k < 3; ++k) e.hit = And(e.hit, Gt(row.b[k] - Abs(q[k]), p.zero));
      if (AllFalse(d, e.hit)) break;
      // The face of least depth h - |q| (ties: the lowest axis), on the side of q's sign.
      V depth = p.inf, axis = p.zero, side = p.zero;
      for (int k = 0; k < 3; ++k) {
        const V dk = row.b[k] - Abs(q[k]);
        const auto deeper = Lt(dk, depth);
        depth = IfThenElse(deeper, dk, depth);
        axis = IfThenElse(deeper, Set(d, float(k)), axis);
        side = IfThenElse(deeper, q[k], side);
      }
      e.normal = onAxis(d, axis, row.axes, Not(SignBit(d, side)));
      e.point = x + e.normal * depth;
      break;
    }
  }
  return e;
}

// The slab test of raycast-inl.hpp's slabs() for a path that must enter the box from outside
// within [0, 1]: s is the entry, `axis` the axis of the face entered (ties: the lowest).
template <class D, class V = LaneOf<D>>
HWY_INLINE MaskOf<D> slabEntry(D d, const Params<D>& p, const Vec3L<V>& lo, const Vec3L<V>& hi,
                               const Vec3L<V>& o, const Vec3L<V>& dir, V& s, V& axis) {
  V enter = Neg(p.inf), exit = p.inf;
  axis = p.zero;
  for (int k = 0; k < 3; ++k) {
    const auto negative = SignBit(d, dir[k]);
    const V tNear = (IfThenElse(negative, hi[k], lo[k]) - o[k]) / dir[k];
    const V tFar = (IfThenElse(negative, lo[k], hi[k]) - o[k]) / dir[k];
    const auto nearer = Gt(tNear, enter);
    enter = IfThenElse(nearer, tNear, enter);
    axis = IfThenElse(nearer, Set(d, float(k)), axis);
    exit = IfThenElse(Lt(tFar, exit), tFar, exit);
  }
  s = enter + p.zero;  // -0 becomes +0
  return And(Le(enter, exit), And(Ge(enter, p.zero), Le(enter, p.one)));
}

// entryOf(): the first point where the path x0 -> x0 + dir enters the row's solid from outside,
// in the lanes of `live` (e.hit). The normal is worked out only if some lane enters.
template <class D, class V = LaneOf<D>>
HWY_INLINE Surface<D> entryOf(D d, const Params<D>& p, const Row<D>& row, MaskOf<D> live,
                              const Vec3L<V>& x0, const Vec3L<V>& dir) {
  Surface<D> e;
  switch (row.kind) {
    case core::ObstacleRow::kMesh:  // Rows::meshEntry's
      e.hit = Lt(p.one, p.zero);
      break;
    case core::ObstacleRow::kPlane: {
      const V f0 = dot(row.a, x0) + row.w;
      const V rate = dot(row.a, dir);
      e.hit = And(live, And(Ge(f0, p.zero), Lt(f0 + rate, p.zero)));
      e.s = f0 / Neg(rate);
      e.normal = row.a;
      break;
    }
    case core::ObstacleRow::kSphere: {
      // hitSphere(): from outside (c0 > 0) the entry, or on the surface (c0 == 0) not leaving.
      const Vec3L<V> c = row.a - x0;
      const V dd = dot(dir, dir);
      const V r2 = row.w * row.w;
      const V c0 = dot(c, c) - r2;
      const V b = dot(c, dir) / dd;
      Vec3L<V> m = c - dir * b;
      m = m - dir * (dot(m, dir) / dd);
      const V h2 = r2 - dot(m, m);
      const V f = Sqrt(h2 / dd);
      const auto outside = Gt(c0, p.zero);
      const auto enters = And(outside, And(Gt(b, p.zero), Ge(h2, p.zero)));
      const auto touches = And(Eq(c0, p.zero), Not(Lt(b, p.zero)));
      e.s = IfThenElse(outside, (c0 / dd) / (b + f), p.zero);
      e.hit = And(live, And(Or(enters, touches), Le(e.s, p.one)));
      if (AllFalse(d, e.hit)) break;
      // unitOr(outward, -dir / |dir|): divided by the largest |component| (std::max's order),
      // then by its length.
      const Vec3L<V> outward = IfThenElse(outside, Neg(m) - dir * f, Neg(c));
      const V ax = Abs(outward[0]), ay = Abs(outward[1]), az = Abs(outward[2]);
      const V yz = IfThenElse(Lt(ay, az), az, ay);
      const V largest = IfThenElse(Lt(ax, yz), yz, ax);
      const Vec3L<V> scaled = outward / largest;
      const Vec3L<V> unit = scaled / Sqrt(dot(scaled, scaled));
      e.normal =
          IfThenElse(And(Gt(largest, p.zero), Lt(largest, p.inf)), unit, Neg(dir) / Sqrt(dd));
      break;
    }
    case core::ObstacleRow::kAabb: {
      V axis;
      e.hit = And(live, slabEntry(d, p, row.a, row.b, x0, dir, e.s, axis));
      if (AllFalse(d, e.hit)) break;
      Vec3L<V> n;
      for (int k = 0; k < 3; ++k) {
        // The face facing the path: -sign(dir) along the axis entered.
        n[k] = IfThenElse(Eq(axis, Set(d, float(k))),
                          IfThenElse(SignBit(d, dir[k]), p.one, Neg(p.one)), p.zero);
      }
      e.normal = n;
      break;
    }
    case core::ObstacleRow::kObb: {
      const Vec3L<V> o = toLocal(row.axes, x0 - row.a), l = toLocal(row.axes, dir);
      V axis;
      e.hit = And(live, slabEntry(d, p, Neg(row.b), row.b, o, l, e.s, axis));
      if (AllFalse(d, e.hit)) break;
      V la = IfThenElse(Eq(axis, Set(d, 1.0f)), l[1], l[0]);
      la = IfThenElse(Eq(axis, Set(d, 2.0f)), l[2], la);
      e.normal = onAxis(d, axis, row.units, SignBit(d, la));
      break;
    }
  }
  return e;
}

// pushOut(): the `live` lanes strictly inside a row, in order, go to `skin` outside it and lose
// the part of v into its surface. The rows are those near where the lanes start (with a tree, as
// the reference finds them); without a tree, those near where they are when the row comes up.
template <class D, bool kCalls, class V = LaneOf<D>>
HWY_INLINE void pushOut(D d, const Params<D>& p, Rows<D, kCalls>& rows, MaskOf<D> live, Vec3L<V>& x,
                        Vec3L<V>& v, core::ParticleCounts& counts) {
  if (AllFalse(d, live)) return;
  PathBox<V> at = pathBox(p, x, x);
  for (const std::uint32_t i : rows.near(d, live, at)) {
    const Row<D>& row = rows[i];
    if (AllFalse(d, And(live, row.near(at)))) continue;
    const Surface<D> e = exitOf(d, p, row, live, x);
    const auto in = e.hit;
    if (AllFalse(d, in)) continue;
    x = IfThenElse(in, e.point + e.normal * p.skin, x);
    if (!rows.tree()) at = pathBox(p, x, x);
    const V vn = dot(v, e.normal);
    v = IfThenElse(And(in, Lt(vn, p.zero)), v - e.normal * vn, v);
    counts.pushedOut += CountTrue(d, in);
  }
}

// respond(): restitution above the threshold speed, Coulomb friction that never reverses.
template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> respond(const Params<D>& p, const Vec3L<V>& v, const Vec3L<V>& n) {
  const V vn = dot(v, n);
  const V e = IfThenElse(Gt(Neg(vn), p.threshold), p.restitution, p.zero);
  Vec3L<V> vt = v - n * vn;
  const V vtLength = Sqrt(dot(vt, vt));
  const V keep = p.one - p.friction * ((p.one + e) * Neg(vn)) / vtLength;
  vt = IfThenElse(Gt(vtLength, p.zero), vt * IfThenElse(Lt(p.zero, keep), keep, p.zero), vt);
  return IfThenElse(Lt(vn, p.zero), vt - n * (e * vn), v);
}

// rest() in the lanes of `m`: the surface takes the parts of v and a into it, and Coulomb
// friction acts against the sliding velocity, or stops it.
template <class D, class V = LaneOf<D>>
HWY_INLINE void rest(const Params<D>& p, MaskOf<D> m, const Vec3L<V>& n, V tau, Vec3L<V>& v,
                     Vec3L<V>& a) {
  const V vn = dot(v, n);
  v = IfThenElse(And(m, Lt(vn, p.zero)), v - n * vn, v);
  const V an = dot(a, n);
  const auto pressed = And(m, Lt(an, p.zero));
  const Vec3L<V> along = a - n * an;
  const V f = p.friction * Neg(an);
  const Vec3L<V> vt = v - n * dot(v, n);
  const V speed = Sqrt(dot(vt, vt));
  const Vec3L<V> sliding = along - vt * (f / speed);
  // Still sliding the same way at the end of tau.
  const auto slides = And(Gt(speed, p.zero), Gt(dot(vt + sliding * tau, vt), p.zero));
  const V at = Sqrt(dot(along, along));
  const Vec3L<V> held{{p.zero, p.zero, p.zero}};
  const Vec3L<V> stopped = IfThenElse(Gt(at, f), along * (p.one - f / at), held);
  a = IfThenElse(pressed, IfThenElse(slides, sliding, stopped), a);
  v = IfThenElse(And(pressed, Not(slides)), v - vt, v);
}

// stepParticle() for the lanes at [i, i + lanes) below `end`.
template <class D, bool kCalls>
HWY_INLINE void stepLanes(D d, const Params<D>& p, const ParticlesView& s, std::size_t i,
                          std::size_t end, Rows<D, kCalls>& rows, core::ParticleCounts& counts) {
  using V = LaneOf<D>;
  namespace F = fields;
  const auto load3 = [&](std::size_t f) {
    return Vec3L<V>{{LoadU(d, s[f] + i), LoadU(d, s[f + 1] + i), LoadU(d, s[f + 2] + i)}};
  };
  const Vec3L<V> xIn = load3(F::Particle::x), vIn = load3(F::Particle::vx);
  const V w = LoadU(d, s[F::Particle::invMass] + i);
  const auto active = And(Gt(w, p.zero), FirstN(d, end - i));  // not pinned, not past end
  if (AllFalse(d, active)) return;

  Vec3L<V> a = p.gravity;
  if (p.forces) a = a + (load3(F::Particle::fx) - vIn * p.drag) * w;
  Vec3L<V> x = xIn, v = vIn;
  Vec3L<V> x0 = x, v0 = v * p.damping, x1 = x0, v1 = v0;
  V tau = p.dt;
  integrate(p, x1, v1, tau, a);
  auto live = active;
  for (int bounce = 0;; ++bounce) {
    const Vec3L<V> dir = x1 - x0;
    const PathBox<V> path = pathBox(p, x0, x1);
    live = And(live, Not(Eq(dot(dir, dir), p.zero)));  // not moving: meets nothing
    // The first entry per lane; ties go to the earlier row.
    auto found = Lt(p.one, p.zero);
    V first = p.zero;
    Vec3L<V> normal{{p.zero, p.zero, p.zero}};
    for (const std::uint32_t r : rows.near(d, live, path)) {
      const Row<D>& row = rows[r];
      if (AllFalse(d, And(live, row.near(path)))) continue;
      Surface<D> e;
      if constexpr (kCalls) {
        e = row.kind == core::ObstacleRow::kMesh
                ? rows.meshEntry(d, r, And(live, row.near(path)), x0, dir)
                : entryOf(d, p, row, live, x0, dir);
      } else {
        e = entryOf(d, p, row, live, x0, dir);
      }
      const auto better = And(e.hit, Or(Not(found), Lt(e.s, first)));
      first = IfThenElse(better, e.s, first);
      normal = IfThenElse(better, e.normal, normal);
      found = Or(found, better);
    }
    const auto hit = And(found, live);
    if (AllFalse(d, hit)) break;
    counts.contacts += CountTrue(d, hit);
    const Vec3L<V> vh = v0 + a * (first * tau);  // the velocity at the contact
    const Vec3L<V> contact = x0 + dir * first + normal * p.skin;
    if (bounce == p.maxBounces) {
      counts.bounceLimited += CountTrue(d, hit);
      Vec3L<V> xs = contact, vs = respond(p, vh, normal);
      pushOut(d, p, rows, hit, xs, vs, counts);
      x1 = IfThenElse(hit, xs, x1);
      v1 = IfThenElse(hit, vs, v1);
      break;
    }
    // A slow contact rests; one that arrived from further than two skins first stops at the
    // contact, as a bounce does, and both go on from there for the time left.
    const auto resting = And(hit, Le(Neg(dot(vh, normal)), p.threshold));
    const auto arrived = Gt(first * Neg(dot(dir, normal)), p.twoSkins);
    const auto moves = And(hit, Or(Not(resting), arrived));
    const auto bounces = And(hit, Not(resting));
    Vec3L<V> xs = contact,
             vs = AllFalse(d, bounces) ? vh : IfThenElse(bounces, respond(p, vh, normal), vh);
    pushOut(d, p, rows, moves, xs, vs, counts);  // a contact in a corner between obstacles
    x0 = IfThenElse(moves, xs, x0);
    v0 = IfThenElse(moves, vs, v0);
    tau = IfThenElse(moves, (p.one - first) * tau, tau);
    if (!AllFalse(d, resting)) rest(p, resting, normal, tau, v0, a);
    Vec3L<V> xn = x0, vn = v0;
    integrate(p, xn, vn, tau, a);
    x1 = IfThenElse(hit, xn, x1);
    v1 = IfThenElse(hit, vn, v1);
    live = hit;
  }
  const std::uint64_t before = counts.pushedOut;
  pushOut(d, p, rows, active, x1, v1, counts);  // no particle ends a step inside (the reference's)
  counts.endPushed += counts.pushedOut - before;
  // Past the supported range (or NaN) the step is not taken.
  auto inRange = active;
  for (int k = 0; k < 3; ++k)
    inRange = And(inRange, And(Le(Abs(x1[k]), p.limit), Le(Abs(v1[k]), p.limit)));
  counts.outOfRange += CountTrue(d, And(active, Not(inRange)));
  x = IfThenElse(inRange, x1, xIn);
  v = IfThenElse(inRange, v1, vIn);
  for (int k = 0; k < 3; ++k) {
    StoreU(x[k], d, s[F::Particle::x + k] + i);
    StoreU(v[k], d, s[F::Particle::vx + k] + i);
  }
}

// The step's first push-out (pushOut()) for the lanes at [i, i + lanes) below `end`, as a pass
// of its own: the step runs it only when a particle may be inside (ParticleStepParams), and the
// fused step is faster without its code.
template <class D, bool kCalls>
HWY_INLINE void pushOutLanes(D d, const Params<D>& p, const ParticlesView& s, std::size_t i,
                             std::size_t end, Rows<D, kCalls>& rows, core::ParticleCounts& counts) {
  using V = LaneOf<D>;
  namespace F = fields;
  const V w = LoadU(d, s[F::Particle::invMass] + i);
  const auto active = And(Gt(w, p.zero), FirstN(d, end - i));
  if (AllFalse(d, active)) return;
  Vec3L<V> x, v;
  for (int k = 0; k < 3; ++k) {
    x[k] = LoadU(d, s[F::Particle::x + k] + i);
    v[k] = LoadU(d, s[F::Particle::vx + k] + i);
  }
  pushOut(d, p, rows, active, x, v, counts);
  for (int k = 0; k < 3; ++k) {
    StoreU(x[k], d, s[F::Particle::x + k] + i);
    StoreU(v[k], d, s[F::Particle::vx + k] + i);
  }
}

template <bool kCalls, class D>
HWY_NOINLINE core::ParticleCounts stepRange(D d, const ParticlesView& s, std::size_t begin,
                                            std::size_t end, const core::ObstacleRow* rows,
                                            std::size_t n, const core::ObstacleQueries* queries,
                                            const core::ParticleStepParams& params) {
  const Params<D> p(d, params);
  Rows<D, kCalls> prepared(d, rows, n, queries);
  core::ParticleCounts counts;
  if (p.pushOutFirst)
    for (std::size_t i = begin; i < end; i += Lanes(d))
      pushOutLanes(d, p, s, i, end, prepared, counts);
  for (std::size_t i = begin; i < end; i += Lanes(d)) stepLanes(d, p, s, i, end, prepared, counts);
  return counts;
}

template <class D>
core::ParticleCounts stepRange(D d, const ParticlesView& s, std::size_t begin, std::size_t end,
                               const core::ObstacleRow* rows, std::size_t n,
                               const core::ObstacleQueries* queries,
                               const core::ParticleStepParams& params) {
  return queries ? stepRange<true>(d, s, begin, end, rows, n, queries, params)
                 : stepRange<false>(d, s, begin, end, rows, n, queries, params);
}

core::ParticleCounts StepParticles(const ParticlesView& s, std::size_t begin, std::size_t end,
                                   const core::ObstacleRow* rows, std::size_t n,
                                   const core::ObstacleQueries* queries,
                                   const core::ParticleStepParams& params) {
  return stepRange(hn::ScalableTag<float>(), s, begin, end, rows, n, queries, params);
}

// ---- baseline ----------------------------------------------------------------------------------
// The same step as a plain loop over the particles, a float per lane, left to the compiler.
core::ParticleCounts StepParticlesAutovec(const ParticlesView& s, std::size_t begin,
                                          std::size_t end, const core::ObstacleRow* rows,
                                          std::size_t n, const core::ObstacleQueries* queries,
                                          const core::ParticleStepParams& params) {
  return stepRange(ScalarLane(), s, begin, end, rows, n, queries, params);
}

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(StepParticles, stepParticles);
SIMDPHYS_EXPORT(StepParticlesAutovec, stepParticlesAutovec);
}  // namespace simdphys::simd
#endif

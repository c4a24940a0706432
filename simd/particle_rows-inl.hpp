// The static obstacles lane-wide for the particle step (simd/particles.cpp): a row per obstacle
// broadcast to every lane, the caller's queries (the tree, the meshes), and the reference's exit
// and entry tests (src/reference/particles/step-inl.hpp, the ray hits of
// src/reference/geometry3d/raycast-inl.hpp) operation for operation. Included inside each
// target's namespace after simd/particle_lanes-inl.hpp (no include guard, by design). Needs
// <hwy/aligned_allocator.h>, <new>, <span> and <vector>.

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

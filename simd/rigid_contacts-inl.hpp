// The contact passes of the rigid-body solver (core/rigid_solve.hpp) written once over lanes: a
// Highway vector of contacts (simd/rigid.cpp) or one contact at a time (its plain-loop baseline).
// The arithmetic is src/reference/rigid/solver-inl.hpp's, point by point, its products and sums
// fused (below). Included inside each target's namespace (no include guard, by design), after
// simd/rigid_records-inl.hpp.

// A vector's fields in the rows (core::ContactRows' blocks): field k at k * kBlockLanes floats
// past the first, fixed offsets from one pointer.
struct RowLanes {
  float* first;
  float* operator[](std::size_t field) const {
    return first + field * core::ContactRows::kBlockLanes;
  }
};

// The passes are chains of dot and cross products: with their products and sums fused they take
// 0.7 of the time (W5, avx512dl). Highway's MulAdd family: one rounding where the target has FMA,
// a product and a sum where it has not; the one-float lane likewise (core/scalar_lanes-inl.hpp),
// so the plain loops do the same arithmetic. The reference rounds each product: the two differ
// by rounding, which their tests allow.

template <class V>
HWY_INLINE V fusedDot(const Vec3L<V>& a, const Vec3L<V>& b) {
  return MulAdd(a[0], b[0], MulAdd(a[1], b[1], a[2] * b[2]));
}
// acc + a s, component-wise.
template <class V>
HWY_INLINE Vec3L<V> mulAdd(const Vec3L<V>& a, V s, const Vec3L<V>& acc) {
  return {{MulAdd(a[0], s, acc[0]), MulAdd(a[1], s, acc[1]), MulAdd(a[2], s, acc[2])}};
}
template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> cross(const Vec3L<V>& a, const Vec3L<V>& b) {
  return {{MulSub(a[1], b[2], a[2] * b[1]), MulSub(a[2], b[0], a[0] * b[2]),
           MulSub(a[0], b[1], a[1] * b[0])}};
}
// acc + a x b.
template <class V>
HWY_INLINE Vec3L<V> crossAdd(const Vec3L<V>& a, const Vec3L<V>& b, const Vec3L<V>& acc) {
  return {{MulAdd(a[1], b[2], NegMulAdd(a[2], b[1], acc[0])),
           MulAdd(a[2], b[0], NegMulAdd(a[0], b[2], acc[1])),
           MulAdd(a[0], b[1], NegMulAdd(a[1], b[0], acc[2]))}};
}

// The lanes' bodies: what a pass reads of them, and their velocities written back.
template <class D>
struct LaneBodies {
  using V = LaneOf<D>;
  const std::uint32_t* index;  // each lane's body
  Vec3L<V> v, w, dp;
  V dq[4];
  V invMass;
  V inertia[6];  // xx, xy, xz, yy, yz, zz

  // The lane's body A (or B) of the rows at `lane`.
  LaneBodies(D d, const core::SolverBody* bodies, const core::ContactRows& rows, std::size_t lane,
             bool isB)
      : index((isB ? rows.b : rows.a) + lane) {
    const RowLanes r{rows.lanes(lane)};
    V f[kRecordFloats];
    loadRecords(d, bodies, index, f);
    v = {{f[0], f[1], f[2]}}, w = {{f[3], f[4], f[5]}}, dp = {{f[6], f[7], f[8]}};
    for (std::size_t k = 0; k < 4; ++k) dq[k] = f[9 + k];
    using R = core::ContactRows;
    invMass = Load(d, r[isB ? R::invMassB : R::invMassA]);
    for (std::size_t k = 0; k < 6; ++k)
      inertia[k] = Load(d, r[(isB ? R::inertiaB : R::inertiaA) + k]);
  }
  void store(D d, core::SolverBody* bodies) const {
    const V f[8] = {v[0], v[1], v[2], w[0], w[1], w[2], dp[0], dp[1]};
    storeRecords(d, bodies, index, f, 8);
  }
  // The world inverse inertia times x (the reference's Mat3 product: a row's dot with x).
  Vec3L<V> inertiaTimes(const Vec3L<V>& x) const {
    const V zero = Zero(D());
    return inertiaTimesAdd(x, {{zero, zero, zero}});
  }
  // acc + the world inverse inertia times x.
  Vec3L<V> inertiaTimesAdd(const Vec3L<V>& x, const Vec3L<V>& acc) const {
    const auto row = [&](std::size_t i, std::size_t j, std::size_t k, const V& to) {
      return MulAdd(inertia[i], x[0], MulAdd(inertia[j], x[1], MulAdd(inertia[k], x[2], to)));
    };
    return {{row(0, 1, 2, acc[0]), row(1, 3, 4, acc[1]), row(2, 4, 5, acc[2])}};
  }
  // dq^-1 n - n: the normal turned back by the body's turn since the step's start (the
  // reference's Separation: Eigen's q * v, v + w 2 (q x v) + q x 2 (q x v), with q conjugated).
  Vec3L<V> turnedBack(const Vec3L<V>& n) const {
    const Vec3L<V> q{{Neg(dq[0]), Neg(dq[1]), Neg(dq[2])}};
    Vec3L<V> uv = cross<D>(q, n);
    uv = uv + uv;
    return (mulAdd(uv, dq[3], n) + cross<D>(q, uv)) - n;
  }
};

template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> load3(D d, const RowLanes& r, std::size_t first) {
  return {{Load(d, r[first]), Load(d, r[first + 1]), Load(d, r[first + 2])}};
}

template <class D, class V = LaneOf<D>>
HWY_INLINE void applyImpulse(LaneBodies<D>& a, LaneBodies<D>& b, const Vec3L<V>& rA,
                             const Vec3L<V>& rB, const Vec3L<V>& P) {
  a.v = mulAdd(P, Neg(a.invMass), a.v);
  a.w = a.inertiaTimesAdd(cross<D>(P, rA), a.w);
  b.v = mulAdd(P, b.invMass, b.v);
  b.w = b.inertiaTimesAdd(cross<D>(rB, P), b.w);
}

template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> relativeVelocity(const LaneBodies<D>& a, const LaneBodies<D>& b,
                                     const Vec3L<V>& rA, const Vec3L<V>& rB) {
  return crossAdd(b.w, rB, b.v) - crossAdd(a.w, rA, a.v);
}

template <class D, class V = LaneOf<D>>
HWY_INLINE V relativeAlong(const LaneBodies<D>& a, const LaneBodies<D>& b, const Vec3L<V>& rA,
                           const Vec3L<V>& rB, const Vec3L<V>& n) {
  return fusedDot(relativeVelocity(a, b, rA, rB), n);
}

// The most points of the lanes' manifolds: past it every lane's points are inert (lanes are
// grouped by count within a batch: KernelPasses::prepare), and a pass skips them.
inline std::size_t pointsOf(ScalarLane, const RowLanes& r) {
  return std::size_t(*r[core::ContactRows::count]);
}
template <class D>
HWY_INLINE std::size_t pointsOf(D d, const RowLanes& r) {
  return std::size_t(hn::GetLane(hn::MaxOfLanes(d, hn::Load(d, r[core::ContactRows::count]))));
}

// Each batch's vectors in turn; a batch's lanes share no moving body.
template <class D, class F>
HWY_INLINE void forEachVector(D d, const core::ContactRows& rows, F&& f) {
  const std::size_t N = Lanes(d);
  for (std::size_t batch = 0; batch < rows.batches; ++batch)
    for (std::size_t lane = rows.batchBegin[batch]; lane < rows.batchBegin[batch + 1]; lane += N)
      f(lane);
}

// The effective mass along dir at anchors rA, rB (the reference's effectiveMass); 0 where the
// lanes have no mass along it.
template <class D, class V = LaneOf<D>>
HWY_INLINE V effectiveMass(D d, const LaneBodies<D>& a, const LaneBodies<D>& b, const Vec3L<V>& rA,
                           const Vec3L<V>& rB, const Vec3L<V>& dir) {
  const Vec3L<V> ra = cross<D>(rA, dir), rb = cross<D>(rB, dir);
  const V k =
      a.invMass + b.invMass + fusedDot(ra, a.inertiaTimes(ra)) + fusedDot(rb, b.inertiaTimes(rb));
  const auto some = Gt(k, Zero(d));
  return IfThenElse(some, Set(d, 1.0f) / IfThenElse(some, k, Set(d, 1.0f)), Zero(d));
}

// The reference's tangentsOf, in its arithmetic (unfused): t1 = (n.z, 0, -n.x) or (0, n.z, -n.y),
// whichever of n.x and n.y is larger, normalised; t2 = n x t1.
template <class D, class V = LaneOf<D>>
HWY_INLINE void tangentsOf(D d, const Vec3L<V>& n, Vec3L<V>& t1, Vec3L<V>& t2) {
  const auto xLarger = Gt(Abs(n[0]), Abs(n[1]));
  const V zero = Zero(d);
  t1 = {{IfThenElse(xLarger, n[2], zero), IfThenElse(xLarger, zero, n[2]),
         Neg(IfThenElse(xLarger, n[0], n[1]))}};
  const V squared = dot(t1, t1);  // 0 in a padding lane (no normal): left 0, as Eigen does
  t1 = t1 / Sqrt(IfThenElse(Gt(squared, zero), squared, Set(d, 1.0f)));
  t2 = {{n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]}};
}

// The points' tangents, masses and normal velocities at the step's start (the reference's
// prepareContacts); points past a manifold's count stay inert.
template <class D>
void prepareT(D d, const core::ContactRows& rows, const core::SolverBody* bodies) {
  using V = LaneOf<D>;
  using R = core::ContactRows;
  forEachVector(d, rows, [&](std::size_t lane) {
    const RowLanes r{rows.lanes(lane)};
    const LaneBodies<D> a(d, bodies, rows, lane, false), b(d, bodies, rows, lane, true);
    const Vec3L<V> n = load3(d, r, R::nx);
    Vec3L<V> t1, t2;
    tangentsOf(d, n, t1, t2);
    for (std::size_t k = 0; k < 3; ++k) {
      Store(t1[k], d, r[R::t1x + k]);
      Store(t2[k], d, r[R::t2x + k]);
    }
    const V count = Load(d, r[R::count]);
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t p = R::kPoint + k * R::kPointFields;
      const auto live = Lt(Set(d, float(k)), count);
      const Vec3L<V> rA = load3(d, r, p + R::rAx), rB = load3(d, r, p + R::rBx);
      Store(IfThenElse(live, effectiveMass(d, a, b, rA, rB, n), Zero(d)), d, r[p + R::normalMass]);
      Store(IfThenElse(live, effectiveMass(d, a, b, rA, rB, t1), Zero(d)), d,
            r[p + R::tangentMass1]);
      Store(IfThenElse(live, effectiveMass(d, a, b, rA, rB, t2), Zero(d)), d,
            r[p + R::tangentMass2]);
      Store(IfThenElse(live, relativeAlong(a, b, rA, rB, n), Zero(d)), d, r[p + R::relative]);
      Store(Zero(d), d, r[p + R::maxNormal]);
    }
  });
}

template <class D>
void warmStartT(D d, const core::ContactRows& rows, core::SolverBody* bodies) {
  using V = LaneOf<D>;
  using R = core::ContactRows;
  forEachVector(d, rows, [&](std::size_t lane) {
    const RowLanes r{rows.lanes(lane)};
    LaneBodies<D> a(d, bodies, rows, lane, false), b(d, bodies, rows, lane, true);
    const Vec3L<V> n = load3(d, r, R::nx), t1 = load3(d, r, R::t1x), t2 = load3(d, r, R::t2x);
    for (std::size_t k = 0, points = pointsOf(d, r); k < points; ++k) {
      const std::size_t p = R::kPoint + k * R::kPointFields;
      const Vec3L<V> rA = load3(d, r, p + R::rAx), rB = load3(d, r, p + R::rBx);
      const Vec3L<V> P =
          mulAdd(n, Load(d, r[p + R::normalImpulse]),
                 mulAdd(t1, Load(d, r[p + R::tangent1]), t2 * Load(d, r[p + R::tangent2])));
      applyImpulse(a, b, rA, rB, P);
    }
    a.store(d, bodies);
    b.store(d, bodies);
  });
}

// One vector of contacts through a solve pass: its rows, its bodies, and a point's friction and
// normal steps (the reference's solveContacts, in the same order of operations).
template <class D>
struct SolveLanes {
  using V = LaneOf<D>;
  using R = core::ContactRows;
  D d;
  const core::ContactPass& pass;
  RowLanes r;
  LaneBodies<D> a, b;
  Vec3L<V> n, t[2];
  V friction, biasRate, massScale, impulseScale;
  bool bounces;        // a lane has restitution: the points' impact speeds and largest pushes kept
  std::size_t points;  // the most points of the lanes' manifolds
  Vec3L<V> nA, nB;     // the reference's Separation: a point's n.(dq r - r) as (dq^-1 n - n).r
  V along;

  SolveLanes(D d_, const core::ContactRows& rows, const core::SolverBody* bodies, std::size_t lane,
             const core::ContactPass& p)
      : d(d_),
        pass(p),
        r{rows.lanes(lane)},
        a(d, bodies, rows, lane, false),
        b(d, bodies, rows, lane, true),
        n(load3(d, r, R::nx)),
        t{load3(d, r, R::t1x), load3(d, r, R::t2x)},
        friction(Load(d, r[R::friction])),
        biasRate(Zero(d)),
        massScale(Set(d, 1.0f)),
        impulseScale(Zero(d)),
        bounces(!AllTrue(d, Eq(Load(d, r[R::restitution]), Zero(d)))),
        points(pointsOf(d, r)) {
    if (pass.bias == core::ContactPass::kSoft) {
      biasRate = Load(d, r[R::biasRate]);
      massScale = Load(d, r[R::massScale]);
      impulseScale = Load(d, r[R::impulseScale]);
    }
  }
  static std::size_t point(std::size_t k) { return R::kPoint + k * R::kPointFields; }

  HWY_INLINE void frictionAt(std::size_t k) {
    const std::size_t p = point(k);
    const Vec3L<V> rA = load3(d, r, p + R::rAx), rB = load3(d, r, p + R::rBx);
    // The reference's cone clamp (solver-inl.hpp).
    const V limit = friction * Load(d, r[p + R::normalImpulse]);
    const Vec3L<V> dv = relativeVelocity(a, b, rA, rB);
    V old[2], total[2];
    for (std::size_t i = 0; i < 2; ++i) {
      const V vt = fusedDot(dv, t[i]);
      old[i] = Load(d, r[p + R::tangent1 + i]);
      total[i] = NegMulAdd(Load(d, r[p + R::tangentMass1 + i]), vt, old[i]);
    }
    const V squared = MulAdd(total[0], total[0], total[1] * total[1]);
    const auto over = Gt(squared, limit * limit);  // then squared > 0
    if (!AllFalse(d, over)) {  // a resting pile's points mostly stick: no root, no division
      const V scale = limit / Sqrt(IfThenElse(over, squared, Set(d, 1.0f)));
      for (std::size_t i = 0; i < 2; ++i) total[i] = IfThenElse(over, total[i] * scale, total[i]);
    }
    for (std::size_t i = 0; i < 2; ++i) Store(total[i], d, r[p + R::tangent1 + i]);
    applyImpulse(a, b, rA, rB, mulAdd(t[0], total[0] - old[0], t[1] * (total[1] - old[1])));
  }

  HWY_INLINE void beginNormals() {
    nA = a.turnedBack(n), nB = b.turnedBack(n);
    along = fusedDot(b.dp - a.dp, n);
  }

  HWY_INLINE void normalAt(std::size_t k) {
    const std::size_t p = point(k);
    const V zero = Zero(d), one = Set(d, 1.0f);
    const Vec3L<V> rA = load3(d, r, p + R::rAx), rB = load3(d, r, p + R::rBx);
    const V sep = Load(d, r[p + R::base]) + (along + (fusedDot(nB, rB) - fusedDot(nA, rA)));
    V bias = zero, ms = one, is = zero;
    if (pass.bias == core::ContactPass::kSoft) {
      bias = Max(biasRate * sep, Set(d, -pass.maxPush)), ms = massScale, is = impulseScale;
    } else if (pass.bias == core::ContactPass::kBaumgarte) {
      bias = Set(d, pass.baumgarte * pass.invH) * Min(zero, sep + Set(d, pass.slop));
    }
    const auto speculative = Gt(sep, zero);
    bias = IfThenElse(speculative, sep * Set(d, pass.invH), bias);
    ms = IfThenElse(speculative, one, ms);
    is = IfThenElse(speculative, zero, is);
    const V vn = relativeAlong(a, b, rA, rB, n);
    float* accumulated = r[p + R::normalImpulse];
    const V old = Load(d, accumulated);
    const V mass = Load(d, r[p + R::normalMass]);
    const V total = Max(NegMulAdd(mass * ms, vn + bias, NegMulAdd(is, old, old)), zero);
    const V impulse = total - old;
    Store(total, d, accumulated);
    // Only restitution reads these (where a lane's restitution is not 0): without it, 8 of the
    // 90 lines a vector reads and 8 of the 20 it writes are left alone.
    if (bounces) {
      float* maxNormal = r[p + R::maxNormal];
      Store(Max(Load(d, maxNormal), impulse), d, maxNormal);
      float* relative = r[p + R::relative];
      Store(IfThenElse(Gt(total, zero), Min(Load(d, relative), vn), Load(d, relative)), d,
            relative);
    }
    applyImpulse(a, b, rA, rB, n * impulse);
  }
};

// The points in turn, forward or backward, each step taken for every vector given before the
// next: the vectors share no moving body, so their steps are independent and their chains of
// dependent arithmetic (each point's impulse moves the bodies the next one reads) overlap.
template <class... Lanes>
HWY_INLINE void solveLanes(const core::ContactPass& pass, core::SolverBody* bodies,
                           Lanes&... lanes) {
  // Backward from the last point any lane has: the points past a lane's count are inert.
  const std::size_t m = std::max({lanes.points...});
  for (std::size_t j = 0; j < m; ++j) (lanes.frictionAt(pass.reverse ? m - 1 - j : j), ...);
  (lanes.beginNormals(), ...);
  for (std::size_t j = 0; j < m; ++j) (lanes.normalAt(pass.reverse ? m - 1 - j : j), ...);
  ((lanes.a.store(lanes.d, bodies), lanes.b.store(lanes.d, bodies)), ...);
}

template <class D>
void solveT(D d, const core::ContactRows& rows, core::SolverBody* bodies,
            const core::ContactPass& pass) {
  const std::size_t N = Lanes(d);
  for (std::size_t batch = 0; batch < rows.batches; ++batch) {
    std::size_t lane = rows.batchBegin[batch];
    const std::size_t end = rows.batchBegin[batch + 1];
    for (; lane + 2 * N <= end; lane += 2 * N) {  // two vectors of a batch at once
      SolveLanes<D> first(d, rows, bodies, lane, pass), second(d, rows, bodies, lane + N, pass);
      solveLanes(pass, bodies, first, second);
    }
    if (lane < end) {
      SolveLanes<D> last(d, rows, bodies, lane, pass);
      solveLanes(pass, bodies, last);
    }
  }
}

template <class D>
void restitutionT(D d, const core::ContactRows& rows, core::SolverBody* bodies, float threshold) {
  using V = LaneOf<D>;
  using R = core::ContactRows;
  const V zero = Zero(d), minusThreshold = Set(d, -threshold);
  forEachVector(d, rows, [&](std::size_t lane) {
    const RowLanes r{rows.lanes(lane)};
    const V e = Load(d, r[R::restitution]);
    if (AllTrue(d, Eq(e, zero))) return;
    LaneBodies<D> a(d, bodies, rows, lane, false), b(d, bodies, rows, lane, true);
    const Vec3L<V> n = load3(d, r, R::nx);
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t p = R::kPoint + k * R::kPointFields;
      const V relative = Load(d, r[p + R::relative]);
      const auto active = And(Not(Eq(e, zero)), And(Le(relative, minusThreshold),
                                                    Not(Eq(Load(d, r[p + R::maxNormal]), zero))));
      if (AllFalse(d, active)) continue;
      const Vec3L<V> rA = load3(d, r, p + R::rAx), rB = load3(d, r, p + R::rBx);
      const V vn = relativeAlong(a, b, rA, rB, n);
      float* accumulated = r[p + R::normalImpulse];
      const V old = Load(d, accumulated);
      const V total = IfThenElse(
          active, Max(NegMulAdd(Load(d, r[p + R::normalMass]), MulAdd(e, relative, vn), old), zero),
          old);
      Store(total, d, accumulated);
      applyImpulse(a, b, rA, rB, n * (total - old));
    }
    a.store(d, bodies);
    b.store(d, bodies);
  });
}

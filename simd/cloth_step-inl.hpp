// The cloth step (cloth.hpp) over a cloth's slots, written once for a lane type: a Highway vector
// (simd/cloth.cpp, the kernel) or one float (simd/cloth_autovec.cpp, the plain-loop baseline). The
// arithmetic is the scalar reference's (src/reference/cloth/step-inl.hpp) operation for
// operation, so every path ends bit for bit where the float reference does.
//
// The springs come in two layouts. A network's batch is read spring by spring with scalar indexed
// loads into lanes (AVX-512 gathers lose to them on the machines measured, DESIGN.md) and written
// back the same way; no two springs of a batch share a particle. A grid's family is a shifted copy
// of the grid: the springs of one colour of family x+1 pair neighbouring lanes of one contiguous
// load (lanes 2m, 2m+1; of x+2, lanes 4m + {0,1} with 4m + {2,3}), and each lane computes its own
// end of its spring, the partner's coordinates brought in by a shuffle; the other families pair a
// row with the next row(s), both contiguous loads. So a grid needs no gather and no scatter.
// Included inside each target's namespace (no include guard, by design), after
// simd/particle_lanes-inl.hpp.

// ---- lanes --------------------------------------------------------------------------------------
inline void storeWhere(ScalarLane, bool m, float v, float* p) {
  if (m) *p = v;
}
// AVX-512's masked store; elsewhere a blend of the memory's values (AVX2's masked store is
// microcoded on AMD's cores, many times slower), which writes the unchanged lanes back.
template <class D, class M, class V>
HWY_INLINE void storeWhere(D d, M m, V v, float* p) {
#if HWY_TARGET <= HWY_AVX3
  hn::BlendedStore(v, m, d, p);
#else
  StoreU(IfThenElse(m, v, LoadU(d, p)), d, p);
#endif
}
template <class D>
HWY_INLINE auto load3(D d, float* const* s, std::size_t field, std::size_t i) {
  return Vec3L<LaneOf<D>>{
      {LoadU(d, s[field] + i), LoadU(d, s[field + 1] + i), LoadU(d, s[field + 2] + i)}};
}
template <class D, class M, class V>
HWY_INLINE void store3(D d, M m, const Vec3L<V>& v, float* const* s, std::size_t field,
                       std::size_t i) {
  for (int k = 0; k < 3; ++k) storeWhere(d, m, v[k], s[field + k] + i);
}
// std::min and std::max as the reference calls them: (b < a) ? b : a and (a < b) ? b : a.
template <class V>
HWY_INLINE V stdMin(V a, V b) {
  return IfThenElse(Lt(b, a), b, a);
}
template <class V>
HWY_INLINE V stdMax(V a, V b) {
  return IfThenElse(Lt(a, b), b, a);
}

// Runs f(begin, end) over [first, end) in parts of `part` elements, shared among the threads of
// an enclosing parallel region (alone outside one), each part whole by one thread: the work of a
// pass touches no element of another part, so the result does not depend on the split.
template <class F>
HWY_INLINE void forParts(std::size_t first, std::size_t end, std::size_t part, F&& f) {
  const auto parts = std::ptrdiff_t((end - first + part - 1) / part);
#pragma omp for schedule(static)
  for (std::ptrdiff_t k = 0; k < parts; ++k)
    f(first + std::size_t(k) * part, std::min(end, first + std::size_t(k + 1) * part));
}
constexpr std::size_t kPart = 2048;  // slots of a part: a multiple of every lane count and of 4

template <class D>
struct ClothLanes {
  using V = LaneOf<D>;
  V h, invH, invH2, keep, margin, friction, zero, one, penalty, zone;
  Vec3L<V> g;
  bool shared = false;  // the passes' parts are shared among threads
  ClothLanes(D d, const core::ClothStepParams& p)
      : h(Set(d, p.h)),
        invH(Set(d, p.invH)),
        invH2(Set(d, p.invH2)),
        keep(Set(d, p.keep)),
        margin(Set(d, p.margin)),
        friction(Set(d, p.friction)),
        zero(Zero(d)),
        one(Set(d, 1.0f)),
        penalty(Set(d, p.penalty)),
        zone(Set(d, p.zone)),
        g(splat3(d, p.gravity)) {}
};

// A spring's constants in lanes: alpha = compliance / h^2, gamma = compliance damping / h.
template <class V>
struct SpringLanes {
  V rest, alpha, gamma, gamma1, stiffness, damping;
};

// ---- one spring, both models --------------------------------------------------------------------
// XPBD: the multiplier's scale k of the correction d (w k) of the end at x, d = partner - x;
// `ok` false where the reference skips the spring.
template <bool kDamped, class V, class M>
HWY_INLINE V xpbdScale(const Vec3L<V>& d, const Vec3L<V>& dv, V wsum, const SpringLanes<V>& s,
                       V zero, M& ok) {
  const V l = Sqrt(dot(d, d));
  V num = l - s.rest;
  V den;
  if constexpr (kDamped) {
    num = num + s.gamma * dot(d, dv) / l;
    den = (s.gamma1 * wsum + s.alpha) * l;
  } else {
    den = (wsum + s.alpha) * l;
  }
  ok = And(ok, And(Gt(l, zero), Gt(den, zero)));
  return num / den;
}

// Mass-spring: the force on the end at x is d k, d = partner - x, dvel = its velocity relative.
template <bool kDamped, class V, class M>
HWY_INLINE V forceScale(const Vec3L<V>& d, const Vec3L<V>& dvel, const SpringLanes<V>& s, V zero,
                        M& ok) {
  const V l = Sqrt(dot(d, d));
  V f = s.stiffness * (l - s.rest);
  if constexpr (kDamped) f = f + s.damping * dot(d, dvel) / l;
  ok = And(ok, Gt(l, zero));
  return f / l;
}

// The springs of a lane each, read and written through `ends` (RunEnds: a grid's row pair;
// IndexedEnds: a network's batch), both ends of each updated.
template <bool kXpbd, bool kDamped, class D, class Ends>
HWY_INLINE void solvePairs(D, const Ends& ends, const SpringLanes<LaneOf<D>>& s, MaskOf<D> ok,
                           const ClothLanes<D>& c) {
  using V = LaneOf<D>;
  using S = core::ClothStreams;
  const Vec3L<V> xa = ends.a3(S::x), xb = ends.b3(S::x);
  const Vec3L<V> dd = xb - xa;
  const V wa = ends.a(S::w), wb = ends.b(S::w);
  if constexpr (kXpbd) {
    Vec3L<V> dv{};
    if constexpr (kDamped) dv = (xb - ends.b3(S::px)) - (xa - ends.a3(S::px));
    const V k = xpbdScale<kDamped>(dd, dv, wa + wb, s, c.zero, ok);
    ends.putB3(S::x, And(ok, Gt(wb, c.zero)), xb + Neg(dd) * (wb * k));
    ends.putA3(S::x, And(ok, Gt(wa, c.zero)), xa + dd * (wa * k));
  } else {
    Vec3L<V> dvel{};
    if constexpr (kDamped) dvel = ends.b3(S::vx) - ends.a3(S::vx);
    const V k = forceScale<kDamped>(dd, dvel, s, c.zero, ok);
    ends.putB3(S::fx, ok, ends.b3(S::fx) + Neg(dd) * k);
    ends.putA3(S::fx, ok, ends.a3(S::fx) + dd * k);
  }
}

// ---- predict and finish, slot by slot -----------------------------------------------------------
template <bool kXpbd, class D>
void predict(D d, const core::ClothView<float>& v, const ClothLanes<D>& c) {
  using S = core::ClothStreams;
  forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; i += Lanes(d)) {
      const auto w = LoadU(d, v.s[S::w] + i);
      const auto live = Gt(w, c.zero);
      if (AllFalse(d, live)) continue;
      auto vel = load3(d, v.s, S::vx, i);
      if constexpr (kXpbd)
        vel = (vel + c.g * c.h) * c.keep;
      else
        vel = (vel + (c.g + load3(d, v.s, S::fx, i) * w) * c.h) * c.keep;
      const auto x = load3(d, v.s, S::x, i);
      store3(d, live, vel, v.s, S::vx, i);
      store3(d, live, x, v.s, S::px, i);
      store3(d, live, x + vel * c.h, v.s, S::x, i);
    }
  });
}

// A contact along n, `depth` deep, where `hit`: pushed out, then friction (the reference's
// collide()).
template <class D, class V, class M>
HWY_INLINE void contact(const ClothLanes<D>& c, M hit, const Vec3L<V>& n, V depth,
                        const Vec3L<V>& p, Vec3L<V>& x) {
  const Vec3L<V> pushed = x + n * depth;
  const Vec3L<V> moved = pushed - p;
  const Vec3L<V> tangent = moved - n * dot(n, moved);
  const V tl = Sqrt(dot(tangent, tangent)), hold = c.friction * depth;
  const V scale = IfThenElse(Le(tl, hold), c.one, hold / tl);
  x = IfThenElse(hit, IfThenElse(Gt(tl, c.zero), pushed - tangent * scale, pushed), x);
}

// A mesh row's contacts: its entries asked of the library lane by lane (the reference's query).
template <class D, class V, class M>
void meshContacts(D d, std::uint32_t index, const core::ObstacleQueries& q, const ClothLanes<D>& c,
                  M live, const Vec3L<V>& p, Vec3L<V>& x) {
  const Vec3L<V> dir = x - p;
  const V len = Sqrt(dot(dir, dir));
  const auto moving = And(live, Gt(len, c.zero));
  if (AllFalse(d, moving)) return;
  const Vec3L<V> ext = dir * ((len + c.margin) / len);
  constexpr std::size_t kMax = 16;
  const std::size_t L = Lanes(d);
  alignas(64) float from[3 * kMax], along[3 * kMax], lanes[kMax], s[kMax], normal[3 * kMax],
      hit[kMax];
  for (int k = 0; k < 3; ++k) Store(p[k], d, from + k * L), Store(ext[k], d, along + k * L);
  Store(IfThenElse(moving, c.one, c.zero), d, lanes);
  q.meshEntry(q.context, index, L, from, along, lanes, s, normal, hit);
  for (std::size_t l = 0; l < L; ++l)
    if (lanes[l] == 0 || hit[l] == 0)
      s[l] = 0, hit[l] = 0, normal[l] = normal[L + l] = normal[2 * L + l] = 0;
  const Vec3L<V> n{{Load(d, normal), Load(d, normal + L), Load(d, normal + 2 * L)}};
  const V depth = c.margin - dot(n, x - (p + ext * Load(d, s)));
  const auto met = And(And(moving, Gt(Load(d, hit), c.zero)), Gt(depth, c.zero));
  if (!AllFalse(d, met)) contact(c, met, n, depth, p, x);
}

template <class D, class V, class M>
HWY_INLINE void collide(D d, const core::ObstacleRow& row, std::uint32_t index,
                        const core::ObstacleQueries* queries, const ClothLanes<D>& c, M live,
                        const Vec3L<V>& p, Vec3L<V>& x) {
  const auto at = [&](int k) { return splat3(d, row.v + k); };
  switch (row.kind) {
    case core::ObstacleRow::kPlane: {
      const Vec3L<V> n = at(0);
      const V s = dot(n, x) + Set(d, row.v[3]);
      const auto hit = And(live, Lt(s, c.margin));
      if (!AllFalse(d, hit)) contact(c, hit, n, c.margin - s, p, x);
      return;
    }
    case core::ObstacleRow::kSphere: {
      const Vec3L<V> e = x - at(0);
      const V r = Set(d, row.v[3]) + c.margin, l2 = dot(e, e);
      auto hit = And(live, Lt(l2, r * r));
      if (AllFalse(d, hit)) return;
      const V l = Sqrt(l2);
      hit = And(hit, Gt(l, c.zero));
      contact(c, hit, e / l, r - l, p, x);
      return;
    }
    case core::ObstacleRow::kObb: {
      const Vec3L<V> centre = at(0), axes[3] = {at(6), at(9), at(12)};
      const Vec3L<V> xc = x - centre, pc = p - centre;
      const V minusOne = Set(d, -1.0f), two = Set(d, 2.0f), three = Set(d, 3.0f);
      V enter = minusOne, exit = two, least = Set(d, std::numeric_limits<float>::infinity());
      V face = minusOne, nearest = c.zero;
      auto outside = Lt(c.one, c.zero);  // all false
      V q[3], q0[3], e[3];
      for (int k = 0; k < 3; ++k) {
        e[k] = Set(d, row.v[3 + k]) + c.margin;
        q[k] = dot(axes[k], xc), q0[k] = dot(axes[k], pc);
        const V dq = q[k] - q0[k];
        const auto in0 = Lt(Abs(q0[k]), e[k]);
        outside = Or(outside, Not(in0));
        const V t0 = (Neg(e[k]) - q0[k]) / dq, t1 = (e[k] - q0[k]) / dq;
        const auto still = Eq(dq, c.zero);
        const V lo = IfThenElse(still, IfThenElse(in0, minusOne, three), stdMin(t0, t1));
        const V hi = IfThenElse(still, two, stdMax(t0, t1));
        const V kk = Set(d, float(k));
        const auto later = Gt(lo, enter);
        enter = IfThenElse(later, lo, enter), face = IfThenElse(later, kk, face);
        exit = stdMin(exit, hi);
        const V pen = e[k] - Abs(q0[k]);
        const auto less = Lt(pen, least);
        least = IfThenElse(less, pen, least), nearest = IfThenElse(less, kk, nearest);
      }
      const V axis = IfThenElse(outside, face, nearest);
      Vec3L<V> n = axes[2];
      V ek = e[2], qk = q[2], q0k = q0[2];
      for (int k = 1; k >= 0; --k) {
        const auto is = Eq(axis, Set(d, float(k)));
        n = IfThenElse(is, axes[k], n);
        ek = IfThenElse(is, e[k], ek), qk = IfThenElse(is, q[k], qk),
        q0k = IfThenElse(is, q0[k], q0k);
      }
      const V side = IfThenElse(Lt(q0k, c.zero), minusOne, c.one);
      const V depth = ek - side * qk;
      const auto crossed = And(And(Le(enter, exit), Ge(enter, c.zero)), Le(enter, c.one));
      const auto hit = And(live, Or(And(outside, crossed), And(Not(outside), Gt(depth, c.zero))));
      if (!AllFalse(d, hit)) contact(c, hit, n * side, depth, p, x);
      return;
    }
    case core::ObstacleRow::kMesh:
      if (queries) meshContacts(d, index, *queries, c, live, p, x);
      return;
    default:
      return;
  }
}

// Penalty springs (the reference's penaltyForce): forces along the normals of the planes,
// spheres and boxes a particle lies within the zone of.
template <class D>
void penaltyForces(D d, const core::ClothView<float>& v, const core::ObstacleRow* rows,
                   std::size_t nRows, const ClothLanes<D>& c) {
  using S = core::ClothStreams;
  using V = LaneOf<D>;
  forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; i += Lanes(d)) {
      const auto live = Gt(LoadU(d, v.s[S::w] + i), c.zero);
      if (AllFalse(d, live)) continue;
      const Vec3L<V> x = load3(d, v.s, S::x, i);
      Vec3L<V> f = load3(d, v.s, S::fx, i);
      for (std::size_t r = 0; r < nRows; ++r) {
        const core::ObstacleRow& row = rows[r];
        const auto at = [&](int k) { return splat3(d, row.v + k); };
        Vec3L<V> n;
        V depth;
        auto hit = live;
        if (row.kind == core::ObstacleRow::kPlane) {
          n = at(0);
          depth = c.zone - (dot(n, x) + Set(d, row.v[3]));
        } else if (row.kind == core::ObstacleRow::kSphere) {
          const Vec3L<V> e = x - at(0);
          const V l = Sqrt(dot(e, e));
          depth = (Set(d, row.v[3]) + c.zone) - l;
          hit = And(hit, Gt(l, c.zero));
          n = e / l;
        } else if (row.kind == core::ObstacleRow::kObb) {
          const Vec3L<V> centre = at(0), axes[3] = {at(6), at(9), at(12)};
          V least = Set(d, std::numeric_limits<float>::infinity()), q = c.zero;
          n = axes[0];
          for (int k = 0; k < 3; ++k) {
            const V qk = dot(axes[k], x - centre);
            const V pen = (Set(d, row.v[3 + k]) + c.zone) - Abs(qk);
            const auto less = Lt(pen, least);
            least = IfThenElse(less, pen, least), q = IfThenElse(less, qk, q);
            n = IfThenElse(less, axes[k], n);
          }
          n = n * IfThenElse(Lt(q, c.zero), Set(d, -1.0f), c.one);
          depth = least;
        } else {
          continue;  // meshes: the path test only
        }
        hit = And(hit, Gt(depth, c.zero));
        if (AllFalse(d, hit)) continue;
        const Vec3L<V> zero3{{c.zero, c.zero, c.zero}};
        f = f + IfThenElse(hit, n * (c.penalty * depth), zero3);
      }
      store3(d, live, f, v.s, S::fx, i);
    }
  });
}

// Tethers, obstacles and the velocity changed by what moved the particle off its prediction.
template <class D>
void finish(D d, const core::ClothView<float>& v, const core::Tethers& tethers,
            const core::ObstacleRow* rows, std::size_t nRows, const core::ObstacleQueries* queries,
            const ClothLanes<D>& c) {
  using S = core::ClothStreams;
  using V = LaneOf<D>;
  forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; i += Lanes(d)) {
      const auto live = Gt(LoadU(d, v.s[S::w] + i), c.zero);
      if (AllFalse(d, live)) continue;
      const Vec3L<V> p = load3(d, v.s, S::px, i), vel = load3(d, v.s, S::vx, i);
      const Vec3L<V> predicted = p + vel * c.h;
      Vec3L<V> x = load3(d, v.s, S::x, i);
      if (tethers.anchor) {
        const V len = LoadU(d, tethers.length + i);
        const Vec3L<V> anchor = load3(d, v.s, S::ax, i);
        const Vec3L<V> e = x - anchor;
        const V l2 = dot(e, e);
        const auto over = And(Ge(len, c.zero), Gt(l2, len * len));
        if (!AllFalse(d, over)) x = IfThenElse(over, anchor + e * (len / Sqrt(l2)), x);
      }
      for (std::size_t r = 0; r < nRows; ++r)
        collide(d, rows[r], std::uint32_t(r), queries, c, live, p, x);
      store3(d, live, x, v.s, S::x, i);
      store3(d, live, vel + (x - predicted) * c.invH, v.s, S::vx, i);
    }
  });
}

// ---- the springs --------------------------------------------------------------------------------
inline std::uint64_t maskBits(ScalarLane, bool m) { return m; }
template <class D, class M>
HWY_INLINE std::uint64_t maskBits(D d, M m) {
  std::uint8_t bytes[8] = {};
  hn::StoreMaskBits(d, m, bytes);
  std::uint64_t bits = 0;
  for (int k = 0; k < 8; ++k) bits |= std::uint64_t(bytes[k]) << (8 * k);
  return bits;
}

// Whether storeWhere writes the lanes of its mask only (AVX-512's masked stores).
constexpr bool kMaskedStores = HWY_TARGET <= HWY_AVX3;

// Writes the lanes of m only (storeWhere may write the others back unchanged).
inline void storeOnly(ScalarLane, bool m, float v, float* p) { storeWhere(ScalarLane(), m, v, p); }
template <class D, class M, class V>
HWY_INLINE void storeOnly(D d, M m, V v, float* p) {
#if HWY_TARGET <= HWY_AVX3
  hn::BlendedStore(v, m, d, p);
#else
  alignas(64) float lanes[16] = {};
  Store(v, d, lanes);
  const std::uint64_t bits = maskBits(d, m);
  for (std::size_t l = 0; l < Lanes(d); ++l)
    if (bits >> l & 1) p[l] = lanes[l];
#endif
}

// Ends as contiguous runs from slots ia and ib (a grid's row pair, or one lane).
template <class D>
struct RunEnds {
  using V = LaneOf<D>;
  D d;
  float* const* s;
  std::size_t ia, ib;
  bool strict;  // b's run writes no lane outside the mask (it spills into another pair's row)
  V a(std::size_t f) const { return LoadU(d, s[f] + ia); }
  V b(std::size_t f) const { return LoadU(d, s[f] + ib); }
  Vec3L<V> a3(std::size_t f) const { return load3(d, s, f, ia); }
  Vec3L<V> b3(std::size_t f) const { return load3(d, s, f, ib); }
  template <class M>
  void putA3(std::size_t f, M m, const Vec3L<V>& v) const {
    store3(d, m, v, s, f, ia);
  }
  template <class M>
  void putB3(std::size_t f, M m, const Vec3L<V>& v) const {
    if (strict)
      for (int k = 0; k < 3; ++k) storeOnly(d, m, v[k], s[f + k] + ib);
    else
      store3(d, m, v, s, f, ib);
  }
};

// n lanes of field[idx[l]], read one by one (faster than AVX2's and AVX-512's gathers here).
inline float gatherLanes(ScalarLane, const float* field, const std::uint32_t* idx, std::size_t) {
  return field[idx[0]];
}
template <class D>
HWY_INLINE LaneOf<D> gatherLanes(D d, const float* field, const std::uint32_t* idx, std::size_t n) {
  alignas(64) float lanes[16] = {};
  for (std::size_t l = 0; l < n; ++l) lanes[l] = field[idx[l]];
  return Load(d, lanes);
}

// Ends read and written lane by lane through slot indices (a network's batch): `n` live lanes.
template <class D>
struct IndexedEnds {
  using V = LaneOf<D>;
  static constexpr std::size_t kMax = 16;  // the widest lane count
  D d;
  float* const* s;
  const std::uint32_t *ia, *ib;
  std::size_t n;
  template <class M>
  static void scatter(D d, M m, V v, float* field, const std::uint32_t* idx, std::size_t n) {
    alignas(64) float lanes[kMax] = {};
    Store(v, d, lanes);
    const std::uint64_t bits = maskBits(d, m);
    for (std::size_t l = 0; l < n; ++l)
      if (bits >> l & 1) field[idx[l]] = lanes[l];
  }
  V a(std::size_t f) const { return gatherLanes(d, s[f], ia, n); }
  V b(std::size_t f) const { return gatherLanes(d, s[f], ib, n); }
  Vec3L<V> a3(std::size_t f) const { return {{a(f), a(f + 1), a(f + 2)}}; }
  Vec3L<V> b3(std::size_t f) const { return {{b(f), b(f + 1), b(f + 2)}}; }
  template <class M>
  void putA3(std::size_t f, M m, const Vec3L<V>& v) const {
    for (int k = 0; k < 3; ++k) scatter(d, m, v[k], s[f + k], ia, n);
  }
  template <class M>
  void putB3(std::size_t f, M m, const Vec3L<V>& v) const {
    for (int k = 0; k < 3; ++k) scatter(d, m, v[k], s[f + k], ib, n);
  }
};

// Whether the lanes are a vector of at least four (shuffles, transposes), not one float.
template <class D>
inline constexpr bool kShuffles = !std::is_same_v<D, ScalarLane> && HWY_TARGET != HWY_SCALAR;

#if HWY_TARGET != HWY_SCALAR  // vectors of four lanes at least
// IndexedEnds whose positions and inverse masses come from and go to the slots' (x, y, z, w)
// quads (ClothStepInput::quads): a spring's end is one 16-byte load, the lanes transposed by
// LoadInterleaved4 (Box2D v3 gathers its bodies' states so), not four scalar loads.
template <class D>
struct QuadEnds : IndexedEnds<D> {
  using V = LaneOf<D>;
  using Base = IndexedEnds<D>;
  float* quads;
  Vec3L<V> xa, xb;
  V wa, wb;
  QuadEnds(const Base& base, float* q) : Base(base), quads(q) {
    load(this->ia, xa, wa);
    load(this->ib, xb, wb);
  }
  // The quads of lanes first, first + 4, first + 8, ... as the blocks of one vector.
  template <class DB>
  static auto blocks(DB db, const float* quads, const std::uint32_t* idx) {
    if constexpr (hn::MaxLanes(DB()) == 4) {
      return LoadU(db, quads + 4 * std::size_t(idx[0]));
    } else {
      const hn::Half<DB> dh;
      return hn::Combine(db, blocks(dh, quads, idx + hn::MaxLanes(dh) / 4), blocks(dh, quads, idx));
    }
  }
  // Built in registers (a stack copy would stall on store forwarding), then transposed block by
  // block: lane 4 b + p of x, y, z, w from block b of vector p. Lanes past n read slot idx[l]
  // (the index streams are padded with valid slots) and are never written.
  void load(const std::uint32_t* idx, Vec3L<V>& x, V& w) const {
    const D d = this->d;
    alignas(64) std::uint32_t order[Base::kMax];  // lane 4 b + p's slot at p L / 4 + b
    const std::size_t L = Lanes(d), B = L / 4;
    for (std::size_t l = 0; l < L; ++l) order[(l % 4) * B + l / 4] = idx[l];
    const V q0 = blocks(d, quads, order), q1 = blocks(d, quads, order + B);
    const V q2 = blocks(d, quads, order + 2 * B), q3 = blocks(d, quads, order + 3 * B);
    const V t0 = hn::InterleaveLower(d, q0, q1), t1 = hn::InterleaveLower(d, q2, q3);
    const V t2 = hn::InterleaveUpper(d, q0, q1), t3 = hn::InterleaveUpper(d, q2, q3);
    const hn::Repartition<double, D> d64;
    const auto lo = [&](V a, V b) {
      return hn::BitCast(d, hn::InterleaveLower(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)));
    };
    const auto hi = [&](V a, V b) {
      return hn::BitCast(d, hn::InterleaveUpper(d64, hn::BitCast(d64, a), hn::BitCast(d64, b)));
    };
    x[0] = lo(t0, t1), x[1] = hi(t0, t1), x[2] = lo(t2, t3), w = hi(t2, t3);
  }
  template <class M>
  void store(const std::uint32_t* idx, M m, const Vec3L<V>& x, V w) const {
    alignas(64) float lanes[4 * Base::kMax] = {};
    hn::StoreInterleaved4(x[0], x[1], x[2], w, this->d, lanes);
    constexpr std::size_t kL = hn::MaxLanes(D());
    if (hn::AllTrue(this->d, m)) {  // the common case, unrolled
      for (std::size_t l = 0; l < kL; ++l)
        std::memcpy(quads + 4 * std::size_t(idx[l]), lanes + 4 * l, 16);
      return;
    }
    const std::uint64_t bits = maskBits(this->d, m);
    for (std::size_t l = 0; l < this->n; ++l)
      if (bits >> l & 1) std::memcpy(quads + 4 * std::size_t(idx[l]), lanes + 4 * l, 16);
  }
  V a(std::size_t f) const { return f == core::ClothStreams::w ? wa : Base::a(f); }
  V b(std::size_t f) const { return f == core::ClothStreams::w ? wb : Base::b(f); }
  Vec3L<V> a3(std::size_t f) const { return f == core::ClothStreams::x ? xa : Base::a3(f); }
  Vec3L<V> b3(std::size_t f) const { return f == core::ClothStreams::x ? xb : Base::b3(f); }
  template <class M>
  void putA3(std::size_t f, M m, const Vec3L<V>& v) const {
    if (f == core::ClothStreams::x)
      store(this->ia, m, v, wa);
    else
      Base::putA3(f, m, v);
  }
  template <class M>
  void putB3(std::size_t f, M m, const Vec3L<V>& v) const {
    if (f == core::ClothStreams::x)
      store(this->ib, m, v, wb);
    else
      Base::putB3(f, m, v);
  }
};

// The slots' positions and inverse masses as (x, y, z, w) quads, and back.
template <class D>
void toQuads(D d, const core::ClothView<float>& v, float* quads) {
  using S = core::ClothStreams;
  forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; i += Lanes(d))
      hn::StoreInterleaved4(LoadU(d, v.s[S::x] + i), LoadU(d, v.s[S::y] + i),
                            LoadU(d, v.s[S::z] + i), LoadU(d, v.s[S::w] + i), d, quads + 4 * i);
  });
}
template <class D>
void fromQuads(D d, const core::ClothView<float>& v, const float* quads) {
  using S = core::ClothStreams;
  forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; i += Lanes(d)) {
      LaneOf<D> x, y, z, w;
      hn::LoadInterleaved4(d, quads + 4 * i, x, y, z, w);
      StoreU(x, d, v.s[S::x] + i), StoreU(y, d, v.s[S::y] + i), StoreU(z, d, v.s[S::z] + i);
    }
  });
}

#endif

template <class D>
HWY_INLINE SpringLanes<LaneOf<D>> springLanes(D d, float rest, float compliance, float stiffness,
                                              float damping, const core::ClothStepParams& p) {
  const float gamma = compliance * damping * p.invH;  // the reference's order
  return {Set(d, rest),      Set(d, compliance * p.invH2),
          Set(d, gamma),     Set(d, 1 + gamma),
          Set(d, stiffness), Set(d, damping)};
}

// One batch of a network, springs [begin, end).
template <bool kXpbd, bool kDamped, class D>
void networkBatch(D d, const core::ClothView<float>& v, const core::SpringNetwork& net,
                  std::size_t begin, std::size_t end, float* quads, const ClothLanes<D>& c,
                  const core::ClothStepParams& p) {
  const std::size_t L = Lanes(d);
  forParts(begin, end, kPart, [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; k += L) {
      const std::size_t n = std::min(L, to - k);
      const IndexedEnds<D> indexed{d, v.s, net.a + k, net.b + k, n};
      SpringLanes<LaneOf<D>> s;
      s.rest = LoadU(d, net.rest + k);
      s.alpha = LoadU(d, net.compliance + k) * Set(d, p.invH2);
      s.gamma = LoadU(d, net.compliance + k) * LoadU(d, net.damping + k) * Set(d, p.invH);
      s.gamma1 = c.one + s.gamma;
      s.stiffness = LoadU(d, net.stiffness + k);
      s.damping = LoadU(d, net.damping + k);
#if HWY_TARGET == HWY_SCALAR
      (void)quads;
#else
      if constexpr (!kShuffles<D>) (void)quads;
      if constexpr (kShuffles<D>)
        if (quads) {
          solvePairs<kXpbd, kDamped>(d, QuadEnds<D>(indexed, quads), s, FirstN(d, n), c);
          continue;
        }
#endif
      solvePairs<kXpbd, kDamped>(d, indexed, s, FirstN(d, n), c);
    }
  });
}

// A grid's x+1 or x+2 family, one colour, by shuffles: each lane its own end of its spring.
template <bool kXpbd, bool kDamped, class D, class Partner, class Dup>
HWY_INLINE void solveLanes(D d, float* const* s, std::size_t i, const float* rest,
                           SpringLanes<LaneOf<D>> sl, const Partner& partner, const Dup& dup,
                           const ClothLanes<D>& c) {
  using S = core::ClothStreams;
  using V = LaneOf<D>;
  sl.rest = dup(LoadU(d, rest + i));
  auto ok = Ge(sl.rest, c.zero);
  if (AllFalse(d, ok)) return;
  const auto other = [&](const Vec3L<V>& x) {
    return Vec3L<V>{{partner(x[0]), partner(x[1]), partner(x[2])}};
  };
  const Vec3L<V> x = load3(d, s, S::x, i), dd = other(x) - x;
  const V w = LoadU(d, s[S::w] + i);
  if constexpr (kXpbd) {
    Vec3L<V> dv{};
    if constexpr (kDamped) {
      const Vec3L<V> p = load3(d, s, S::px, i);
      dv = (other(x) - other(p)) - (x - p);
    }
    const V k = xpbdScale<kDamped>(dd, dv, w + partner(w), sl, c.zero, ok);
    store3(d, And(ok, Gt(w, c.zero)), x + dd * (w * k), s, S::x, i);
  } else {
    Vec3L<V> dvel{};
    if constexpr (kDamped) {
      const Vec3L<V> vel = load3(d, s, S::vx, i);
      dvel = other(vel) - vel;
    }
    const V k = forceScale<kDamped>(dd, dvel, sl, c.zero, ok);
    store3(d, ok, load3(d, s, S::fx, i) + dd * k, s, S::fx, i);
  }
}

// Family x+1 (`next`: neighbouring lanes) or x+2 (lanes two apart in each block of four).
template <bool kXpbd, bool kDamped, class D>
HWY_INLINE void alongByShuffles(D d, float* const* s, std::size_t i, const float* rest,
                                const SpringLanes<LaneOf<D>>& sl, bool next,
                                const ClothLanes<D>& c) {
#if HWY_TARGET != HWY_SCALAR
  if (next) {
    solveLanes<kXpbd, kDamped>(
        d, s, i, rest, sl, [](auto x) { return hn::Shuffle2301(x); },
        [](auto r) { return hn::DupEven(r); }, c);
  } else {
    solveLanes<kXpbd, kDamped>(
        d, s, i, rest, sl, [](auto x) { return hn::Shuffle1032(x); },
        [d](auto r) {  // the rests of lanes 0, 1 of each block of four to lanes 2, 3
          const hn::Repartition<std::uint64_t, D> d64;
          const auto r64 = hn::BitCast(d64, r);
          return hn::BitCast(d, hn::InterleaveLower(d64, r64, r64));
        },
        c);
  }
#else
  (void)d, (void)s, (void)i, (void)rest, (void)sl, (void)next, (void)c;
#endif
}

template <bool kXpbd, bool kDamped, class D>
void gridFamily(D d, const core::ClothView<float>& v, const core::SpringGrid& g, std::uint32_t f,
                const ClothLanes<D>& c, const core::ClothStepParams& p) {
  using G = core::SpringGrid;
  const std::size_t L = Lanes(d);
  const std::uint32_t kind = G::kKind[f];
  SpringLanes<LaneOf<D>> sl =
      springLanes(d, 0, g.compliance[kind], g.stiffness[kind], g.damping[kind], p);
  const float* rest = g.rest[f];
  const std::size_t o = std::size_t(g.offset(f));
  const auto run = [&](std::size_t ia, std::size_t n, bool strict) {
    SpringLanes<LaneOf<D>> s = sl;
    s.rest = LoadU(d, rest + ia);
    const auto ok = And(FirstN(d, n), Ge(s.rest, c.zero));
    if (!AllFalse(d, ok))
      solvePairs<kXpbd, kDamped>(d, RunEnds<D>{d, v.s, ia, ia + o, strict}, s, ok, c);
  };
  const bool along = f == G::kX || f == G::kBendX;  // pairs within a row
  const std::size_t span = f == G::kBendX || f == G::kBendZ ? 2 : 1;
  for (std::size_t colour = 0; colour < 2; ++colour) {
    if (along) {
      const std::size_t first = colour * span;
      forParts(first, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
        if constexpr (kShuffles<D>) {
          for (std::size_t i = begin; i < end; i += L)
            alongByShuffles<kXpbd, kDamped>(d, v.s, i, rest, sl, f == G::kX, c);
        } else {
          for (std::size_t i = begin; i < end; i += 2 * span)
            for (std::size_t q = i; q < i + span; ++q) run(q, 1, false);
        }
      });
    } else {
      // This colour's rows: j with (j / span) % 2 == colour, a row a part. A shear family's run
      // spills one lane into a row beyond the pair (the next row of the colour, or the row's own
      // end): with threads, that vector writes no lane it does not change (a write-back of an
      // unchanged lane could undo another thread's update; alone, it rewrites what it read).
      const std::size_t rows = (g.rows + 2 * span - 1 - colour * span) / (2 * span) * span;
      forParts(0, rows, 1, [&](std::size_t k, std::size_t) {
        const std::size_t j = k / span * 2 * span + colour * span + k % span;
        if (j >= g.rows) return;
        const std::size_t row = j * g.stride, rowEnd = row + g.stride;
        for (std::size_t i = row; i < rowEnd; i += L)
          run(i, L,
              !kMaskedStores && c.shared &&
                  ((f == G::kShear && i + L >= rowEnd) || (f == G::kShearBack && i == row)));
      });
    }
  }
}

// ---- the step -----------------------------------------------------------------------------------
template <bool kXpbd, bool kDamped, class D>
void springs(D d, const core::ClothView<float>& v, const core::SpringNetwork& net,
             const core::SpringGrid* grid, float* quads, const ClothLanes<D>& c,
             const core::ClothStepParams& p) {
  if (grid) {
    for (std::uint32_t f = 0; f < core::SpringGrid::kFamilies; ++f)
      gridFamily<kXpbd, kDamped>(d, v, *grid, f, c, p);
    return;
  }
#if HWY_TARGET != HWY_SCALAR
  if constexpr (kShuffles<D>) {
    if (quads) toQuads(d, v, quads);
  } else {
    quads = nullptr;  // one lane: nothing to transpose
  }
#else
  quads = nullptr;
#endif
  for (std::size_t b = 0; b < net.batches; ++b)
    networkBatch<kXpbd, kDamped>(d, v, net, net.batchBegin[b], net.batchBegin[b + 1], quads, c, p);
#if HWY_TARGET != HWY_SCALAR
  if constexpr (kShuffles<D> && kXpbd)
    if (quads) fromQuads(d, v, quads);
#endif
}

template <bool kXpbd, bool kDamped, class D>
void substeps(D d, const core::ClothView<float>& v, const core::SpringNetwork& net,
              const core::SpringGrid* grid, const core::Tethers& t, const core::ObstacleRow* rows,
              std::size_t nRows, const core::ObstacleQueries* queries, float* quads,
              const core::ClothStepParams& p) {
  using S = core::ClothStreams;
  ClothLanes<D> c(d, p);
  c.shared = omp_get_num_threads() > 1;
  for (int sub = 0; sub < p.substeps; ++sub) {
    if constexpr (!kXpbd) {
      forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = 0; k < 3; ++k)
          std::fill(v.s[S::fx + k] + begin, v.s[S::fx + k] + end, 0.0f);
      });
      springs<kXpbd, kDamped>(d, v, net, grid, quads, c, p);
      if (p.penalty > 0) penaltyForces(d, v, rows, nRows, c);
    }
    predict<kXpbd>(d, v, c);
    if constexpr (kXpbd) springs<kXpbd, kDamped>(d, v, net, grid, quads, c, p);
    finish(d, v, t, rows, nRows, queries, c);
  }
}

// The step: the tethers' anchors copied (no substep moves a pinned particle), then the substeps,
// in one parallel region of `threads` threads whose passes share out their parts.
template <class D>
void stepClothT(D d, const core::ClothView<float>& v, const core::SpringNetwork& net,
                const core::SpringGrid* grid, const core::Tethers& t, const core::ObstacleRow* rows,
                std::size_t nRows, const core::ObstacleQueries* queries, float* quads,
                const core::ClothStepParams& p, int threads) {
  using S = core::ClothStreams;
  const bool xpbd = p.model == core::ClothStepParams::kXpbd;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    if (t.anchor)
      forParts(0, v.slots, kPart, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          if (t.length[i] >= 0)
            for (std::size_t k = 0; k < 3; ++k) v.s[S::ax + k][i] = v.s[S::x + k][t.anchor[i]];
      });
    if (xpbd && p.damped) substeps<true, true>(d, v, net, grid, t, rows, nRows, queries, quads, p);
    if (xpbd && !p.damped)
      substeps<true, false>(d, v, net, grid, t, rows, nRows, queries, quads, p);
    if (!xpbd && p.damped)
      substeps<false, true>(d, v, net, grid, t, rows, nRows, queries, quads, p);
    if (!xpbd && !p.damped)
      substeps<false, false>(d, v, net, grid, t, rows, nRows, queries, quads, p);
  }
}

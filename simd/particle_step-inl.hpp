// The particle step over the streams (simd/particles.cpp): the push-out, the bounce loop and the
// pass over a range, written once over a lane type. Included inside each target's namespace (no
// include guard, by design) by the kernel (particles.cpp) and its plain-loop baseline
// (particles_autovec.cpp), two files so that the two compile side by side.

#include "simd/particle_lanes-inl.hpp"
#include "simd/particle_rows-inl.hpp"

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

// The bodies' motion over a substep on their solver records (core/rigid_solve.hpp), written once
// over lanes: the arithmetic of src/reference/rigid/step-inl.hpp's integratePositions, a body a
// lane. Included inside each target's namespace (no include guard, by design), after
// simd/rigid_records-inl.hpp and simd/rigid_contacts-inl.hpp (cross).

template <class V>
struct QuatL {
  V x, y, z, w;
};

template <class D, class V = LaneOf<D>>
HWY_INLINE QuatL<V> product(const QuatL<V>& a, const QuatL<V>& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
      a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

// v rotated by the unit quaternion q (Eigen's: v + w uv + q x uv, uv = 2 q x v).
template <class D, class V = LaneOf<D>>
HWY_INLINE Vec3L<V> rotate(const QuatL<V>& q, const Vec3L<V>& v) {
  const Vec3L<V> axis{{q.x, q.y, q.z}};
  Vec3L<V> uv = cross<D>(axis, v);
  uv = uv + uv;
  return v + uv * q.w + cross<D>(axis, uv);
}

template <class V>
HWY_INLINE QuatL<V> conjugate(const QuatL<V>& q) {
  return {Neg(q.x), Neg(q.y), Neg(q.z), q.w};
}

// q turned by the rotation vector r, first order, normalised (the reference's turned).
template <class D, class V = LaneOf<D>>
HWY_INLINE QuatL<V> turned(D d, const QuatL<V>& q, const Vec3L<V>& r) {
  const QuatL<V> dq = product<D>(QuatL<V>{r[0], r[1], r[2], Zero(d)}, q);
  const V half = Set(d, 0.5f);
  const QuatL<V> out{q.x + dq.x * half, q.y + dq.y * half, q.z + dq.z * half, q.w + dq.w * half};
  const V norm = Sqrt(out.x * out.x + out.y * out.y + out.z * out.z + out.w * out.w);
  return {out.x / norm, out.y / norm, out.z / norm, out.w / norm};
}

// Moves records [0, frames.count) by their velocities over h: dp by v h, dq by the turn at the
// rate of its midpoint with the angular momentum kept, and w recomputed from it at the new
// orientation (bodies with mass); bodies without turn at w.
template <class D>
void integrateT(D d, core::SolverBody* bodies, const core::BodyFrames& frames, float h) {
  using V = LaneOf<D>;
  const std::size_t N = Lanes(d);
  const V hv = Set(d, h), halfH = Set(d, 0.5f * h), one = Set(d, 1.0f);
  std::uint32_t index[kRecordFloats];
  for (std::size_t first = 0; first < frames.count; first += N) {
    for (std::size_t i = 0; i < N; ++i) index[i] = std::uint32_t(first + i);
    V f[kRecordFloats];
    loadRecords(d, bodies, index, f);
    const Vec3L<V> v{{f[0], f[1], f[2]}};
    Vec3L<V> w{{f[3], f[4], f[5]}};
    const Vec3L<V> dp = Vec3L<V>{{f[6], f[7], f[8]}} + v * hv;
    const QuatL<V> dq{f[9], f[10], f[11], f[12]};
    const auto at = [&](const float* stream) { return Load(d, stream + first); };
    const QuatL<V> q0{at(frames.q[0]), at(frames.q[1]), at(frames.q[2]), at(frames.q[3])};
    const Vec3L<V> invI{
        {at(frames.invInertia[0]), at(frames.invInertia[1]), at(frames.invInertia[2])}};
    const auto dynamic = Gt(at(frames.dynamic), Zero(d));
    // With mass: L = I w kept through the turn, w = I^-1 L read at the midpoint and the end.
    const auto rate = [&](const QuatL<V>& q, const Vec3L<V>& L) {
      const Vec3L<V> local = rotate<D>(conjugate(q), L);
      return rotate<D>(q, Vec3L<V>{{invI[0] * local[0], invI[1] * local[1], invI[2] * local[2]}});
    };
    const QuatL<V> was = product<D>(dq, q0);
    const Vec3L<V> local = rotate<D>(conjugate(was), w);
    const Vec3L<V> L =
        rotate<D>(was, Vec3L<V>{{(one / invI[0]) * local[0], (one / invI[1]) * local[1],
                                 (one / invI[2]) * local[2]}});
    const Vec3L<V> mid = rate(turned(d, was, w * halfH), L);
    const QuatL<V> turnedDynamic = turned(d, dq, mid * hv);
    const Vec3L<V> wDynamic = rate(product<D>(turnedDynamic, q0), L);
    const QuatL<V> turnedFree = turned(d, dq, w * hv);
    w = IfThenElse(dynamic, wDynamic, w);
    const QuatL<V> out{IfThenElse(dynamic, turnedDynamic.x, turnedFree.x),
                       IfThenElse(dynamic, turnedDynamic.y, turnedFree.y),
                       IfThenElse(dynamic, turnedDynamic.z, turnedFree.z),
                       IfThenElse(dynamic, turnedDynamic.w, turnedFree.w)};
    const V g[kRecordFloats] = {v[0],  v[1],  v[2],  w[0],  w[1],  w[2],  dp[0], dp[1],
                                dp[2], out.x, out.y, out.z, out.w, f[13], f[14], f[15]};
    storeRecords(d, bodies, index, g, kRecordFloats);
  }
}

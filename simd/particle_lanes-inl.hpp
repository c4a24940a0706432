// The particle step's lanes (simd/particles.cpp): 3-vectors of lanes with Eigen's orders of
// operations, the step's constants broadcast, the integrators and the path's box for the culls,
// written once for a Highway vector or one float (core/scalar_lanes-inl.hpp). Included inside
// each target's namespace (no include guard, by design). Needs <hwy/highway.h>, <cmath>,
// <cstddef>, <limits> and simd/kernels.hpp.

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

// The scalar reference of a cloth step (cloth.hpp), written once on Eigen for float (the
// reference path) and double (the truth errors are measured against). The kernels
// (simd/cloth_*-inl.hpp) mirror it operation for operation: Eigen's x + (y + z) dot products, the
// same products and quotients in the same order, no contraction.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/cloth_step.hpp"
#include "simdphys/math.hpp"

namespace simdphys::reference {

template <class T>
struct ClothState {
  const core::ClothView<T>& v;
  Vec3<T> load(std::size_t field, std::size_t i) const {
    return {v.s[field][i], v.s[field + 1][i], v.s[field + 2][i]};
  }
  void store(std::size_t field, std::size_t i, const Vec3<T>& x) const {
    for (int k = 0; k < 3; ++k) v.s[field + k][i] = x[k];
  }
};

namespace F = core;  // ClothStreams' fields

// XPBD: one spring as a distance constraint. alpha = compliance / h^2, gamma = compliance
// damping / h (Macklin et al. 2016, eq. 26).
template <class T>
void projectSpring(const ClothState<T>& s, std::uint32_t a, std::uint32_t b, T rest, T alpha,
                   T gamma) {
  using S = core::ClothStreams;
  const Vec3<T> xa = s.load(S::x, a), xb = s.load(S::x, b);
  const T wa = s.v.s[S::w][a], wb = s.v.s[S::w][b];
  const Vec3<T> d = xb - xa;
  const T l = std::sqrt(d.dot(d));
  T num = l - rest;
  if (gamma != 0) {
    const Vec3<T> dv = (xb - s.load(S::px, b)) - (xa - s.load(S::px, a));
    num = num + gamma * d.dot(dv) / l;
  }
  const T den = ((T(1) + gamma) * (wa + wb) + alpha) * l;
  if (!(l > 0 && den > 0)) return;
  const T k = num / den;
  if (wa > 0) s.store(S::x, a, xa + d * (wa * k));  // a pinned end is never written
  if (wb > 0) s.store(S::x, b, xb + (-d) * (wb * k));
}

// Mass-spring: one Hooke spring's force, added to both ends.
template <class T>
void springForce(const ClothState<T>& s, std::uint32_t a, std::uint32_t b, T rest, T stiffness,
                 T damping) {
  using S = core::ClothStreams;
  const Vec3<T> d = s.load(S::x, b) - s.load(S::x, a);
  const T l = std::sqrt(d.dot(d));
  if (!(l > 0)) return;
  T f = stiffness * (l - rest);
  if (damping != 0) f = f + damping * d.dot(s.load(S::vx, b) - s.load(S::vx, a)) / l;
  const T k = f / l;
  s.store(S::fx, a, s.load(S::fx, a) + d * k);
  s.store(S::fx, b, s.load(S::fx, b) + (-d) * k);
}

// A penalty spring (the appendix's contact as a spring): the force penalty * depth along the
// normal of a plane, sphere or box (its nearest face) that x lies within `zone` of; else zero.
template <class T>
Vec3<T> penaltyForce(const core::ObstacleRow& row, const Vec3<T>& x, T zone, T penalty) {
  const auto at = [&](int k) { return Vec3<T>(T(row.v[k]), T(row.v[k + 1]), T(row.v[k + 2])); };
  switch (row.kind) {
    case core::ObstacleRow::kPlane: {
      const Vec3<T> n = at(0);
      const T depth = zone - (n.dot(x) + T(row.v[3]));
      return depth > 0 ? Vec3<T>(n * (penalty * depth)) : Vec3<T>::Zero();
    }
    case core::ObstacleRow::kSphere: {
      const Vec3<T> e = x - at(0);
      const T l = std::sqrt(e.dot(e)), depth = (T(row.v[3]) + zone) - l;
      return depth > 0 && l > 0 ? Vec3<T>((e / l) * (penalty * depth)) : Vec3<T>::Zero();
    }
    case core::ObstacleRow::kObb: {
      const Vec3<T> c = at(0), axes[3] = {at(6), at(9), at(12)};
      T least = std::numeric_limits<T>::infinity(), q = 0;
      int face = 0;
      for (int k = 0; k < 3; ++k) {
        const T qk = axes[k].dot(x - c), pen = (T(row.v[3 + k]) + zone) - std::abs(qk);
        if (pen < least) least = pen, face = k, q = qk;
      }
      const Vec3<T> n = axes[face] * (q < 0 ? T(-1) : T(1));
      return least > 0 ? Vec3<T>(n * (penalty * least)) : Vec3<T>::Zero();
    }
    default:
      return Vec3<T>::Zero();  // meshes: the path test only
  }
}

// The path p -> x of a free particle against one obstacle row: moved out to `margin` from the
// surface, then its tangential motion limited by friction (position-based Coulomb: held when it
// is below friction times the push, else shortened by that much).
// A mesh (row `index`, through `queries`) is met along the path extended by the margin, so that a
// particle within the margin of its surface meets it; it is kept the margin off the plane of the
// triangle it meets, on the path's side (two-sided).
template <class T>
void collide(const core::ObstacleRow& row, std::uint32_t index,
             const core::ObstacleQueries* queries, const Vec3<T>& p, Vec3<T>& x, T margin,
             T friction) {
  Vec3<T> n;
  T depth;
  const auto at = [&](int k) { return Vec3<T>(T(row.v[k]), T(row.v[k + 1]), T(row.v[k + 2])); };
  switch (row.kind) {
    case core::ObstacleRow::kPlane: {
      n = at(0);
      const T s = n.dot(x) + T(row.v[3]);
      if (!(s < margin)) return;
      depth = margin - s;
      break;
    }
    case core::ObstacleRow::kSphere: {
      const Vec3<T> e = x - at(0);
      const T r = T(row.v[3]) + margin, l2 = e.dot(e);
      if (!(l2 < r * r)) return;
      const T l = std::sqrt(l2);
      if (!(l > 0)) return;
      n = e / l;
      depth = r - l;
      break;
    }
    case core::ObstacleRow::kObb: {
      // In the box's frame, grown by the margin: a path from outside stops on the face it
      // entered through (the slab entered last), however far it went (a thin box is not passed
      // through); a path from inside (in the margin, or pushed in) leaves by the start's nearest
      // face, if it ends beyond it.
      const Vec3<T> c = at(0), axes[3] = {at(6), at(9), at(12)};
      const Vec3<T> q(axes[0].dot(x - c), axes[1].dot(x - c), axes[2].dot(x - c));
      const Vec3<T> q0(axes[0].dot(p - c), axes[1].dot(p - c), axes[2].dot(p - c));
      T enter = -1, exit = 2, least = std::numeric_limits<T>::infinity();
      int face = -1, nearest = 0;
      bool outside = false;
      for (int k = 0; k < 3; ++k) {
        const T e = T(row.v[3 + k]) + margin;
        const T dq = q[k] - q0[k];
        outside = outside || !(std::abs(q0[k]) < e);
        // The segment's parameters at the two planes, ordered: inside the slab between them.
        const T t0 = (-e - q0[k]) / dq, t1 = (e - q0[k]) / dq;
        const T lo = dq == 0 ? (std::abs(q0[k]) < e ? T(-1) : T(3)) : std::min(t0, t1);
        const T hi = dq == 0 ? T(2) : std::max(t0, t1);
        if (lo > enter) enter = lo, face = k;
        exit = std::min(exit, hi);
        const T pen = e - std::abs(q0[k]);
        if (pen < least) least = pen, nearest = k;
      }
      if (outside && !(enter <= exit && enter >= 0 && enter <= 1)) return;  // not crossed
      const int k = outside ? face : nearest;
      const T side = q0[k] < 0 ? T(-1) : T(1);
      n = axes[k] * side;
      depth = T(row.v[3 + k]) + margin - side * q[k];
      if (!outside && !(depth > 0)) return;
      break;
    }
    case core::ObstacleRow::kMesh: {
      const Vec3<T> dir = x - p;
      const T len = std::sqrt(dir.dot(dir));
      if (!queries || !(len > 0)) return;
      const Vec3<T> ext = dir * ((len + margin) / len);
      float from[3], along[3], live = 1, s = 0, normal[3] = {}, hit = 0;  // the mesh is float
      for (int k = 0; k < 3; ++k) from[k] = float(p[k]), along[k] = float(ext[k]);
      queries->meshEntry(queries->context, index, 1, from, along, &live, &s, normal, &hit);
      if (hit == 0) return;
      n = Vec3<T>(T(normal[0]), T(normal[1]), T(normal[2]));
      depth = margin - n.dot(x - (p + ext * T(s)));
      if (!(depth > 0)) return;
      break;
    }
    default:
      return;
  }
  x = x + n * depth;
  const Vec3<T> moved = x - p;
  const Vec3<T> tangent = moved - n * n.dot(moved);
  const T tl = std::sqrt(tangent.dot(tangent)), hold = friction * depth;
  if (tl > 0) x = x - tangent * (tl <= hold ? T(1) : hold / tl);
}

// One step of substeps (cloth.hpp) over the slots.
template <class T>
void stepCloth(const core::ClothView<T>& v, const core::SpringNetwork& net,
               const core::Tethers& tethers, std::span<const core::ObstacleRow> rows,
               const core::ObstacleQueries* queries, const core::ClothStepParams& p) {
  using S = core::ClothStreams;
  const ClothState<T> s{v};
  const T h = T(p.h), invH = T(p.invH), invH2 = T(p.invH2), keep = T(p.keep);
  const T margin = T(p.margin), friction = T(p.friction);
  const Vec3<T> g(T(p.gravity[0]), T(p.gravity[1]), T(p.gravity[2]));
  const bool xpbd = p.model == core::ClothStepParams::kXpbd;
  for (int sub = 0; sub < p.substeps; ++sub) {
    if (!xpbd) {
      for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t i = 0; i < v.slots; ++i) v.s[S::fx + k][i] = 0;
      for (std::size_t k = 0; k < net.batchBegin[net.batches]; ++k)
        springForce<T>(s, net.a[k], net.b[k], T(net.rest[k]), T(net.stiffness[k]),
                       T(net.damping[k]));
      if (p.penalty > 0)
        for (std::size_t i = 0; i < v.slots; ++i) {
          if (v.s[S::w][i] == 0) continue;
          const Vec3<T> x = s.load(S::x, i);
          Vec3<T> f = s.load(S::fx, i);
          for (const core::ObstacleRow& row : rows)
            f = f + penaltyForce<T>(row, x, T(p.zone), T(p.penalty));
          s.store(S::fx, i, f);
        }
    }
    for (std::size_t i = 0; i < v.slots; ++i) {
      const T w = v.s[S::w][i];
      if (w == 0) continue;
      Vec3<T> vel = s.load(S::vx, i);
      vel = xpbd ? Vec3<T>((vel + g * h) * keep)
                 : Vec3<T>((vel + (g + s.load(S::fx, i) * w) * h) * keep);
      const Vec3<T> x = s.load(S::x, i);
      s.store(S::vx, i, vel);
      s.store(S::px, i, x);
      s.store(S::x, i, x + vel * h);
    }
    if (xpbd)
      for (std::size_t k = 0; k < net.batchBegin[net.batches]; ++k) {
        const T compliance = T(net.compliance[k]);
        projectSpring<T>(s, net.a[k], net.b[k], T(net.rest[k]), compliance * invH2,
                         compliance * T(net.damping[k]) * invH);
      }
    // The velocity changes by what moved the particle off its prediction x0 + v h (the same
    // bits as predicted), not (x - x0) / h: far from the origin a small step may round to no
    // motion at all, and would lose the velocity.
    for (std::size_t i = 0; i < v.slots; ++i) {
      if (v.s[S::w][i] == 0) continue;
      const Vec3<T> x0 = s.load(S::px, i), vel = s.load(S::vx, i);
      const Vec3<T> predicted = x0 + vel * h;
      Vec3<T> x = s.load(S::x, i);
      if (tethers.anchor && tethers.length[i] >= 0) {
        const Vec3<T> d = x - s.load(S::x, tethers.anchor[i]);
        const T l2 = d.dot(d), len = T(tethers.length[i]);
        if (l2 > len * len) x = s.load(S::x, tethers.anchor[i]) + d * (len / std::sqrt(l2));
      }
      for (std::uint32_t r = 0; r < rows.size(); ++r)
        collide<T>(rows[r], r, queries, x0, x, margin, friction);
      s.store(S::x, i, x);
      s.store(S::vx, i, vel + (x - predicted) * invH);
    }
  }
}

}  // namespace simdphys::reference

// The watertight ray-triangle test (raycast.hpp's intersectTriangle) with one triangle per lane,
// included inside each target's namespace (no include guard, by design). Used by the triangle
// stream (batch3d.cpp) and the mesh BVH's leaves (bvh_ray.cpp), so both agree bit for bit with
// the scalar test: vertices moved into the ray's sheared frame, edge functions u, v, w (with the
// scalar's exact recomputation for lanes where one rounds to zero, which decides points exactly
// on an edge), then t = (sum of weighted depths) / det (barycentric where that overflows). Needs
// <hwy/highway.h> and hn.

// a b - c d, recomputed in double where the float result is zero: the scalar test's
// differenceOfProducts (raycast.hpp) for floats, so that a point exactly on an edge is decided the
// same way in every lane.
inline float exactEdge(float a, float b, float c, float d) {
  const float r = a * b - c * d;
  return r != 0 ? r : float(double(a) * double(b) - double(c) * double(d));
}

// The hit test once the three vertices are in the ray's sheared frame: px, py (x, y after the
// shear) and pz (the depth along kz, relative to the origin), one triangle and one ray per lane;
// sz and tMax per lane. Returns the lanes hit with t in [0, tMax], their t in `t` (the other
// lanes' t is any value). kEarlyOut skips the depth and its division when no lane is inside: a
// branch that pays for one ray against 8 triangles, but not for packets, whose leaf tests run
// back to back (3% on W2's packets, docs/bvh.md).
template <bool kEarlyOut = true, class D>
HWY_INLINE hn::Mask<D> watertightSheared(D d, const hn::Vec<D> (&px)[3], const hn::Vec<D> (&py)[3],
                                         const hn::Vec<D> (&pz)[3], hn::Vec<D> sz, hn::Vec<D> tMax,
                                         hn::Vec<D>& t) {
  constexpr std::size_t kMaxLanes = hn::MaxLanes(D());
  const auto zero = hn::Zero(d);
  auto edge = [](auto a, auto b, auto c, auto e) { return hn::Sub(hn::Mul(a, b), hn::Mul(c, e)); };
  auto u = edge(px[2], py[1], py[2], px[1]);
  auto w1 = edge(px[0], py[2], py[0], px[2]);  // the scalar's v
  auto w2 = edge(px[1], py[0], py[1], px[0]);  // the scalar's w
  // Some edge function zero: its least magnitude is (one compare, no mask ors).
  const auto onEdge = hn::Eq(hn::Min(hn::Abs(u), hn::Min(hn::Abs(w1), hn::Abs(w2))), zero);
  if (HWY_UNLIKELY(!hn::AllFalse(d, onEdge))) {
    alignas(64) float X[3][kMaxLanes], Y[3][kMaxLanes], U[3][kMaxLanes];
    for (int q = 0; q < 3; ++q) hn::Store(px[q], d, X[q]), hn::Store(py[q], d, Y[q]);
    for (std::size_t k = 0; k < hn::Lanes(d); ++k) {
      U[0][k] = exactEdge(X[2][k], Y[1][k], Y[2][k], X[1][k]);
      U[1][k] = exactEdge(X[0][k], Y[2][k], Y[0][k], X[2][k]);
      U[2][k] = exactEdge(X[1][k], Y[0][k], Y[1][k], X[0][k]);
    }
    u = hn::Load(d, U[0]), w1 = hn::Load(d, U[1]), w2 = hn::Load(d, U[2]);
  }
  // Some edge function negative and some positive, from their least and most: two compares where
  // six and four mask ors were (a lane with a NaN misses either way, its det being NaN).
  const auto anyNegative = hn::Lt(hn::Min(u, hn::Min(w1, w2)), zero);
  const auto anyPositive = hn::Gt(hn::Max(u, hn::Max(w1, w2)), zero);
  const auto det = hn::Add(hn::Add(u, w1), w2);
  // A lane whose point is outside an edge, or whose triangle is degenerate, misses at any t:
  // with none left, the depth and its division are skipped (Embree's early out).
  const auto inside = hn::AndNot(hn::And(anyNegative, anyPositive), hn::Ne(det, zero));
  if (kEarlyOut && hn::AllFalse(d, inside)) {
    t = tMax;
    return inside;
  }
  const auto scaled =
      hn::Add(hn::Add(hn::Mul(u, hn::Mul(sz, pz[0])), hn::Mul(w1, hn::Mul(sz, pz[1]))),
              hn::Mul(w2, hn::Mul(sz, pz[2])));
  t = hn::Div(scaled, det);
  // The scalar's barycentric form where u * depth overflowed (near the range's edges only).
  const auto overflow = hn::Not(hn::IsFinite(scaled));
  if (HWY_UNLIKELY(!hn::AllFalse(d, overflow))) {
    const auto bary = hn::Add(hn::Add(hn::Mul(hn::Div(u, det), hn::Mul(sz, pz[0])),
                                      hn::Mul(hn::Div(w1, det), hn::Mul(sz, pz[1]))),
                              hn::Mul(hn::Div(w2, det), hn::Mul(sz, pz[2])));
    t = hn::IfThenElse(overflow, bary, t);
  }
  t = hn::Add(t, zero);  // -0 becomes +0
  return hn::And(inside, hn::And(hn::Ge(t, zero), hn::Le(t, tMax)));
}

// The lanes whose triangle the ray hits with t in [0, tMax]; their t in `t`. `r` is the ray's
// precomputation: a WatertightQuery (kernels.hpp) or anything with its fields (TraversalRay).
// `vertex(q, k)` loads coordinate k of vertex q (a, b, c) of the lanes' triangles.
template <class D, class Query, class VertexRow>
HWY_INLINE hn::Mask<D> watertightHits(D d, const Query& r, float tMax, VertexRow vertex,
                                      hn::Vec<D>& t) {
  const float origin[3] = {r.ox, r.oy, r.oz};
  const auto sx = hn::Set(d, r.sx), sy = hn::Set(d, r.sy);
  // Per vertex: its coordinates relative to the origin, along kx, ky, kz.
  auto relative = [&](int q, int k) { return hn::Sub(vertex(q, k), hn::Set(d, origin[k])); };
  hn::Vec<D> px[3], py[3], pz[3];
  for (int q = 0; q < 3; ++q) {
    pz[q] = relative(q, r.kz);
    px[q] = hn::Sub(relative(q, r.kx), hn::Mul(sx, pz[q]));
    py[q] = hn::Sub(relative(q, r.ky), hn::Mul(sy, pz[q]));
  }
  return watertightSheared(d, px, py, pz, hn::Set(d, r.sz), hn::Set(d, tMax), t);
}

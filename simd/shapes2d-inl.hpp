// The 2D shape tests of geometry2d/ written once over a lane type V: a Highway vector (the SIMD
// kernels) or float (the plain-loop baseline). Included inside each target's namespace (no include
// guard, by design), after the includer's `hn` alias. Each mirrors its scalar function operation
// for operation; with two terms a sum has one possible order, so the only freedom Eigen has
// (how it associates a reduction) never arises. Nothing here fuses: the project compiles with
// -ffp-contract=off.
//
// The operations are called unqualified: for vectors argument-dependent lookup finds Highway's,
// for floats the overloads below.

inline float Add(float a, float b) { return a + b; }
inline float Sub(float a, float b) { return a - b; }
inline float Mul(float a, float b) { return a * b; }
inline float Neg(float a) { return -a; }
inline float Abs(float a) { return std::abs(a); }
inline float Sqrt(float a) { return std::sqrt(a); }
// std::max's rule (b only if a < b); Highway's Max differs only on the sign of a zero result,
// which no test below can see (zeros are only compared or added to a nonzero value).
inline float Max(float a, float b) { return std::max(a, b); }
inline bool Le(float a, float b) { return a <= b; }
inline bool And(bool a, bool b) { return a & b; }  // no branch: keeps plain loops vectorisable

// |(x, y)|: Eigen's norm(), sqrt(x x + y y).
template <class V>
V length2(V x, V y) {
  return Sqrt(Add(Mul(x, x), Mul(y, y)));
}

// The circle tests' closed comparison: distance <= reach + tol max(distance, reach).
template <class V>
auto withinReach(V distance, V reach, V tol) {
  return Le(distance, Add(reach, Mul(tol, Max(distance, reach))));
}

// intersects(Circle a, Circle b): |cb - ca| against ra + rb.
template <class V>
auto circleMeetsCircle(V ax, V ay, V ar, V bx, V by, V br, V tol) {
  return withinReach(length2(Sub(bx, ax), Sub(by, ay)), Add(ar, br), tol);
}

// contains(Circle, p): |p - c| against r.
template <class V>
auto circleContains(V cx, V cy, V r, V px, V py, V tol) {
  return withinReach(length2(Sub(px, cx), Sub(py, cy)), r, tol);
}

// intersects(Rect a, Rect b): closed interval overlap on both axes, exact.
template <class V>
struct RectLanes {
  V minX, minY, maxX, maxY;
};
template <class V>
auto rectMeetsRect(const RectLanes<V>& a, const RectLanes<V>& b) {
  return And(And(Le(a.minX, b.maxX), Le(a.minY, b.maxY)),
             And(Le(b.minX, a.maxX), Le(b.minY, a.maxY)));
}

// contains(Rect, p): min <= p <= max, exact.
template <class V>
auto rectContains(const RectLanes<V>& r, V px, V py) {
  return And(And(Le(r.minX, px), Le(r.minY, py)), And(Le(px, r.maxX), Le(py, r.maxY)));
}

// An oriented rectangle: centre, half extents, local x axis (c, s), local y axis (-s, c).
template <class V>
struct OrientedRectLanes {
  V cx, cy, hx, hy, c, s;
};

// contains(OrientedRect, p): local = axes^T (p - c); max(|local| - h) against
// tol (|p - c| + max(h)).
template <class V>
auto orientedRectContains(const OrientedRectLanes<V>& b, V px, V py, V tol) {
  const V ox = Sub(px, b.cx), oy = Sub(py, b.cy);
  const V lx = Add(Mul(b.c, ox), Mul(b.s, oy));
  const V ly = Add(Mul(Neg(b.s), ox), Mul(b.c, oy));
  const V excess = Max(Sub(Abs(lx), b.hx), Sub(Abs(ly), b.hy));
  return Le(excess, Mul(tol, Add(length2(ox, oy), Max(b.hx, b.hy))));
}

// collisions.hpp's projectedRadius: half the extent of b's projection on the unit axis u.
template <class V>
V projectedRadius(const OrientedRectLanes<V>& b, V ux, V uy) {
  return Add(Mul(b.hx, Abs(Add(Mul(b.c, ux), Mul(b.s, uy)))),
             Mul(b.hy, Abs(Add(Mul(Neg(b.s), ux), Mul(b.c, uy)))));
}

// collisions.hpp's maxSeparation(ref, other), d = other's centre - ref's centre: the larger of the
// separations along ref's two axes (the scalar keeps the first of equal ones; the value is the
// same).
template <class V>
V maxSeparation(const OrientedRectLanes<V>& ref, const OrientedRectLanes<V>& other, V dx, V dy) {
  const V ns = Neg(ref.s);
  const V along0 = Add(Mul(dx, ref.c), Mul(dy, ref.s));
  const V along1 = Add(Mul(dx, ns), Mul(dy, ref.c));
  const V sep0 = Sub(Abs(along0), Add(ref.hx, projectedRadius(other, ref.c, ref.s)));
  const V sep1 = Sub(Abs(along1), Add(ref.hy, projectedRadius(other, ns, ref.c)));
  return Max(sep0, sep1);
}

// intersects(OrientedRect a, OrientedRect b): boxesIntersect in the frame centred on a, where a's
// centre is a - a = 0 and b's is d = b - a. The scalar function first puts the pair in a canonical
// order and centres the frame on the first; the other order computes the same bits: its offset is
// fl(a - b) = -fl(b - a) (rounding is symmetric), which changes no |d.u|, no |d| and no sum of
// half extents. So one order serves every lane. 0 - d is written -d: they differ only in the sign
// of a zero, which |d.u| drops.
template <class V>
auto orientedRectMeetsOrientedRect(const OrientedRectLanes<V>& a, const OrientedRectLanes<V>& b,
                                   V tol) {
  const V dx = Sub(b.cx, a.cx), dy = Sub(b.cy, a.cy);
  const V slack = Mul(tol, Add(length2(dx, dy), Add(Add(a.hx, a.hy), Add(b.hx, b.hy))));
  return And(Le(maxSeparation(a, b, dx, dy), slack),
             Le(maxSeparation(b, a, Neg(dx), Neg(dy)), slack));
}

// The ray-box slab test, written once over a lane type: a Highway vector (8 boxes against one ray
// in the single-ray walk, one box against 8 or 16 rays in a packet) or a float (the reference
// walk, the scene's walk and its ray filter). Included inside the includer's namespace (no include
// guard, by design), after core/traversal_ray.hpp and, for floats, core/scalar_lanes-inl.hpp; the
// operations are called unqualified (Highway's found by argument-dependent lookup).

// One axis's slab clips the ray's interval [enter, exit]: enter rises to the near face's distance
// tNear, exit falls to the far face's tFar. kFinite: no distance is NaN, so Max/Min do it;
// otherwise comparisons, which leave the interval as it is where a distance is NaN (0 * inf, or
// 0 / 0: the origin on a face the ray runs along, so the whole line lies in that slab). The walks
// below clip [0, bound] with products by the inverse; an exact ray-box hit is the same clip of
// (-inf, inf) with quotients by the direction (batch3d.cpp's rayClosestBox and its baseline; the
// reference's slabs, src/reference/geometry3d/raycast-inl.hpp, writes the comparisons out, since
// it also keeps the axis of the face for the hit's normal).
template <bool kFinite, class V>
inline void clipSlab(V tNear, V tFar, V& enter, V& exit) {
  if constexpr (kFinite) {
    enter = Max(tNear, enter);
    exit = Min(tFar, exit);
  } else {
    enter = IfThenElse(Gt(tNear, enter), tNear, enter);
    exit = IfThenElse(Lt(tFar, exit), tFar, exit);
  }
}

// The walks' test: the lanes whose ray enters their box before `bound` (and after 0), and
// `enter`, the scaled distance where it does (traversal_ray.hpp: scaled so that a box the ray
// touches in exact arithmetic is never culled). `faces(a, nearFace, farFace)` gives axis a's near
// and far face (chosen by the sign bit of the direction), axis by axis so that the lanes' loads
// or selects interleave with the arithmetic; origin and inverse are the ray's, per axis.
template <bool kFinite, class D, class V, class Faces>
inline auto raySlab(D d, Faces faces, const V (&origin)[3], const V (&inverse)[3], V bound,
                    V& enter) {
  enter = Zero(d);
  V exit = bound;
  for (int a = 0; a < 3; ++a) {
    V nearFace, farFace;
    faces(a, nearFace, farFace);
    clipSlab<kFinite>(Mul(Sub(nearFace, origin[a]), inverse[a]),
                      Mul(Sub(farFace, origin[a]), inverse[a]), enter, exit);
  }
  enter = Mul(enter, Set(d, ::simdphys::detail::kEnterScale));
  return Le(enter, Mul(exit, Set(d, ::simdphys::detail::kExitScale)));
}

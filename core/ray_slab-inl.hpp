// The ray-box slab test, written once over a lane type: a Highway vector (8 boxes against one ray
// in the single-ray walk, one box against 8 or 16 rays in a packet) or a float (the reference
// walk, the scene's walk and its ray filter). Included inside the includer's namespace (no include
// guard, by design), after core/traversal_ray.hpp and, for floats, core/scalar_lanes-inl.hpp; the
// operations are called unqualified (Highway's found by argument-dependent lookup).

// The lanes whose ray enters their box before `bound` (and after 0), and `enter`, the scaled
// distance where it does. Per axis: the box's near and far face (chosen by the sign bit of the
// direction), the ray's origin and inverse direction. kFinite: every inverse is finite, so no
// product is NaN and Max/Min bound the interval; otherwise comparisons, which leave the bound as
// it is where a product is NaN (traversal_ray.hpp: the whole line lies in that slab).
template <bool kFinite, class D, class V>
inline auto raySlab(D d, const V (&nearFace)[3], const V (&farFace)[3], const V (&origin)[3],
                    const V (&inverse)[3], V bound, V& enter) {
  enter = Zero(d);
  V exit = bound;
  for (int a = 0; a < 3; ++a) {
    const V tNear = Mul(Sub(nearFace[a], origin[a]), inverse[a]);
    const V tFar = Mul(Sub(farFace[a], origin[a]), inverse[a]);
    if constexpr (kFinite) {
      enter = Max(tNear, enter);
      exit = Min(tFar, exit);
    } else {
      enter = IfThenElse(Gt(tNear, enter), tNear, enter);
      exit = IfThenElse(Lt(tFar, exit), tFar, exit);
    }
  }
  enter = Mul(enter, Set(d, ::simdphys::detail::kEnterScale));
  return Le(enter, Mul(exit, Set(d, ::simdphys::detail::kExitScale)));
}

// The shapes of entry the explicit instantiation lists of src/reference/<header>.cpp share: each
// names a query once for a pair or kind of shapes, for the scalar T its list is written for.
#pragma once

// f(a, b) for two kinds of shapes, in the order the pair is written in (the other order swaps the
// arguments inline: primitives.hpp).
#define SIMDPHYS_INSTANTIATE_PAIR(T, R, f, A, B) template R f(const A<T>&, const B<T>&);

// f(a, b) for two shapes of one kind.
#define SIMDPHYS_INSTANTIATE_SAME_KIND(T, R, f, A) template R f(const A<T>&, const A<T>&);

// contains(shape, point) and closestPoint(shape, point), with the point as a Vec (Vec2 or Vec3).
#define SIMDPHYS_INSTANTIATE_POINT_QUERIES(T, Shape, Vec)                   \
  template bool contains(const Shape<T>&, const detail::NoDeduce<Vec<T>>&); \
  template Vec<T> closestPoint(const Shape<T>&, const detail::NoDeduce<Vec<T>>&);

// linecast(shape, segment) and linetest(shape, segment).
#define SIMDPHYS_INSTANTIATE_SEGMENT_QUERIES(T, Shape)                              \
  template std::optional<RayHitT<T>> linecast(const Shape<T>&, const SegmentT<T>&); \
  template bool linetest(const Shape<T>&, const SegmentT<T>&);

// Batch forms of the 2D shape tests: one shape against a stream, a vector of elements at a time,
// or the same lane test as a plain loop (the auto-vectorisation baseline). The tests themselves are
// in shapes2d-inl.hpp, written once for both.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/batch2d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "simd/export.hpp"
#include "simd/kernels.hpp"

SIMDPHYS_TARGET_BEGIN();

#include "simd/compress-inl.hpp"
#include "simd/shapes2d-inl.hpp"

// Runs `test(at, all)` over a stream: `at(field)` is the field of the current elements, `all(x)`
// a query value beside them. Vectors up to `padded` (padding lanes fail every test), or, kPlain,
// floats up to `count` in plain loops: a block of answers (a loop the compiler can vectorise; this
// file is compiled with -fno-math-errno so that std::sqrt does not stop it), then the indices of
// the ones that pass.
template <bool kPlain, class Test>
std::size_t run(std::size_t count, std::size_t padded, std::uint32_t* out, Test test) {
  if constexpr (kPlain) {
    constexpr std::size_t kBlock = 256;
    std::size_t n = 0;
    for (std::size_t start = 0; start < count; start += kBlock) {
      const std::size_t m = std::min(kBlock, count - start);
      bool keep[kBlock];
      for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = start + k;
        keep[k] = test([i](const float* field) { return field[i]; }, [](float x) { return x; });
      }
      for (std::size_t k = 0; k < m; ++k) {
        out[n] = std::uint32_t(start + k);
        n += keep[k];
      }
    }
    return n;
  } else {
    return selectIndices(padded, out, [&](auto d, std::size_t i) {
      return test([d, i](const float* field) { return hn::Load(d, field + i); },
                  [d](float x) { return hn::Set(d, x); });
    });
  }
}

template <class At>
auto rectLanes(At at, const RectsView& v) {
  using F = fields::Rect;
  return RectLanes<decltype(at(v[F::minX]))>{at(v[F::minX]), at(v[F::minY]), at(v[F::maxX]),
                                             at(v[F::maxY])};
}

template <class At>
auto orientedRectLanes(At at, const OrientedRectsView& v) {
  using F = fields::OrientedRect;
  return OrientedRectLanes<decltype(at(v[F::cx]))>{at(v[F::cx]), at(v[F::cy]),  at(v[F::hx]),
                                                   at(v[F::hy]), at(v[F::cos]), at(v[F::sin])};
}

// Each test below is written once for both forms; HWY_EXPORT takes plain functions, so this
// names the two: Name (Highway vectors) and NameAutovec (the plain-loop baseline).
#define SIMDPHYS_TWO_FORMS(Name, Query, View)                                    \
  std::size_t Name(const Query& q, const View& v, std::uint32_t* out) {          \
    return Name##Forms<false>(q, v, out);                                        \
  }                                                                              \
  std::size_t Name##Autovec(const Query& q, const View& v, std::uint32_t* out) { \
    return Name##Forms<true>(q, v, out);                                         \
  }

template <bool kPlain>
std::size_t CircleOverlapsCirclesForms(const CircleQuery2d& q, const CirclesView& v,
                                       std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    // Padding has radius -inf: a reach of -inf, which no distance is within.
    return circleMeetsCircle(all(q.x), all(q.y), all(q.r), at(v[fields::Circle::x]),
                             at(v[fields::Circle::y]), at(v[fields::Circle::r]), all(q.tolerance));
  });
}
SIMDPHYS_TWO_FORMS(CircleOverlapsCircles, CircleQuery2d, CirclesView)

template <bool kPlain>
std::size_t RectOverlapsRectsForms(const RectQuery2d& q, const RectsView& v, std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    const RectLanes<decltype(all(q.minX))> query{all(q.minX), all(q.minY), all(q.maxX),
                                                 all(q.maxY)};
    return rectMeetsRect(query, rectLanes(at, v));  // padding is empty: max = -inf fails
  });
}
SIMDPHYS_TWO_FORMS(RectOverlapsRects, RectQuery2d, RectsView)

template <bool kPlain>
std::size_t OrientedRectOverlapsOrientedRectsForms(const OrientedRectQuery2d& q,
                                                   const OrientedRectsView& v, std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    const OrientedRectLanes<decltype(all(q.cx))> query{all(q.cx), all(q.cy),  all(q.hx),
                                                       all(q.hy), all(q.cos), all(q.sin)};
    const auto element = orientedRectLanes(at, v);
    // Padding (half extents -inf) would compute -inf * 0 = NaN for some queries: masked out by
    // its negative extent, which no valid rectangle has.
    return And(Le(all(0.0f), element.hx),
               orientedRectMeetsOrientedRect(query, element, all(q.tolerance)));
  });
}
SIMDPHYS_TWO_FORMS(OrientedRectOverlapsOrientedRects, OrientedRectQuery2d, OrientedRectsView)

template <bool kPlain>
std::size_t PointInCirclesForms(const PointQuery2d& p, const CirclesView& v, std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    return circleContains(at(v[fields::Circle::x]), at(v[fields::Circle::y]),
                          at(v[fields::Circle::r]), all(p.x), all(p.y), all(p.tolerance));
  });
}
SIMDPHYS_TWO_FORMS(PointInCircles, PointQuery2d, CirclesView)

template <bool kPlain>
std::size_t PointInRectsForms(const PointQuery2d& p, const RectsView& v, std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    return rectContains(rectLanes(at, v), all(p.x), all(p.y));
  });
}
SIMDPHYS_TWO_FORMS(PointInRects, PointQuery2d, RectsView)

template <bool kPlain>
std::size_t PointInOrientedRectsForms(const PointQuery2d& p, const OrientedRectsView& v,
                                      std::uint32_t* out) {
  return run<kPlain>(v.count, v.padded, out, [&](auto at, auto all) {
    // Padding: |local| - (-inf) = +inf against tol * -inf: never contained, no NaN.
    return orientedRectContains(orientedRectLanes(at, v), all(p.x), all(p.y), all(p.tolerance));
  });
}
SIMDPHYS_TWO_FORMS(PointInOrientedRects, PointQuery2d, OrientedRectsView)

#undef SIMDPHYS_TWO_FORMS

SIMDPHYS_TARGET_END();

#if HWY_ONCE
namespace simdphys::simd {
SIMDPHYS_EXPORT(CircleOverlapsCircles, circleOverlapsCircles);
SIMDPHYS_EXPORT(CircleOverlapsCirclesAutovec, circleOverlapsCirclesAutovec);
SIMDPHYS_EXPORT(RectOverlapsRects, rectOverlapsRects);
SIMDPHYS_EXPORT(RectOverlapsRectsAutovec, rectOverlapsRectsAutovec);
SIMDPHYS_EXPORT(OrientedRectOverlapsOrientedRects, orientedRectOverlapsOrientedRects);
SIMDPHYS_EXPORT(OrientedRectOverlapsOrientedRectsAutovec, orientedRectOverlapsOrientedRectsAutovec);
SIMDPHYS_EXPORT(PointInCircles, pointInCircles);
SIMDPHYS_EXPORT(PointInCirclesAutovec, pointInCirclesAutovec);
SIMDPHYS_EXPORT(PointInRects, pointInRects);
SIMDPHYS_EXPORT(PointInRectsAutovec, pointInRectsAutovec);
SIMDPHYS_EXPORT(PointInOrientedRects, pointInOrientedRects);
SIMDPHYS_EXPORT(PointInOrientedRectsAutovec, pointInOrientedRectsAutovec);
}  // namespace simdphys::simd
#endif

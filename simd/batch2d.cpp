// Batch forms of the 2D shape tests: one shape against a stream, a vector of elements at a time,
// or the same lane test as a plain loop (the auto-vectorisation baseline). The tests themselves are
// in shapes2d-inl.hpp, written once for both.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/batch2d.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "simd/kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace simdphys::simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "simd/compress-inl.hpp"
#include "simd/shapes2d-inl.hpp"

// Runs `test(at, all)` over a stream: `at(field)` is the field of the current elements, `all(x)`
// a query value beside them. Vectors up to `padded` (padding lanes fail every test), or floats up
// to `count` in plain loops: a block of answers (a loop the compiler can vectorise; this file is
// compiled with -fno-math-errno so that std::sqrt does not stop it), then the indices of the ones
// that pass.
template <class Test>
std::size_t run(Loop loop, std::size_t count, std::size_t padded, std::uint32_t* out, Test test) {
  if (loop == Loop::kAutovec) {
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
  }
  return selectIndices(padded, out, [&](auto d, std::size_t i) {
    return test([d, i](const float* field) { return hn::Load(d, field + i); },
                [d](float x) { return hn::Set(d, x); });
  });
}

template <class At>
auto rectLanes(At at, const RectsView& v) {
  return RectLanes<decltype(at(v.minX))>{at(v.minX), at(v.minY), at(v.maxX), at(v.maxY)};
}

template <class At>
auto orientedRectLanes(At at, const OrientedRectsView& v) {
  return OrientedRectLanes<decltype(at(v.cx))>{at(v.cx), at(v.cy),  at(v.hx),
                                               at(v.hy), at(v.cos), at(v.sin)};
}

std::size_t CircleOverlapsCircles(const CircleQuery2d& q, const CirclesView& v, std::uint32_t* out,
                                  Loop loop) {
  return run(loop, v.count, v.padded, out, [&](auto at, auto all) {
    // Padding has radius -inf: a reach of -inf, which no distance is within.
    return circleMeetsCircle(all(q.x), all(q.y), all(q.r), at(v.x), at(v.y), at(v.r),
                             all(q.tolerance));
  });
}

std::size_t RectOverlapsRects(const RectQuery2d& q, const RectsView& v, std::uint32_t* out,
                              Loop loop) {
  return run(loop, v.count, v.padded, out, [&](auto at, auto all) {
    const RectLanes<decltype(all(q.minX))> query{all(q.minX), all(q.minY), all(q.maxX),
                                                 all(q.maxY)};
    return rectMeetsRect(query, rectLanes(at, v));  // padding is empty: max = -inf fails
  });
}

std::size_t OrientedRectOverlapsOrientedRects(const OrientedRectQuery2d& q,
                                              const OrientedRectsView& v, std::uint32_t* out,
                                              Loop loop) {
  return run(loop, v.count, v.padded, out, [&](auto at, auto all) {
    const OrientedRectLanes<decltype(all(q.cx))> query{all(q.cx), all(q.cy),  all(q.hx),
                                                       all(q.hy), all(q.cos), all(q.sin)};
    const auto element = orientedRectLanes(at, v);
    // Padding (half extents -inf) would compute -inf * 0 = NaN for some queries: masked out by
    // its negative extent, which no valid rectangle has.
    return And(Le(all(0.0f), element.hx),
               orientedRectMeetsOrientedRect(query, element, all(q.tolerance)));
  });
}

std::size_t PointInCircles(const PointQuery2d& p, const CirclesView& v, std::uint32_t* out,
                           Loop loop) {
  return run(loop, v.count, v.padded, out, [&](auto at, auto all) {
    return circleContains(at(v.x), at(v.y), at(v.r), all(p.x), all(p.y), all(p.tolerance));
  });
}

std::size_t PointInRects(const PointQuery2d& p, const RectsView& v, std::uint32_t* out, Loop loop) {
  return run(loop, v.count, v.padded, out,
             [&](auto at, auto all) { return rectContains(rectLanes(at, v), all(p.x), all(p.y)); });
}

std::size_t PointInOrientedRects(const PointQuery2d& p, const OrientedRectsView& v,
                                 std::uint32_t* out, Loop loop) {
  return run(loop, v.count, v.padded, out, [&](auto at, auto all) {
    // Padding: |local| - (-inf) = +inf against tol * -inf: never contained, no NaN.
    return orientedRectContains(orientedRectLanes(at, v), all(p.x), all(p.y), all(p.tolerance));
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace simdphys::simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace simdphys::simd {
HWY_EXPORT(CircleOverlapsCircles);
HWY_EXPORT(RectOverlapsRects);
HWY_EXPORT(OrientedRectOverlapsOrientedRects);
HWY_EXPORT(PointInCircles);
HWY_EXPORT(PointInRects);
HWY_EXPORT(PointInOrientedRects);

std::size_t circleOverlapsCircles(const CircleQuery2d& q, const CirclesView& v, std::uint32_t* out,
                                  Loop loop) {
  return HWY_DYNAMIC_DISPATCH(CircleOverlapsCircles)(q, v, out, loop);
}
std::size_t rectOverlapsRects(const RectQuery2d& q, const RectsView& v, std::uint32_t* out,
                              Loop loop) {
  return HWY_DYNAMIC_DISPATCH(RectOverlapsRects)(q, v, out, loop);
}
std::size_t orientedRectOverlapsOrientedRects(const OrientedRectQuery2d& q,
                                              const OrientedRectsView& v, std::uint32_t* out,
                                              Loop loop) {
  return HWY_DYNAMIC_DISPATCH(OrientedRectOverlapsOrientedRects)(q, v, out, loop);
}
std::size_t pointInCircles(const PointQuery2d& p, const CirclesView& v, std::uint32_t* out,
                           Loop loop) {
  return HWY_DYNAMIC_DISPATCH(PointInCircles)(p, v, out, loop);
}
std::size_t pointInRects(const PointQuery2d& p, const RectsView& v, std::uint32_t* out, Loop loop) {
  return HWY_DYNAMIC_DISPATCH(PointInRects)(p, v, out, loop);
}
std::size_t pointInOrientedRects(const PointQuery2d& p, const OrientedRectsView& v,
                                 std::uint32_t* out, Loop loop) {
  return HWY_DYNAMIC_DISPATCH(PointInOrientedRects)(p, v, out, loop);
}
}  // namespace simdphys::simd
#endif

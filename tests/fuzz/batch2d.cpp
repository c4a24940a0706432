// Fuzz target: the 2D batch queries (geometry2d/batch.hpp) on streams decoded from the bytes (up
// to 40 elements), each on every path against the reference path, exactly (index lists).
#include <sstream>
#include <vector>

#include "simdphys/geometry2d/batch.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace simdphys {
namespace {

// Mostly valid elements; sometimes as decoded, which the stream must reject with an Error.
Circle circle(fuzz::Input& in) {
  const Vec2f c = in.vec2();
  const float r = in.scalar();
  return {c, in.byte() < 240 ? std::abs(r) : r};
}
Rect rect(fuzz::Input& in) {
  const Vec2f a = in.vec2(), b = in.vec2();
  return in.byte() < 240 ? Rect{a.cwiseMin(b), a.cwiseMax(b)} : Rect{a, b};
}
OrientedRect orientedRect(fuzz::Input& in) {
  const Vec2f c = in.vec2(), e = in.vec2();
  return {c, in.byte() < 240 ? Vec2f(e.cwiseAbs()) : e, in.scalar()};
}

template <class Stream, class Make>
Stream streamOf(fuzz::Input& in, Make make) {
  Stream s;
  for (std::size_t i = 0, n = in.count(40); i < n; ++i) s.push(make(in));
  return s;
}

std::string describe(const OrientedRect& r) {
  std::ostringstream o;
  o.precision(9);
  o << "center (" << r.center.transpose() << ") half (" << r.halfExtents.transpose()
    << ") rotation " << r.rotation;
  return o.str();
}

template <class Query>
void indices(const char* what, Query query, const std::function<std::string()>& context = {}) {
  fuzz::sameOnEveryPath(
      what,
      [&] {
        std::vector<std::uint32_t> out;
        const std::size_t n = query(out);
        fuzz::require(n == out.size(), std::string(what) + ": the count is not the list's size");
        return out;
      },
      context);
}

}  // namespace
}  // namespace simdphys

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  fuzz::Input in(data, size);
  try {
    switch (in.byte() % 6) {
      case 0: {
        const auto s = streamOf<CircleStream>(in, circle);
        const Circle q = circle(in);
        indices("overlapping(Circle, CircleStream)", [&](auto& o) { return overlapping(q, s, o); });
        break;
      }
      case 1: {
        const auto s = streamOf<RectStream>(in, rect);
        const Rect q = rect(in);
        indices("overlapping(Rect, RectStream)", [&](auto& o) { return overlapping(q, s, o); });
        break;
      }
      case 2: {
        const auto s = streamOf<OrientedRectStream>(in, orientedRect);
        const OrientedRect q = orientedRect(in);
        indices(
            "overlapping(OrientedRect, OrientedRectStream)",
            [&](auto& o) { return overlapping(q, s, o); },
            [&] {
              std::string text = "\n  query: " + describe(q);
              for (std::size_t i = 0; i < s.size(); ++i)
                text += "\n  element " + std::to_string(i) + ": " + describe(s[i]);
              std::vector<std::uint32_t> ids;
              ScopedPath p("reference");
              overlapping(q, s, ids);
              text += "\n  reference:";
              for (std::uint32_t id : ids) text += " " + std::to_string(id);
              return text;
            });
        break;
      }
      case 3: {
        const auto s = streamOf<CircleStream>(in, circle);
        const Vec2f p = in.vec2();
        indices("containing(point, CircleStream)", [&](auto& o) { return containing(p, s, o); });
        break;
      }
      case 4: {
        const auto s = streamOf<RectStream>(in, rect);
        const Vec2f p = in.vec2();
        indices("containing(point, RectStream)", [&](auto& o) { return containing(p, s, o); });
        break;
      }
      default: {
        const auto s = streamOf<OrientedRectStream>(in, orientedRect);
        const Vec2f p = in.vec2();
        indices("containing(point, OrientedRectStream)",
                [&](auto& o) { return containing(p, s, o); });
        break;
      }
    }
  } catch (const Error&) {  // a stream rejected an element
  }
  return 0;
}

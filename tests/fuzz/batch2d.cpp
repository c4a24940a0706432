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

std::string describe(const OrientedRect& r) {
  std::ostringstream o;
  o.precision(9);
  o << "center (" << r.center.transpose() << ") half (" << r.halfExtents.transpose()
    << ") rotation " << r.rotation;
  return o.str();
}

}  // namespace
}  // namespace simdphys

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace simdphys;
  fuzz::Input in(data, size);
  try {
    switch (in.byte() % 6) {
      case 0: {
        const auto s = fuzz::streamOf<CircleStream>(in, circle);
        const Circle q = circle(in);
        fuzz::indices("overlapping(Circle, CircleStream)",
                      [&](auto& o) { return overlapping(q, s, o); });
        break;
      }
      case 1: {
        const auto s = fuzz::streamOf<RectStream>(in, rect);
        const Rect q = rect(in);
        fuzz::indices("overlapping(Rect, RectStream)",
                      [&](auto& o) { return overlapping(q, s, o); });
        break;
      }
      case 2: {
        const auto s = fuzz::streamOf<OrientedRectStream>(in, orientedRect);
        const OrientedRect q = orientedRect(in);
        fuzz::indices(
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
        const auto s = fuzz::streamOf<CircleStream>(in, circle);
        const Vec2f p = in.vec2();
        fuzz::indices("containing(point, CircleStream)",
                      [&](auto& o) { return containing(p, s, o); });
        break;
      }
      case 4: {
        const auto s = fuzz::streamOf<RectStream>(in, rect);
        const Vec2f p = in.vec2();
        fuzz::indices("containing(point, RectStream)",
                      [&](auto& o) { return containing(p, s, o); });
        break;
      }
      default: {
        const auto s = fuzz::streamOf<OrientedRectStream>(in, orientedRect);
        const Vec2f p = in.vec2();
        fuzz::indices("containing(point, OrientedRectStream)",
                      [&](auto& o) { return containing(p, s, o); });
        break;
      }
    }
  } catch (const Error&) {  // a stream rejected an element
  }
  return 0;
}

#include "simdphys/geometry2d/streams.hpp"

namespace simdphys {
namespace {
std::array<float, 3> fieldsOf(const Circle& c) { return {c.center.x(), c.center.y(), c.radius}; }
std::array<float, 4> fieldsOf(const Rect& r) {
  return {r.min.x(), r.min.y(), r.max.x(), r.max.y()};
}
}  // namespace

void CircleStream::push(const Circle& c) { pushValid("CircleStream::push", c, fieldsOf(c)); }

void CircleStream::set(std::size_t i, const Circle& c) {
  setValid("CircleStream::set", i, c, fieldsOf(c));
}

void RectStream::push(const Rect& r) { pushValid("RectStream::push", r, fieldsOf(r)); }

void RectStream::set(std::size_t i, const Rect& r) {
  setValid("RectStream::set", i, r, fieldsOf(r));
}

void OrientedRectStream::push(const OrientedRect& r) {
  pushValid("OrientedRectStream::push", r, fieldsOf(r));
}

void OrientedRectStream::set(std::size_t i, const OrientedRect& r) {
  setValid("OrientedRectStream::set", i, r, fieldsOf(r));
}

}  // namespace simdphys

#include "simdphys/geometry2d/streams.hpp"

namespace simdphys {
using detail::at;
using detail::requireIndex;

void CircleStream::push(const Circle& c) {
  validate(c, at("CircleStream::push", size()));
  append({c.center.x(), c.center.y(), c.radius});
}

void CircleStream::set(std::size_t i, const Circle& c) {
  requireIndex(i, size(), "CircleStream::set");
  validate(c, at("CircleStream::set", i));
  store(i, {c.center.x(), c.center.y(), c.radius});
}

void RectStream::push(const Rect& r) {
  validate(r, at("RectStream::push", size()));
  append({r.min.x(), r.min.y(), r.max.x(), r.max.y()});
}

void RectStream::set(std::size_t i, const Rect& r) {
  requireIndex(i, size(), "RectStream::set");
  validate(r, at("RectStream::set", i));
  store(i, {r.min.x(), r.min.y(), r.max.x(), r.max.y()});
}

void OrientedRectStream::push(const OrientedRect& r) {
  validate(r, at("OrientedRectStream::push", size()));
  append(fieldsOf(r));
}

void OrientedRectStream::set(std::size_t i, const OrientedRect& r) {
  requireIndex(i, size(), "OrientedRectStream::set");
  validate(r, at("OrientedRectStream::set", i));
  store(i, fieldsOf(r));
}

}  // namespace simdphys

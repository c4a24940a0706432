// What the fuzz targets share: decoding the fuzzer's bytes into values and shapes, and running a
// query on every path to compare it with the reference path. A finding (a path that disagrees,
// a broken promise) prints what and where, then aborts: libFuzzer keeps the input, and the
// corpus replay test fails.
#pragma once

#include <Eigen/Geometry>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "simdphys/core.hpp"
#include "simdphys/math.hpp"

namespace simdphys::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) finding(what);
}

// The bytes as a stream of values; past the end every value is zero, so any input decodes.
class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() {
    if (size_ == 0) return 0;
    --size_;
    return *data_++;
  }
  std::uint32_t word() {
    std::uint32_t w = 0;
    for (int k = 0; k < 4; ++k) w = w << 8 | byte();
    return w;
  }
  // 0 to max.
  std::size_t count(std::size_t max) { return byte() % (max + 1); }

  // Mostly multiples of 1/8 in [-16, 16), so that shapes touch, share edges and coincide exactly;
  // sometimes a value at or past the edge of the supported range, or any bit pattern (NaN, inf,
  // subnormal): input that must be answered, or rejected with an Error.
  float scalar() {
    static constexpr float kInf = std::numeric_limits<float>::infinity();
    static constexpr float kSpecial[16] = {0.0f,
                                           -0.0f,
                                           1e-18f,
                                           1e-30f,
                                           kMaxCoordinate,
                                           -kMaxCoordinate,
                                           1e20f,
                                           -1e20f,
                                           3e38f,
                                           std::numeric_limits<float>::max(),
                                           -std::numeric_limits<float>::max(),
                                           kInf,
                                           -kInf,
                                           std::numeric_limits<float>::quiet_NaN(),
                                           std::numeric_limits<float>::denorm_min(),
                                           1e17f};
    const std::uint8_t mode = byte();
    if (mode < 216) return float(std::int8_t(byte())) / 8;
    if (mode < 240) return kSpecial[byte() % 16];
    return std::bit_cast<float>(word());
  }
  Vec2f vec2() { return {scalar(), scalar()}; }
  Vec3f vec3() {
    const float x = scalar(), y = scalar();
    return {x, y, scalar()};
  }
  // A unit vector (a zero or non-finite one is left as it is, for the callee to reject).
  Vec3f direction() {
    const Vec3f d = vec3();
    const float n = d.norm();
    return n > 0 && std::isfinite(n) ? Vec3f(d / n) : d;
  }
  // Mostly a rotation (about a decoded axis); sometimes the identity, sometimes any 9 values.
  Mat3f axes() {
    const std::uint8_t mode = byte();
    if (mode < 64) return Mat3f::Identity();
    if (mode < 240) {
      const Vec3f axis = direction();
      const float angle = scalar();
      if (!(axis.norm() > 0.5f) || !std::isfinite(angle)) return Mat3f::Identity();
      return Eigen::AngleAxisf(angle, axis).toRotationMatrix();
    }
    Mat3f m;
    for (int k = 0; k < 9; ++k) m.data()[k] = scalar();
    return m;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

// A float as a key that compares by value, except that a NaN equals the same NaN: paths must
// agree exactly, but -0 and +0 are the same answer (a clamp may return either).
inline std::uint32_t bitsOf(float x) { return x == 0 ? 0u : std::bit_cast<std::uint32_t>(x); }

// A query's outcome: the message of the Error it threw, or its result.
template <class R>
using Outcome = std::variant<std::string, R>;

template <class F>
auto outcomeOf(F&& query) -> Outcome<decltype(query())> {
  try {
    return query();
  } catch (const Error& e) {
    return std::string(e.what());
  }
}

// Runs `query` on the reference path and on every other path this machine has; any difference
// (a result, or an Error on one path and not another) is a finding, whose message ends with
// `context()` if given (the decoded input). Returns the reference's outcome.
template <class F>
auto sameOnEveryPath(const std::string& what, F&& query,
                     const std::function<std::string()>& context = {}) {
  static const std::vector<std::string> paths = availablePaths();
  auto reference = [&] {
    ScopedPath p("reference");
    return outcomeOf(query);
  }();
  for (const std::string& path : paths) {
    if (path == "reference") continue;
    ScopedPath p(path);
    if (!(outcomeOf(query) == reference))
      finding(what + ": path " + path + " disagrees with the reference path" +
              (context ? context() : std::string()));
  }
  return reference;
}

template <class R>
const R* resultOf(const Outcome<R>& o) {
  return std::get_if<R>(&o);
}

// A stream of up to 40 elements, each decoded by `make`.
template <class Stream, class Make>
Stream streamOf(Input& in, Make make) {
  Stream s;
  for (std::size_t i = 0, n = in.count(40); i < n; ++i) s.push(make(in));
  return s;
}

// A batch query that fills a list of indices and returns its count: the same on every path, and
// the count the list's size.
template <class Query>
void indices(const char* what, Query query, const std::function<std::string()>& context = {}) {
  sameOnEveryPath(
      what,
      [&] {
        std::vector<std::uint32_t> out;
        const std::size_t n = query(out);
        require(n == out.size(), std::string(what) + ": the count is not the list's size");
        return out;
      },
      context);
}

}  // namespace simdphys::fuzz

// simdphys core: errors, the execution path (scalar reference or a SIMD instruction set) and the
// aligned, padded streams that every batch kernel reads.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace simdphys {

namespace detail {
struct Snapshot;  // src/world/snapshot.cpp: saves and restores a World's members (snapshot.hpp)
}

// Every rejected input throws this, with a message saying what was wrong and where
// (function, element index, field).
class Error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A pair of object indices, a < b: what a broadphase reports.
struct Pair {
  std::uint32_t a, b;
  friend bool operator==(const Pair&, const Pair&) = default;
  friend auto operator<=>(const Pair&, const Pair&) = default;
};

// The index of no element: an ElementHit's (or ModelHit::triangle's) miss.
inline constexpr std::uint32_t kNoHit = ~0u;

// The first element a ray hits in a stream or a mesh (its index there: a box, a sphere, a
// triangle) and the distance along the ray: what the closest-hit queries answer
// (geometry3d/batch.hpp, mesh_bvh.hpp) on every path. A miss is index kNoHit, t = +inf.
struct ElementHit {
  std::uint32_t index = kNoHit;
  float t = std::numeric_limits<float>::infinity();
  bool hit() const { return index != kNoHit; }
};

// ---------------------------------------------------------------------------------------------
// Execution paths. "reference" is the scalar Eigen path; the others are the SIMD instruction
// sets the kernels were compiled for ("hwy_scalar" or "emu128" for the baseline without SIMD,
// "sse4", "avx2", "avx512", "avx512dl"), as far as this CPU supports them. The best one is chosen
// at start-up, or the one named by the environment variable SIMDPHYS_ISA.

// The paths this machine can run, best SIMD path first, "reference" last.
std::vector<std::string> availablePaths();
// The path in use now.
std::string activePath();
// Forces a path; throws Error if the name is unknown or this CPU lacks it.
void setPath(std::string_view name);
// True when the active path is the scalar reference.
bool referencePathActive();

// Sets a path for the lifetime of the guard and restores the previous one after.
class ScopedPath {
 public:
  explicit ScopedPath(std::string_view name) : previous_(activePath()) { setPath(name); }
  ~ScopedPath() { setPath(previous_); }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;

 private:
  std::string previous_;
};

// ---------------------------------------------------------------------------------------------
// Streams: one contiguous array per field, 64-byte aligned, padded to a multiple of kStreamPad
// elements so kernels of any width need no scalar tail. Padding holds a value chosen by the
// owning container so that padded lanes never produce a result (an empty box, a sphere of
// radius -inf).

inline constexpr std::size_t kStreamAlign = 64;
inline constexpr std::size_t kStreamPad = 16;  // the widest lane count: 16 floats (AVX-512)

constexpr std::size_t paddedSize(std::size_t n) {
  return (n + kStreamPad - 1) / kStreamPad * kStreamPad;
}

namespace detail {
// kStreamAlign-aligned memory. Blocks of 2 MiB or more are aligned to 2 MiB and offered to the
// kernel for transparent huge pages (Linux): one fault instead of 512, and fewer TLB misses, for
// the streams and trees that fill them once and then sweep them.
void* allocateAligned(std::size_t bytes);
void freeAligned(void* p, std::size_t bytes) noexcept;
}  // namespace detail

template <class T>
struct AlignedAllocator {
  static_assert(alignof(T) <= kStreamAlign, "AlignedAllocator aligns to kStreamAlign at least");
  using value_type = T;
  AlignedAllocator() = default;
  template <class U>
  AlignedAllocator(const AlignedAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(detail::allocateAligned(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { detail::freeAligned(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const AlignedAllocator<U>&) const {
    return true;
  }
};

template <class T>
using AlignedVector = std::vector<T, AlignedAllocator<T>>;

// One field of a stream: `size()` live elements followed by padding up to paddedSize(size()).
template <class T>
class Stream {
 public:
  Stream() = default;
  explicit Stream(T pad) : pad_(pad) {}

  std::size_t size() const { return size_; }
  std::size_t padded() const { return data_.size(); }
  T* data() { return data_.data(); }
  const T* data() const { return data_.data(); }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  std::span<const T> view() const { return {data_.data(), size_}; }
  std::span<T> view() { return {data_.data(), size_}; }

  void resize(std::size_t n) {
    data_.resize(paddedSize(n), pad_);
    for (std::size_t i = n; i < data_.size(); ++i) data_[i] = pad_;
    size_ = n;
  }
  void reserve(std::size_t n) { data_.reserve(paddedSize(n)); }
  void clear() { resize(0); }

 private:
  AlignedVector<T> data_;
  std::size_t size_ = 0;
  T pad_{};
};

}  // namespace simdphys

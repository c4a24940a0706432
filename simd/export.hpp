// The frame every kernel file shares. A kernel file is compiled once per target by
// hwy/foreach_target.h: its per-target code stands between SIMDPHYS_TARGET_BEGIN() and
// SIMDPHYS_TARGET_END() (the namespace simdphys::simd::HWY_NAMESPACE, compiled for that target,
// with `hn` naming Highway's ops), and its HWY_ONCE part defines each kernel declared in
// kernels.hpp with one SIMDPHYS_EXPORT line: after HWY_EXPORT(Target), `name` calls the chosen
// target's Target.
#pragma once

#include <hwy/highway.h>

#include <type_traits>

#define SIMDPHYS_TARGET_BEGIN() \
  HWY_BEFORE_NAMESPACE();       \
  namespace simdphys::simd {    \
  namespace HWY_NAMESPACE {     \
  namespace hn = hwy::HWY_NAMESPACE

#define SIMDPHYS_TARGET_END()      \
  } /* namespace HWY_NAMESPACE */  \
  } /* namespace simdphys::simd */ \
  HWY_AFTER_NAMESPACE()

#define SIMDPHYS_EXPORT(Target, name)                                               \
  HWY_EXPORT(Target);                                                               \
  const decltype(name) name([]() -> std::remove_const_t<decltype(name)>::Function { \
    return &HWY_DYNAMIC_DISPATCH(Target);                                           \
  })

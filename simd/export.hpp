// Defines a kernel declared in kernels.hpp from its per-target implementations: after
// HWY_EXPORT(Target), `name` calls the chosen target's Target. One line per kernel, in the
// HWY_ONCE part of the kernel's file.
#pragma once

#include <hwy/highway.h>

#include <type_traits>

#define SIMDPHYS_EXPORT(Target, name)                                               \
  HWY_EXPORT(Target);                                                               \
  const decltype(name) name([]() -> std::remove_const_t<decltype(name)>::Function { \
    return &HWY_DYNAMIC_DISPATCH(Target);                                           \
  })

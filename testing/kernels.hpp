// Test support: the SIMD kernels as the library calls them (simd/kernels.hpp), the streams seen
// through their kernel views, shapes as kernel queries, and the plain-loop baselines, for the
// tests that check a kernel directly and the benchmarks that time one. Internal: not installed.
#pragma once

#include "simd/kernels.hpp"
#include "src/views.hpp"

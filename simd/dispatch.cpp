// Which compiled Highway target HWY_DYNAMIC_DISPATCH calls. Highway's own mechanism picks the
// best supported target; forcing one goes through its test hook, which replaces the set of
// supported targets, so the real set is read once, before any forcing.
#include <hwy/highway.h>

#include "kernels.hpp"

namespace simdphys::simd {
namespace {

struct Target {
  std::int64_t bit;
  const char* name;
};

// Best first, as Highway orders its bits (lower bit = better target).
constexpr Target kTargets[] = {
    {HWY_AVX3_DL, "avx512dl"},  {HWY_AVX3, "avx512"}, {HWY_AVX2, "avx2"},
    {HWY_SSE4, "sse4"},         {HWY_SSSE3, "ssse3"}, {HWY_EMU128, "emu128"},
    {HWY_SCALAR, "hwy_scalar"},
};

std::int64_t realSupported() {
  static const std::int64_t bits = [] {
    hwy::SetSupportedTargetsForTest(0);
    return hwy::SupportedTargets() & HWY_TARGETS;
  }();
  return bits;
}

}  // namespace

std::vector<std::string> supportedTargets() {
  std::vector<std::string> names;
  for (const Target& t : kTargets)
    if (realSupported() & t.bit) names.emplace_back(t.name);
  return names;
}

bool selectTarget(const std::string& name) {
  for (const Target& t : kTargets) {
    if (name != t.name || !(realSupported() & t.bit)) continue;
    hwy::SetSupportedTargetsForTest(t.bit);
    hwy::GetChosenTarget().Update(hwy::SupportedTargets());
    return true;
  }
  return false;
}

}  // namespace simdphys::simd

// Aligned allocation for streams and trees, with transparent huge pages for large blocks.
#include <new>

#include "simdphys/core.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace simdphys::detail {
namespace {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr bool kHugePages = true;
#else
constexpr bool kHugePages = false;  // the large alignment would buy nothing
#endif
constexpr std::size_t kHugePage = std::size_t(2) << 20;

// From one huge page up. The alignment's slack (and the size's rounding up to it) is address
// space only: never touched, never backed.
std::size_t alignmentFor(std::size_t bytes) {
  return kHugePages && bytes >= kHugePage ? kHugePage : kStreamAlign;
}
}  // namespace

void* allocateAligned(std::size_t bytes) {
  const std::size_t align = alignmentFor(bytes);
  void* p = ::operator new(bytes, std::align_val_t(align));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: where huge pages are off or unavailable, the kernel uses small ones.
  if (align == kHugePage) madvise(p, bytes / kHugePage * kHugePage, MADV_HUGEPAGE);
#endif
  return p;
}

void freeAligned(void* p, std::size_t bytes) noexcept {
  ::operator delete(p, std::align_val_t(alignmentFor(bytes)));
}

}  // namespace simdphys::detail

#include "core/allocator_tuning.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__GLIBC__) && defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#endif

namespace homesh {
namespace {

std::atomic<bool> thresholds_set{false};

constexpr int kMmapThreshold = 64 << 20;
constexpr int kTrimThreshold = 256 << 20;

// The heap grown by kTrimThreshold at once (M_TOP_PAD, a block below the mmap
// threshold allocated and freed: the trim threshold keeps it) and that fresh range
// advised for transparent huge pages. False if the heap did not grow where it was
// (not contiguous: glibc went on in mmap'd memory) or madvise refused.
bool advise_heap() {
#if defined(__GLIBC__) && defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (mallopt(M_TOP_PAD, kTrimThreshold) != 1) return false;
  void* volatile probe = std::malloc(kMmapThreshold - (1 << 20));  // volatile: not elided
  std::free(probe);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  constexpr std::uintptr_t kHuge = 2 << 20;
  const std::uintptr_t a = (before + kHuge - 1) & ~(kHuge - 1), b = after & ~(kHuge - 1);
  return b > a && madvise(reinterpret_cast<void*>(a), b - a, MADV_HUGEPAGE) == 0;
#else
  return false;
#endif
}

}  // namespace

bool allocator_tuning_declined() {
  const char* env = std::getenv("HOMESH_MALLOC");
  return env && std::strcmp(env, "default") == 0;
}

const AllocatorTuning& tune_allocator() {
  static const AllocatorTuning applied = [] {
    AllocatorTuning t;
    if (allocator_tuning_declined()) return t;
#if defined(__GLIBC__)
    const char* env = std::getenv("HOMESH_MALLOC");
    t.thresholds = mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
                   mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
    if (t.thresholds && env && std::strcmp(env, "huge-pages") == 0) t.huge_pages = advise_heap();
#endif
    thresholds_set = t.thresholds;
    return t;
  }();
  return applied;
}

bool allocator_thresholds_set() { return thresholds_set; }

}  // namespace homesh

#include "core/allocator_tuning.h"

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace homesh {

bool tune_allocator() {
  static const bool applied = [] {
    const char* env = std::getenv("HOMESH_MALLOC");
    if (env && std::strcmp(env, "default") == 0) return false;
#if defined(__GLIBC__)
    constexpr int kMmapThreshold = 64 << 20;
    constexpr int kTrimThreshold = 256 << 20;
    return mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 &&
           mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
#else
    return false;
#endif
  }();
  return applied;
}

}  // namespace homesh

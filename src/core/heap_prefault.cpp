#include "core/heap_prefault.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include "core/allocator_tuning.h"
#include "core/huge_page_allocator.h"

#if defined(__GLIBC__) && defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace homesh {
namespace {

// Below this a fresh process's thread start costs more than it saves: on issue 16's
// corpus star4_nolayer_coarse at p = 2 (1 MiB) took 7.2 ms against 6.2; the range is
// populated by the caller at once instead. Below kSmallest nothing is done. 10 MiB, not
// 2: a helper thread's start on this 2-core VM's idle core sometimes took milliseconds
// (and the destructor waits for it): medians (max) of 8 alternated fresh runs, helper /
// at once: lshape_r02_nolayer p = 4 (3.4 MB) 13.0 (19.8) / 12.4 (12.8) ms, naca0012_voronoi
// p = 4 (8.5 MB) 22.9 (31.3) / 20.3 (21.6), circle_voronoi p = 4 18.3 (22.0) / 18.2 (19.2),
// star4_nolayer_coarse p = 4 18.0 (18.3) / 18.0 (18.6), lshape_r05_voronoi p = 5 21.9 (29.6)
// / 23.0 (23.6); from 15 MB on the helper was as fast or faster (circles6_nolayer p = 5,
// star1_bl_1e-3 p = 5).
constexpr std::size_t kLeast = std::size_t(10) << 20;
constexpr std::size_t kSmallest = std::size_t(64) << 10;
constexpr std::size_t kChunk = std::size_t(128) << 10;  // the stop is seen within one
#if defined(__linux__) && !defined(MADV_POPULATE_WRITE)
constexpr int MADV_POPULATE_WRITE = 23;
#endif

}  // namespace

HeapPrefault::HeapPrefault(std::size_t bytes) {
#if defined(__GLIBC__) && defined(__linux__)
  const bool small = bytes < kLeast;
  if (bytes < kSmallest || !allocator_thresholds_set() ||
      (!small && std::thread::hardware_concurrency() < 2))
    return;
  // The heap grown by `bytes` (not touched: malloc writes a chunk header, free another).
  void* volatile block = std::malloc(bytes);  // volatile: not elided
  if (!block) return;
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  std::free(block);
  const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));
  // Only a range of the main heap, which keeps it (glibc's brk heap, kept by the trim
  // threshold; fresh where the break moved, else a free chunk, perhaps resident already,
  // which costs the helper little), never memory mapped elsewhere (mmap'd chunks and
  // other allocators' arenas lie above the break).
  if (!(start + bytes <= brk)) return;
  const std::uintptr_t page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  const std::uintptr_t a = (start + page - 1) & ~(page - 1), b = (start + bytes) & ~(page - 1);
  if (b <= a) return;
  first_ = a;
  bytes_ = b - a;
  if (small) {  // populated here, at once: no thread to start, no 2 MiB page to zero
    if (madvise(reinterpret_cast<void*>(a), b - a, MADV_POPULATE_WRITE) == 0) done_ = b - a;
    return;
  }
  // In 2 MiB pages where the kernel has them (a hint; refused, 4 KiB ones): the helper
  // zeroes them, not the caller, and the run walks fewer page tables.
  advise_huge_pages(reinterpret_cast<void*>(a), b - a);
  helper_ = std::thread([this, a, b] {
    for (std::uintptr_t p = a; p < b && !stop_.load(std::memory_order_relaxed); p += kChunk) {
      const std::size_t len = std::size_t(std::min<std::uintptr_t>(kChunk, b - p));
      if (madvise(reinterpret_cast<void*>(p), len, MADV_POPULATE_WRITE) != 0) return;
      done_ += len;
    }
  });
#else
  (void)bytes;
#endif
}

HeapPrefault::~HeapPrefault() {
  stop_ = true;
  if (helper_.joinable()) helper_.join();
}

}  // namespace homesh

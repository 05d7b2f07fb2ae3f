#pragma once
// Fresh memory, faulted in ahead of its first use by another core.
//
// A process's first large run touches most of its memory for the first time, and
// each first touch of a 4 KiB page is a page fault: 10-14 us on the virtual machines
// this project runs on, where a curve run at p = 5 faults 1-4k pages (half its time
// in a fresh process: circle_voronoi 33 ms against 14 ms for a second run in the same
// process). HeapPrefault grows malloc's heap by `bytes` at once (a block allocated and
// freed: allocator_tuning.h's trim threshold keeps it) and populates that range's page
// tables from a helper thread (madvise MADV_POPULATE_WRITE, Linux 5.14: no byte of it
// written, so the allocations the caller makes there meanwhile are safe), while the
// caller goes on; what the caller reaches before the helper does, it faults in itself.
// The range's whole 2 MiB pages are advised for transparent huge pages first
// (core/huge_page_allocator.h; the advice stays on that part of the heap): the helper
// zeroes them, so the caller never waits on a fresh 2 MiB page, the cause of the 2-3x runs
// that ended HOMESH_MALLOC=huge-pages as the default (allocator_tuning.h). 18 curve runs of
// issue 16's corpus at p = 3-5, alternated fresh processes, medians of 2, against the 4 KiB
// pages: median 0.84x (circle_voronoi p = 5 0.75x, naca4412_a8_nolayer_fine p = 5 0.69x,
// flap_gap02_bl_1e-4 p = 3 1.01x), the slowest single run 1.07x the 4 KiB median; 12 small
// runs (p = 2-5, 543-3419 triangles) median 1.00x. The whole heap in huge pages
// (HOMESH_MALLOC=huge-pages) did as well there (0.82x), but for every stage and run size.
// The destructor stops the helper (within one 128 KiB chunk) and joins it.
//
// A no-op (active() false) where it cannot help or cannot be safe: without glibc's
// heap (a sanitizer's or valgrind's allocator: the block is not below the break), without
// MADV_POPULATE_WRITE (older kernels: the first madvise fails and the helper stops),
// where allocator_tuning.h's thresholds are not in place (tune_allocator() not called,
// as the CLI and the Python module do at start, or declined: the heap would be trimmed),
// or for less than 64 KiB. Below 10 MiB no thread is started (its start cost more than it
// saved: star4_nolayer_coarse p = 2, 1 MiB, 7.2 against 6.2 ms; heap_prefault.cpp has the
// 2-10 MiB runs): the range is populated by
// the constructor itself, one madvise for what would be a fault per page (ten small p = 2-3
// runs of the corpus, alternated fresh processes, medians of 6: 0.93x and 0.97x in two
// rounds, 19 of 20 faster); on one core a larger range gets nothing.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>

namespace homesh {

class HeapPrefault {
 public:
  explicit HeapPrefault(std::size_t bytes);
  ~HeapPrefault();
  HeapPrefault(const HeapPrefault&) = delete;
  HeapPrefault& operator=(const HeapPrefault&) = delete;

  /// Whether a helper was started.
  bool active() const { return helper_.joinable(); }
  /// Bytes populated so far, of the range [first(), first() + bytes()) (whole pages).
  std::size_t populated() const { return done_.load(); }
  std::uintptr_t first() const { return first_; }
  std::size_t bytes() const { return bytes_; }

 private:
  std::uintptr_t first_ = 0;
  std::size_t bytes_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> done_{0};
  std::thread helper_;
};

}  // namespace homesh

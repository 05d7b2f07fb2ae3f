#pragma once
// glibc's malloc returns freed blocks above its mmap threshold (128 KiB at the
// start, raised as such blocks are freed) and the free top of its heaps above
// its trim threshold to the kernel, and the next allocation of that size is
// fresh pages, each zeroed on its first touch. homesh's stages allocate and free
// the same sparse matrices, factors (CHOLMOD's copies and supernodes) and element
// buffers solve after solve, so on a virtual machine, where a page fault is
// dear, a third of a curving run went on faults: on issue 16's corpus (p = 4-5,
// best of five runs) lshape_r05_voronoi 0.25 -> 0.15 s, circle_nolayer_coarse
// 0.30 -> 0.20 s, naca0012_bl_1e-3_coarse 0.39 -> 0.27 s, circles6_bl_1e-3
// 0.53 -> 0.34 s, with the thresholds below.
//
// tune_allocator() raises the mmap threshold to 64 MiB and the trim threshold
// to 256 MiB (mallopt), once per process: freed memory up to those sizes stays
// in the process for the next solve (the resident size stays near its peak, as
// with most allocators other than glibc's).
//
// HOMESH_MALLOC=huge-pages also grows the heap by 256 MiB at once (M_TOP_PAD; not
// resident until touched) and advises that range for transparent huge pages (madvise
// MADV_HUGEPAGE, which Debian's default THP mode "madvise" asks for): 2 MiB per first
// fault, not 4 KiB. It was the default until 3 Dec 2026, chosen on the best of 2 fresh
// runs (circles6_bl_1e-3 p = 5 1.20 -> 0.63 s). Six fresh runs each on this project's VMs
// showed why best-of is the wrong measure here: with huge pages a run is the fastest
// (0.64 s) or takes 2-3x (2.1-2.6 s, two of six on circles6_bl_1e-3 p = 5; 2.2 s, one of six,
// on plate_holes_layers_1e-3 p = 5 with local=0.9), 65 % of it in the kernel's
// clear_page_erms (zeroing fresh 2 MiB pages; most likely pages the host has not backed yet). With
// the thresholds only: 0.73-0.93 s (mean 0.81 against 1.29) and 0.84-1.08 s (0.92 against 1.08);
// glibc's own settings 0.81-0.96 and 0.78-1.32. The same on the smaller runs (within the
// scatter) and on flap_gap02_bl_1e-4 p = 5 (4.5-5.2 s, 4.5-6.5 with huge pages).
//
// CHOLMOD's large blocks do get huge pages, one mapping each (fem/cholmod_memory.h).
//
// The CLI and the Python module call it at start; a C++ caller of the library
// may. HOMESH_MALLOC=default in the environment leaves glibc's settings alone,
// HOMESH_MALLOC=huge-pages adds the huge pages (no-huge-pages, or anything else: the
// thresholds only). A no-op off glibc, and
// under a sanitizer's or valgrind's allocator (mallopt refused, or the heap not
// grown).
namespace homesh {

struct AllocatorTuning {
  bool thresholds = false;  ///< the mmap and trim thresholds were set
  bool huge_pages = false;  ///< the heap range was advised for transparent huge pages
};

/// Applies the tuning above once (later calls return the first call's outcome).
const AllocatorTuning& tune_allocator();

/// Whether tune_allocator() has run and set the thresholds (asks, applies nothing).
bool allocator_thresholds_set();

/// Whether the environment declines homesh's allocator tuning (HOMESH_MALLOC=default):
/// tune_allocator's and fem/cholmod_memory.h's.
bool allocator_tuning_declined();

}  // namespace homesh

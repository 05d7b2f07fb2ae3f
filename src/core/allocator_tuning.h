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
// Then the first fault of every fresh page: a single curving in a fresh process
// (a script, the CLI, each run of issue 16's benchmark) touches most of its
// memory for the first time, and on this project's virtual machines a 4 KiB fault
// costs about 20 us (a 32 MB matrix copy took 0.18 s). tune_allocator() also grows
// the heap by 256 MiB at once (M_TOP_PAD; not resident until touched) and advises
// that range for transparent huge pages (madvise MADV_HUGEPAGE, which Debian's
// default THP mode "madvise" asks for): 2 MiB per fault. Fresh-process curving
// (best of 2), without -> with: circles6_bl_1e-3 p = 5 1.20 -> 0.63 s,
// naca9415_a5_bl_1e-3 p = 5 0.72 -> 0.47 s, plate_holes_layers_1e-3 p = 5 1.18 ->
// 0.70 s, naca0012_bl_1e-5_fine p = 3 0.77 -> 0.49 s; runs needing more than the
// range gain less (flap_gap02_bl_1e-4 p = 5, 380 MB: 7.9 -> 6.7 s).
//
// The CLI and the Python module call it at start; a C++ caller of the library
// may. HOMESH_MALLOC=default in the environment leaves glibc's settings alone,
// HOMESH_MALLOC=no-huge-pages sets the thresholds only. A no-op off glibc, and
// under a sanitizer's or valgrind's allocator (mallopt refused, or the heap not
// grown).
namespace homesh {

struct AllocatorTuning {
  bool thresholds = false;  ///< the mmap and trim thresholds were set
  bool huge_pages = false;  ///< the heap range was advised for transparent huge pages
};

/// Applies the tuning above once (later calls return the first call's outcome).
const AllocatorTuning& tune_allocator();

}  // namespace homesh

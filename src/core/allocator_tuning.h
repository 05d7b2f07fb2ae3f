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
// with most allocators other than glibc's). The CLI and the Python module call it
// at start; a C++ caller of the library may. HOMESH_MALLOC=default in the
// environment leaves glibc's settings alone. A no-op off glibc.
namespace homesh {

/// Applies the thresholds above once (later calls do nothing); returns whether
/// they were applied (false: HOMESH_MALLOC=default, not glibc, or mallopt refused).
bool tune_allocator();

}  // namespace homesh

#pragma once
// CHOLMOD's large blocks in transparent huge pages. A solve's CHOLMOD work is mostly
// fresh memory in a fresh process: its copy and transpose of the matrix and the
// supernodal factor (12 MB of the 29 MB a curving of circles6_nolayer at p = 5 first
// touches), and on this project's VMs a 4 KiB page costs 10-14 us on its first touch,
// a 2 MiB one about 150 us (2.2 ms where the host has not backed it yet): 5 ms a
// 2 MiB block in small pages against 0.15-2.2 ms in one.
//
// route_cholmod_memory() points SuiteSparse's allocation functions (SuiteSparse_config)
// at these: a block of 2 MiB or more is mapped on its own, 2 MiB aligned, and advised
// for transparent huge pages (madvise MADV_HUGEPAGE, which Debian's default THP mode
// "madvise" honours); freed, it is kept for the next request of its size (the next
// solve's factor), up to kKeptBytes in all, as core/allocator_tuning.h keeps glibc's
// freed memory; smaller blocks are malloc's. A block malloc gave (CHOLMOD memory of the
// process from before the routing) is freed and reallocated by malloc. Only large
// blocks: advising the whole heap (HOMESH_MALLOC=huge-pages) also gave 2 MiB pages to
// everything small, and runs of 2-3x in two of six.
//
// Measured (fresh processes, 10 each, medians): circles6_nolayer p = 5 128 -> 108 ms,
// star1_bl_1e-3 p = 5 160 -> 140 ms; circles6_bl_1e-3 p = 5 (many small solves) 79 ms
// either way.
//
// The CLI and the Python module route once at start, beside tune_allocator();
// HOMESH_MALLOC=default declines both. A no-op without CHOLMOD or off Linux.
#include <cstddef>

#include "core/huge_page_allocator.h"

namespace homesh {

/// Routes CHOLMOD's allocations as above, once per process; whether they are routed
/// (false without CHOLMOD, off Linux, or with HOMESH_MALLOC=default).
bool route_cholmod_memory();

/// The routed allocation functions themselves (usable without the routing; tests).
namespace cholmod_memory {

constexpr std::size_t kHugePage = kHugePageBytes;           ///< the smallest block mapped
constexpr std::size_t kKeptBytes = std::size_t{256} << 20;  ///< freed blocks kept at most

void* allocate(std::size_t bytes);
void* allocate_zeroed(std::size_t count, std::size_t size);
void* reallocate(void* p, std::size_t bytes);
void release(void* p);

struct Stats {
  std::size_t mapped_blocks = 0;  ///< large blocks in use
  std::size_t kept_blocks = 0;    ///< freed large blocks kept for reuse
  std::size_t kept_bytes = 0;
};
Stats stats();

}  // namespace cholmod_memory
}  // namespace homesh

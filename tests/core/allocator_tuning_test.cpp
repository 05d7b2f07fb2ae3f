// The allocator tuning (core/allocator_tuning.h): applied on glibc unless the
// environment says HOMESH_MALLOC=default (or a sanitizer's allocator refuses), and
// once; the heap advised for transparent huge pages only where HOMESH_MALLOC=huge-pages asks
// and the kernel has them.
#include "core/allocator_tuning.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "core/sanitizers.h"

namespace {

// Whether a [heap] mapping of this process carries the huge-page advice ("hg").
bool heap_advised() {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool in_heap = false;
  while (std::getline(smaps, line)) {
    if (line.find('-') != std::string::npos && line.find(' ') != std::string::npos &&
        line.find(':') > line.find(' '))
      in_heap = line.find("[heap]") != std::string::npos;  // a mapping's header line
    if (in_heap && line.rfind("VmFlags:", 0) == 0 && line.find(" hg") != std::string::npos)
      return true;
  }
  return false;
}

}  // namespace

TEST_CASE("allocator tuning: applied on glibc unless HOMESH_MALLOC=default", "[core]") {
  const char* env = std::getenv("HOMESH_MALLOC");
  const bool declined = env && std::strcmp(env, "default") == 0;
  const bool huge = env && std::strcmp(env, "huge-pages") == 0;
#if defined(__GLIBC__)
  // ASan's allocator refuses mallopt.
  const bool expected = !declined && !homesh::kAddressSanitizer;
#else
  const bool expected = false;
  (void)declined;
#endif
  const homesh::AllocatorTuning& t = homesh::tune_allocator();
  CHECK(t.thresholds == expected);
  CHECK(homesh::allocator_thresholds_set() == expected);
  CHECK(&homesh::tune_allocator() == &t);  // once: the same answer, nothing redone
#if defined(__linux__)
  // Kernels built with transparent huge pages take the advice in any mode.
  const bool thp = std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
  CHECK(t.huge_pages == (expected && thp && huge));
  // Advised where the tuning says so. (Not the converse: core/heap_prefault.h advises the
  // ranges it populates, and a test of it may have run first in this process.)
  if (t.huge_pages) CHECK(heap_advised());
#else
  CHECK(!t.huge_pages);
  (void)huge;
#endif
}

// The huge-page allocator and advice (core/huge_page_allocator.h): large vectors start
// on a 2 MiB boundary and small ones on a cache line; the advice covers exactly the
// whole 2 MiB pages inside a range, and the kernel keeps it (/proc/self/smaps).
#include "core/huge_page_allocator.h"

#include <sys/mman.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "huge_page_advice.h"

using namespace homesh;
using namespace homesh::core_test;

namespace {

constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;

}  // namespace

TEST_CASE("huge pages: vectors aligned by size", "[core]") {
  HugeVector<double> big(3 << 18);  // 6 MiB
  HugeVector<double> small(100);
  CHECK(reinterpret_cast<std::uintptr_t>(big.data()) % kHuge == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(small.data()) % 64 == 0);
  big.back() = small.back() = 1.0;
  CHECK(big.back() + small.back() == 2.0);
}

TEST_CASE("huge pages: the advice covers the whole 2 MiB pages inside the range", "[core]") {
  // A fresh mapping, 2 MiB aligned within: heap memory may carry an earlier test's advice.
  void* mapping =
      mmap(nullptr, 9 * kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  REQUIRE(mapping != MAP_FAILED);
  const auto base = (reinterpret_cast<std::uintptr_t>(mapping) + kHuge - 1) & ~(kHuge - 1);
  void* block = reinterpret_cast<void*>(base);
  // No whole page inside: nothing advised.
  CHECK_FALSE(advise_huge_pages(reinterpret_cast<void*>(base + 4096), kHuge));
  CHECK_FALSE(advise_huge_pages(block, kHuge - 1));
#if defined(__linux__)
  // From mid-page 1 to mid-page 4: pages 2 and 3 only.
  const bool ok = advise_huge_pages(reinterpret_cast<void*>(base + kHuge + 4096), 3 * kHuge);
  CHECK(ok == thp_kernel());
  if (ok) {
    CHECK_FALSE(advised(base + kHuge));
    CHECK(advised(base + 2 * kHuge));
    CHECK(advised(base + 3 * kHuge + kHuge - 1));
    CHECK_FALSE(advised(base + 4 * kHuge));
  }
#endif
  munmap(mapping, 9 * kHuge);
}

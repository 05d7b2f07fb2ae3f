// core/heap_prefault.h: the heap grown and its pages made resident by the helper,
// without a byte of what the caller writes there meanwhile changed; small sizes made
// resident at once, without a thread; nothing where glibc's heap is not the allocator's.
#include "core/heap_prefault.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <thread>
#include <vector>

#include "core/allocator_tuning.h"
#include "core/sanitizers.h"
#include "huge_page_advice.h"

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>

namespace {

// How many pages of the prefault's range are not resident (mincore), or -1.
long prefault_pages_not_resident(const homesh::HeapPrefault& prefault) {
  const std::size_t page = std::size_t(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> resident(prefault.bytes() / page);
  if (mincore(reinterpret_cast<void*>(prefault.first()), prefault.bytes(), resident.data()) != 0)
    return -1;
  long missing = 0;
  for (unsigned char r : resident) missing += (r & 1) == 0;
  return missing;
}

}  // namespace
#endif

TEST_CASE("heap prefault: the grown heap resident, the data written meanwhile intact", "[core]") {
  const homesh::AllocatorTuning& tuning = homesh::tune_allocator();
  CHECK_FALSE(homesh::HeapPrefault(std::size_t(1) << 20).active());  // too small for a thread
  CHECK_FALSE(homesh::HeapPrefault(std::size_t(8) << 20).active());  // populated at once
  constexpr std::size_t kBytes = std::size_t(24) << 20;
  homesh::HeapPrefault prefault(kBytes);
#if defined(__GLIBC__) && defined(__linux__)
  const bool expected =
      tuning.thresholds && !homesh::kAddressSanitizer && std::thread::hardware_concurrency() >= 2;
  CHECK(prefault.active() == expected);
#else
  (void)tuning;
#endif
  if (!prefault.active()) return;
  const long page = sysconf(_SC_PAGESIZE);
  CHECK(prefault.bytes() + 2 * std::size_t(page) >= kBytes);
  CHECK(prefault.first() % std::uintptr_t(page) == 0);
  // Its whole 2 MiB pages advised for transparent huge pages, where the kernel has them.
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const std::uintptr_t huge_first = (prefault.first() + kHuge - 1) & ~(kHuge - 1);
  CHECK(homesh::core_test::advised(huge_first) == homesh::core_test::thp_kernel());
  CHECK(homesh::core_test::advised(huge_first + kHuge) == homesh::core_test::thp_kernel());
  // A block allocated and filled while the helper runs, where the freed range was (glibc
  // gives the freed chunk back), not one byte of it changed by the population.
  constexpr std::size_t kBlock = kBytes - (std::size_t(1) << 20);
  auto* block = static_cast<unsigned char*>(std::malloc(kBlock));
  REQUIRE(block);
  const auto at = reinterpret_cast<std::uintptr_t>(block);
  CHECK(at >= prefault.first() - std::uintptr_t(page));
  CHECK(at < prefault.first() + prefault.bytes());
  for (std::size_t i = 0; i < kBlock; ++i) block[i] = static_cast<unsigned char>(i * 7 + 1);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (prefault.populated() < prefault.bytes() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  REQUIRE(prefault.populated() == prefault.bytes());
  CHECK(prefault_pages_not_resident(prefault) == 0);  // every page of the range
  std::size_t changed = 0;
  for (std::size_t i = 0; i < kBlock; ++i)
    changed += block[i] != static_cast<unsigned char>(i * 7 + 1);
  CHECK(changed == 0);
  std::free(block);
}

TEST_CASE("heap prefault: a small range resident at once, without a thread; a tiny one left",
          "[core]") {
  const homesh::AllocatorTuning& tuning = homesh::tune_allocator();
  CHECK(homesh::HeapPrefault(std::size_t(32) << 10).bytes() == 0);  // below 64 KiB: nothing
  const homesh::HeapPrefault prefault(std::size_t(1) << 20);
  CHECK_FALSE(prefault.active());
#if defined(__GLIBC__) && defined(__linux__)
  if (!tuning.thresholds || homesh::kAddressSanitizer) {
    CHECK(prefault.bytes() == 0);
    return;
  }
  const long page = sysconf(_SC_PAGESIZE);
  CHECK(prefault.bytes() + 2 * std::size_t(page) >= std::size_t(1) << 20);
  // Populated before the constructor returned: every page resident.
  REQUIRE(prefault.populated() == prefault.bytes());
  CHECK(prefault_pages_not_resident(prefault) == 0);
#else
  (void)tuning;
#endif
}

#pragma once
// A std::allocator that asks the kernel for transparent huge pages (2 MiB)
// for large arrays: the fast-marching engine reads its per-node arrays (tens
// to hundreds of MB on a 2000 x 2000 grid) at 2D neighbours, a grid row
// apart, and with 4 KiB pages nearly every such read misses the TLB. Where
// the kernel does not give huge pages on request (transparent_hugepage
// "never"), or the array is small, it is an ordinary allocation (aligned to
// a cache line).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace homesh {

/// A transparent huge page (x86-64, arm64 with 4 KiB base pages).
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// bytes rounded up to whole huge pages.
inline constexpr std::size_t whole_huge_pages(std::size_t bytes) {
  return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

/// Advises the whole 2 MiB pages inside [p, p + bytes) for transparent huge pages,
/// for an array allocated but not yet touched (a large malloc block is fresh pages in a
/// fresh process); true if some range was advised. A hint: pages already touched keep
/// their size.
inline bool advise_huge_pages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = kHugePageBytes;
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t a = (begin + kHuge - 1) & ~(kHuge - 1), b = (begin + bytes) & ~(kHuge - 1);
  return b > a && madvise(reinterpret_cast<void*>(a), b - a, MADV_HUGEPAGE) == 0;
#else
  (void)p;
  (void)bytes;
  return false;
#endif
}

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kHuge = kHugePageBytes;
  /// Smaller arrays start on a cache line.
  static constexpr std::size_t kLine = alignof(T) > 64 ? alignof(T) : 64;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHuge) return static_cast<T*>(::operator new(bytes, std::align_val_t(kLine)));
    const std::size_t rounded = whole_huge_pages(bytes);
    void* p = std::aligned_alloc(kHuge, rounded);
    if (!p) throw std::bad_alloc();
    advise_huge_pages(p, rounded);  // a hint: refused, 4 KiB pages
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHuge)
      ::operator delete(p, std::align_val_t(kLine));
    else
      std::free(p);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept {
    return false;
  }
};

/// A std::vector in huge pages once it is large.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace homesh

#include "fem/cholmod_memory.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "core/allocator_tuning.h"

#if defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#define HOMESH_MAPPED_BLOCKS 1
#endif

#ifdef HOMESH_WITH_CHOLMOD
#include <SuiteSparse_config.h>
#endif

namespace homesh {
namespace cholmod_memory {
namespace {

struct Block {
  void* p;
  std::size_t bytes;
};

// The large blocks in use (by address) and the freed ones kept, oldest first.
struct Registry {
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> mapped;
  std::vector<Block> kept;
  std::size_t kept_bytes = 0;
};

Registry& block_registry() {
  static Registry* r = new Registry;  // never destroyed: CHOLMOD may free at exit
  return *r;
}

#if defined(HOMESH_MAPPED_BLOCKS)
// A fresh mapping of `bytes` (a multiple of kHugePage) at a kHugePage boundary, advised
// for huge pages; nullptr if the kernel refuses.
void* map_block(std::size_t bytes) {
  const std::size_t span = bytes + kHugePage;
  void* m = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) return nullptr;
  char* const start = static_cast<char*>(m);
  char* const p = reinterpret_cast<char*>(
      (reinterpret_cast<std::uintptr_t>(start) + kHugePage - 1) & ~std::uintptr_t{kHugePage - 1});
  if (p > start) munmap(start, static_cast<std::size_t>(p - start));
  char* const end = start + span;
  if (end > p + bytes) munmap(p + bytes, static_cast<std::size_t>(end - (p + bytes)));
  advise_huge_pages(p, bytes);  // a hint: refused, the block has small pages
  return p;
}
#endif

}  // namespace

void* allocate(std::size_t bytes) {
#if defined(HOMESH_MAPPED_BLOCKS)
  if (bytes < kHugePage) return std::malloc(bytes);
  const std::size_t need = whole_huge_pages(bytes);
  Registry& r = block_registry();
  {
    // The smallest kept block that fits and wastes at most its half.
    std::lock_guard<std::mutex> lock(r.mutex);
    auto best = r.kept.end();
    for (auto it = r.kept.begin(); it != r.kept.end(); ++it)
      if (it->bytes >= need && it->bytes <= 2 * need &&
          (best == r.kept.end() || it->bytes < best->bytes))
        best = it;
    if (best != r.kept.end()) {
      const Block b = *best;
      r.kept.erase(best);
      r.kept_bytes -= b.bytes;
      r.mapped.emplace(b.p, b.bytes);
      return b.p;
    }
  }
  void* p = map_block(need);
  if (!p) return nullptr;
  std::lock_guard<std::mutex> lock(r.mutex);
  r.mapped.emplace(p, need);
  return p;
#else
  return std::malloc(bytes);
#endif
}

void* allocate_zeroed(std::size_t count, std::size_t size) {
  if (size != 0 && count > std::numeric_limits<std::size_t>::max() / size) return nullptr;
  const std::size_t bytes = count * size;
  if (bytes < kHugePage) return std::calloc(count, size);
  void* p = allocate(bytes);
  if (p) std::memset(p, 0, bytes);  // a kept block holds its last user's data
  return p;
}

void release(void* p) {
  if (!p) return;
#if defined(HOMESH_MAPPED_BLOCKS)
  Registry& r = block_registry();
  std::vector<Block> unmap;
  {
    std::lock_guard<std::mutex> lock(r.mutex);
    const auto it = r.mapped.find(p);
    if (it == r.mapped.end()) {
      std::free(p);
      return;
    }
    r.kept.push_back({p, it->second});
    r.kept_bytes += it->second;
    r.mapped.erase(it);
    while (r.kept_bytes > kKeptBytes) {  // the oldest go back to the kernel
      unmap.push_back(r.kept.front());
      r.kept_bytes -= r.kept.front().bytes;
      r.kept.erase(r.kept.begin());
    }
  }
  for (const Block& b : unmap) munmap(b.p, b.bytes);
#else
  std::free(p);
#endif
}

void* reallocate(void* p, std::size_t bytes) {
  if (!p) return allocate(bytes);
#if defined(HOMESH_MAPPED_BLOCKS)
  std::size_t old = 0;
  {
    Registry& r = block_registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    const auto it = r.mapped.find(p);
    if (it != r.mapped.end()) old = it->second;
  }
  if (old == 0 && bytes < kHugePage) return std::realloc(p, bytes);
  if (old >= bytes) return p;  // a mapped block shrinks in place
  const std::size_t have = old > 0 ? old : malloc_usable_size(p);
  void* q = allocate(bytes);
  if (!q) return nullptr;  // p stays valid, as realloc's
  std::memcpy(q, p, std::min(have, bytes));
  release(p);
  return q;
#else
  return std::realloc(p, bytes);
#endif
}

Stats stats() {
  Registry& r = block_registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return {r.mapped.size(), r.kept.size(), r.kept_bytes};
}

}  // namespace cholmod_memory

bool route_cholmod_memory() {
  static const bool routed = [] {
    if (allocator_tuning_declined()) return false;
#if defined(HOMESH_WITH_CHOLMOD) && defined(HOMESH_MAPPED_BLOCKS)
    SuiteSparse_config.malloc_func = cholmod_memory::allocate;
    SuiteSparse_config.calloc_func = cholmod_memory::allocate_zeroed;
    SuiteSparse_config.realloc_func = cholmod_memory::reallocate;
    SuiteSparse_config.free_func = cholmod_memory::release;
    return true;
#else
    return false;
#endif
  }();
  return routed;
}

}  // namespace homesh

#pragma once
// What the kernel says of this process's huge-page advice (/proc/self/smaps), for the
// tests of core/huge_page_allocator.h and core/heap_prefault.h.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

namespace homesh::core_test {

// Whether the mapping holding address a carries the huge-page advice ("hg").
inline bool advised(std::uintptr_t a) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool in = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      in = lo <= a && a < hi;
      continue;
    }
    if (in && line.rfind("VmFlags:", 0) == 0) return line.find(" hg") != std::string::npos;
  }
  return false;
}

inline bool thp_kernel() {
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

}  // namespace homesh::core_test

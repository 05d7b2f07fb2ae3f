// The allocator thresholds (core/allocator_tuning.h): applied on glibc unless the
// environment says HOMESH_MALLOC=default (or a sanitizer's allocator refuses), and once.
#include "core/allocator_tuning.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

#include "core/sanitizers.h"

TEST_CASE("allocator tuning: applied on glibc unless HOMESH_MALLOC=default", "[core]") {
  const char* env = std::getenv("HOMESH_MALLOC");
  const bool declined = env && std::strcmp(env, "default") == 0;
#if defined(__GLIBC__)
  // ASan's allocator refuses mallopt.
  const bool expected = !declined && !homesh::kAddressSanitizer;
#else
  const bool expected = false;
  (void)declined;
#endif
  CHECK(homesh::tune_allocator() == expected);
  CHECK(homesh::tune_allocator() == expected);  // once: the same answer, nothing redone
}

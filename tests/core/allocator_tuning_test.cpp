// The allocator thresholds (core/allocator_tuning.h): applied on glibc unless the
// environment says HOMESH_MALLOC=default (or a sanitizer's allocator refuses), and once.
#include "core/allocator_tuning.h"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>

TEST_CASE("allocator tuning: applied on glibc unless HOMESH_MALLOC=default", "[core]") {
  const char* env = std::getenv("HOMESH_MALLOC");
  const bool declined = env && std::strcmp(env, "default") == 0;
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HOMESH_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(HOMESH_TEST_ASAN)
  const bool expected = false;  // ASan's allocator refuses mallopt
  (void)declined;
#elif defined(__GLIBC__)
  const bool expected = !declined;
#else
  const bool expected = false;
#endif
  CHECK(homesh::tune_allocator() == expected);
  CHECK(homesh::tune_allocator() == expected);  // once: the same answer, nothing redone
}

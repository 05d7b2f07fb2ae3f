#pragma once
// Whether this build runs under AddressSanitizer (gcc defines __SANITIZE_ADDRESS__,
// clang answers __has_feature): its allocator refuses address-space limits (the
// Gmsh child's RLIMIT_AS) and mallopt (core/allocator_tuning.h).
#if defined(__SANITIZE_ADDRESS__)
#define HOMESH_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HOMESH_ASAN 1
#endif
#endif

namespace homesh {

#if defined(HOMESH_ASAN)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

}  // namespace homesh

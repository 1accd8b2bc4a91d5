#pragma once
// Which sanitizers this translation unit is built with, as macros (for #if) and as constants: g++
// defines __SANITIZE_ADDRESS__ and __SANITIZE_THREAD__, clang answers __has_feature.
//   CATPLAN_ASAN             AddressSanitizer
//   CATPLAN_MALLOC_REPLACED  a sanitizer with its own malloc (address, thread or memory)

#if defined(__SANITIZE_ADDRESS__)
#define CATPLAN_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CATPLAN_ASAN 1
#endif
#endif

#if defined(CATPLAN_ASAN) || defined(__SANITIZE_THREAD__)
#define CATPLAN_MALLOC_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define CATPLAN_MALLOC_REPLACED 1
#endif
#endif

namespace catplan {

#ifdef CATPLAN_ASAN
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

#ifdef CATPLAN_MALLOC_REPLACED
inline constexpr bool kMallocReplaced = true;
#else
inline constexpr bool kMallocReplaced = false;
#endif

} // namespace catplan

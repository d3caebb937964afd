// Which sanitizer a build has (GCC's and Clang's ways of saying so), for the code that works
// around their allocators: LUMEN_ASAN and LUMEN_TSAN are 1 or 0.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define LUMEN_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LUMEN_ASAN 1
#endif
#endif
#ifndef LUMEN_ASAN
#define LUMEN_ASAN 0
#endif

#if defined(__SANITIZE_THREAD__)
#define LUMEN_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define LUMEN_TSAN 1
#endif
#endif
#ifndef LUMEN_TSAN
#define LUMEN_TSAN 0
#endif

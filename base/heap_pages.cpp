#include "base/heap_pages.hpp"

#include <cstdint>
#include <cstdlib>

#include <sys/mman.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "base/huge_pages.hpp"
#include "base/sanitizers.hpp"

#ifndef MADV_COLLAPSE
#define MADV_COLLAPSE 25  // Linux 6.1; older kernels refuse it, which costs nothing
#endif

// Sanitizers bring their own allocator: glibc's arenas are not there to tune.
#if defined(__GLIBC__) && !LUMEN_ASAN && !LUMEN_TSAN
#define LUMEN_TUNE_GLIBC_HEAP 1
#else
#define LUMEN_TUNE_GLIBC_HEAP 0
#endif

namespace lumen {

void grow_heaps_for_huge_pages() {
#if LUMEN_TUNE_GLIBC_HEAP
    mallopt(M_TOP_PAD, 16 << 20);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
#endif
}

void back_thread_heap_with_huge_pages() {
#if LUMEN_TUNE_GLIBC_HEAP
    constexpr uintptr_t kArenaSize = uintptr_t(64) << 20;  // glibc's HEAP_MAX_SIZE on 64 bits
    void* probe = std::malloc(1);  // makes the thread's arena, whose header it follows
    if (!probe) return;
    void* arena = reinterpret_cast<void*>(reinterpret_cast<uintptr_t>(probe) & ~(kArenaSize - 1));
    if (madvise(arena, kArenaSize, MADV_HUGEPAGE) == 0) madvise(arena, kHugePage, MADV_COLLAPSE);
    std::free(probe);
#endif
}

}  // namespace lumen

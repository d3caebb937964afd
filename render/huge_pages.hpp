// An allocator that asks the kernel for 2 MiB pages (transparent huge pages, madvise) for
// arrays of 4 MiB or more: a big mesh's per-triangle data, read once per ray at a scattered
// triangle, would otherwise cost a TLB miss on most reads (Embree's own BVH is allocated the
// same way). Smaller arrays come from malloc as usual.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace lumen::render {

template <class T> struct HugePages {
    using value_type = T;
    static constexpr size_t kPage = size_t(2) << 20, kFrom = 2 * kPage;

    HugePages() = default;
    template <class U> HugePages(const HugePages<U>&) {}

    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        void* p = bytes >= kFrom ? std::aligned_alloc(kPage, (bytes + kPage - 1) & ~(kPage - 1))
                                 : std::malloc(bytes);
        if (!p) throw std::bad_alloc();
        if (bytes >= kFrom) madvise(p, bytes, MADV_HUGEPAGE);  // a hint: failure is harmless
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t) { std::free(p); }
    template <class U> bool operator==(const HugePages<U>&) const { return true; }
};

}  // namespace lumen::render

// Memory the kernel may back with 2 MiB pages (transparent huge pages, madvise mode). On the
// virtual machines lumen is measured on a 4 KiB page fault costs about 14 us, so memory that a
// run fills quickly and keeps is cheaper in huge pages: a big mesh's per-triangle data (read at
// scattered triangles, where 4 KiB pages would also cost a TLB miss on most reads; Embree
// allocates its BVH the same way) and the syntax tree's nodes (parser/node_pool.cpp).
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace lumen {

inline constexpr size_t kHugePage = size_t(2) << 20;

// `bytes` rounded up to whole huge pages, aligned to one, with the kernel asked to back them
// with huge pages (a hint: where it cannot, they are ordinary pages). Freed with std::free.
inline void* allocate_huge_pages(size_t bytes) {
    bytes = (bytes + kHugePage - 1) & ~(kHugePage - 1);
    void* p = std::aligned_alloc(kHugePage, bytes);
    if (!p) throw std::bad_alloc();
    madvise(p, bytes, MADV_HUGEPAGE);
    return p;
}

// An allocator for arrays: 4 MiB or more in huge pages, smaller ones from malloc as usual.
template <class T> struct HugePages {
    using value_type = T;
    static constexpr size_t kFrom = 2 * kHugePage;

    HugePages() = default;
    template <class U> HugePages(const HugePages<U>&) {}

    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        void* p = bytes >= kFrom ? allocate_huge_pages(bytes) : std::malloc(bytes);
        if (!p) throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t) { std::free(p); }
    template <class U> bool operator==(const HugePages<U>&) const { return true; }
};

}  // namespace lumen

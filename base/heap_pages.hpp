// The malloc heap of the thread that parses, evaluates and builds the scene, backed by 2 MiB
// pages (transparent huge pages, madvise mode). On the virtual machines lumen is measured on a
// 4 KiB page fault costs 10-14 us, and that thread fills a few MB (the 15 standard includes)
// to hundreds (a big mesh) in small blocks and keeps them: at 4 KiB a page, `lumen --check`
// of the standard includes spent a fifth of its time in 560 faults of its heap.
#pragma once

namespace lumen {

// Process-wide, before the thread starts: glibc grows each heap 16 MiB at a time (so that a
// whole 2 MiB range is writable when first touched, which a huge page needs) and serves blocks
// of up to 32 MiB from the heap rather than from their own mappings (where glibc's adaptive
// threshold ends anyway, but without the 4 KiB-paged blocks it makes on the way).
void grow_heaps_for_huge_pages();

// First thing on a new thread: its glibc arena (64 MiB of address space aligned to its size,
// that starts with the arena's header) may be backed by huge pages, and its first 2 MiB, whose
// header page is already mapped in 4 KiB pages, is collapsed into one. A hint: where the kernel
// has no huge pages or another allocator serves malloc, nothing changes but the speed.
void back_thread_heap_with_huge_pages();

}  // namespace lumen

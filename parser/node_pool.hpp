// Where syntax-tree nodes live: fixed-size slots in 2 MiB slabs in huge pages, recycled
// through a free list. A run's tree is a few MB of ~100-byte nodes made in a burst, which from
// malloc cost a 4 KiB page fault per 40 nodes; in huge pages it is one fault per slab
// (`lumen --check` of the 15 standard includes: 39 -> 29 ms, page faults 1430 -> 760).
// Slabs are kept for the rest of the run: a later frame's tree reuses the slots. Builds with
// AddressSanitizer use the ordinary heap, so that it still checks every node.
#pragma once
#include <cstddef>

namespace lumen::ast {

void* allocate_node_slot(std::size_t size);
void free_node_slot(void* slot, std::size_t size) noexcept;  // size as allocated

}  // namespace lumen::ast

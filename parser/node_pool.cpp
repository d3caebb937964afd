#include "parser/node_pool.hpp"

#include <mutex>
#include <new>

#include "base/huge_pages.hpp"
#include "base/sanitizers.hpp"
#include "parser/ast.hpp"

// AddressSanitizer builds keep nodes on the heap, where it checks them.
#define LUMEN_NODE_POOL (!LUMEN_ASAN)

namespace lumen::ast {
namespace {

constexpr std::size_t kSlot = (sizeof(Node) + alignof(Node) - 1) / alignof(Node) * alignof(Node);
static_assert(kSlot >= sizeof(void*));

// One pool for every thread (trees are built by the interpreter's thread; tests build them
// on others): a mutex is cheap next to what a node costs to fill.
struct Pool {
    std::mutex mutex;
    void* free = nullptr;  // a freed slot, whose first word points to the next one
    char* next = nullptr;  // the current slab's first unused slot
    char* end = nullptr;
};

Pool& pool() {
    static Pool* p = new Pool;  // never destroyed: nodes may be freed during static teardown
    return *p;
}

}  // namespace

void* allocate_node_slot(std::size_t size) {
    if (!LUMEN_NODE_POOL || size != sizeof(Node)) return ::operator new(size);
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    if (p.free) {
        void* slot = p.free;
        p.free = *static_cast<void**>(slot);
        return slot;
    }
    if (p.next == p.end) {
        p.next = static_cast<char*>(allocate_huge_pages(kHugePage));
        p.end = p.next + kHugePage / kSlot * kSlot;
    }
    void* slot = p.next;
    p.next += kSlot;
    return slot;
}

void free_node_slot(void* slot, std::size_t size) noexcept {
    if (!slot) return;
    if (!LUMEN_NODE_POOL || size != sizeof(Node)) return ::operator delete(slot);
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    *static_cast<void**>(slot) = p.free;
    p.free = slot;
}

}  // namespace lumen::ast

// An allocator whose value-initialisation is default-initialisation: resize() of a buffer of
// numbers leaves them unwritten instead of zeroing them. Large output buffers are filled
// completely right after, by several threads; zeroing first doubled the memory traffic and
// took every page fault on one thread (~20 ms of an 800x600 write).
#pragma once
#include <memory>
#include <new>
#include <utility>

namespace lumen::render {

template <class T>
struct DefaultInit : std::allocator<T> {
    using std::allocator<T>::allocator;
    template <class U>
    struct rebind {
        using other = DefaultInit<U>;
    };
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

}  // namespace lumen::render

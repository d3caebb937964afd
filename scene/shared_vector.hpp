// A vector that copies of its owner share until one of them writes (copy on write). A mesh's
// vertices and faces are the bulk of a scene that copies it: `mesh { Declared_Mesh translate
// ... }` a hundred times (mesh_camera scenes do) would otherwise hold a hundred copies, as
// POV-Ray does not. Readers see a const std::vector; writers call edit() (or push_back),
// which copies the elements first when another owner shares them. A reference edit() returns
// must not be kept past a copy of the owner.
#pragma once
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

namespace lumen::scene {

template <class T> class SharedVector {
public:
    SharedVector() = default;
    SharedVector(std::vector<T> v) : p_(std::make_shared<std::vector<T>>(std::move(v))) {}
    SharedVector(std::initializer_list<T> l) : SharedVector(std::vector<T>(l)) {}

    const std::vector<T>& get() const { return p_ ? *p_ : none(); }
    operator const std::vector<T>&() const { return get(); }
    size_t size() const { return get().size(); }
    bool empty() const { return get().empty(); }
    const T& operator[](size_t i) const { return (*p_)[i]; }
    const T& front() const { return get().front(); }
    const T& back() const { return get().back(); }
    const T* data() const { return get().data(); }
    auto begin() const { return get().begin(); }
    auto end() const { return get().end(); }

    // The elements to write, this owner's alone from here on.
    std::vector<T>& edit() {
        if (!p_)
            p_ = std::make_shared<std::vector<T>>();
        else if (p_.use_count() > 1)
            p_ = std::make_shared<std::vector<T>>(*p_);
        return *p_;
    }
    void push_back(T v) { edit().push_back(std::move(v)); }
    // Where the elements live: owners that share them give the same answer (empty: null).
    const void* identity() const { return p_ && !p_->empty() ? p_.get() : nullptr; }

private:
    static const std::vector<T>& none() {
        static const std::vector<T> empty;
        return empty;
    }
    std::shared_ptr<std::vector<T>> p_;
};

}  // namespace lumen::scene

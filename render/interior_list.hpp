// The list of interiors a ray is inside (POV-Ray 3.7's rules), in a fixed array so that
// spawning rays never allocates.
#pragma once
#include "scene/texture.hpp"

namespace lumen::render {

class InteriorList {
public:
    static constexpr int kCapacity = 24;
    struct Entry {
        const void* id;
        const scene::Interior* interior;
        bool hollow;  // the owner is `hollow`: fog and media still act inside it
    };

    InteriorList() = default;
    // Copies only the used entries: lists are copied for every secondary and shadow ray.
    InteriorList(const InteriorList& o) : size_(o.size_) {
        for (int i = 0; i < size_; ++i) entries_[i] = o.entries_[i];
    }
    InteriorList& operator=(const InteriorList& o) {
        size_ = o.size_;
        for (int i = 0; i < size_; ++i) entries_[i] = o.entries_[i];
        return *this;
    }

    bool empty() const { return size_ == 0; }
    int size() const { return size_; }
    const Entry& operator[](int i) const { return entries_[i]; }
    const Entry& last() const { return entries_[size_ - 1]; }

    int find(const void* id) const {
        for (int i = size_ - 1; i >= 0; --i)
            if (entries_[i].id == id) return i;
        return -1;
    }
    // Deeper nesting than kCapacity is dropped: the ray then behaves as if outside.
    void push(const void* id, const scene::Interior* interior, bool hollow = false) {
        if (size_ < kCapacity) entries_[size_++] = {id, interior, hollow};
    }
    // Inside an object that is not hollow: POV-Ray has no fog or media there.
    bool in_solid() const {
        for (int i = 0; i < size_; ++i)
            if (!entries_[i].hollow) return true;
        return false;
    }
    void remove_at(int i) {
        for (int k = i; k + 1 < size_; ++k) entries_[k] = entries_[k + 1];
        --size_;
    }
    // Enter the interior if outside it, leave it if inside (shadow rays, continued rays).
    void toggle(const void* id, const scene::Interior* interior, bool hollow) {
        const int i = find(id);
        if (i >= 0)
            remove_at(i);
        else
            push(id, interior, hollow);
    }

private:
    int size_ = 0;
    Entry entries_[kCapacity];  // only [0, size_) is meaningful
};

// Where a ray goes when it crosses the surface of an object with interior `in` (identity `id`):
// the interior list beyond the surface, and the ratio of refractive indices n1/n2 there
// (eye rays and photons alike).
double cross_interface(const InteriorList& before, const void* id, const scene::Interior* in,
                       bool hollow, InteriorList& after);

// The relative IOR (n2/n1) fresnel reflection uses where a ray in `ray_in` meets the surface
// of the object `id`, whose crossing has the ratio `eta` (n1/n2, from cross_interface): the
// physical 1/eta, but for a ray leaving the innermost object it is in while it is inside
// another as well (the camera inside a plane, say), where POV-Ray takes 1, so that fresnel
// gives reflection_min (measured on glass spheres: with the camera inside a plane's
// half-space the inner reflections follow 1 exactly, without it the physical ratio).
inline double fresnel_relative_ior(const InteriorList& ray_in, const void* id, double eta) {
    if (ray_in.size() >= 2 && ray_in.last().id == id) return 1.0;
    return 1.0 / eta;
}

}  // namespace lumen::render

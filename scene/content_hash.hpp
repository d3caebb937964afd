// A 64-bit hash of scene content, walked field by field: numbers by value (-0 as 0, so equal
// values hash equally), vectors, containers, and every struct through its `fields(s, f)` list
// (shapes, pattern kinds, warps). What a cached result depends on is hashed explicitly with
// it (the radiosity solution's reuse key); source locations never are.
#pragma once
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/object.hpp"

namespace lumen::scene {

class ContentHash {
public:
    uint64_t value() const { return h_; }

    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 1099511628211ULL;  // FNV-1a
    }
    void add(double v) {
        if (v == 0) v = 0;  // -0 and 0 are the same value
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        bytes(&bits, sizeof bits);
    }
    void add(const std::string& s) {
        add(uint64_t(s.size()));
        bytes(s.data(), s.size());
    }
    void add(const glm::dvec2& v) { add(v.x), add(v.y); }
    void add(const glm::dvec3& v) { add(v.x), add(v.y), add(v.z); }
    void add(const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) add(m[c][r]);
    }
    void add(const Transform& t) { add(t.m); }
    void add(const Colour& c) { add(c.r), add(c.g), add(c.b), add(c.f), add(c.t); }

    template <class T> void add(const T& v) {
        if constexpr (std::is_enum_v<T>) {
            add(int64_t(v));
        } else if constexpr (std::is_integral_v<T>) {
            const int64_t i = int64_t(v);
            bytes(&i, sizeof i);
        } else if constexpr (std::is_floating_point_v<T>) {
            add(double(v));
        } else if constexpr (requires { T::fields(v, Visitor{this}); }) {
            T::fields(v, Visitor{this});
        } else {
            static_assert(sizeof(T) == 0, "ContentHash: no way to hash this type");
        }
    }
    template <class T, size_t N> void add(const std::array<T, N>& a) {
        for (const T& e : a) add(e);
    }
    template <class T> void add(const std::vector<T>& v) {
        add(uint64_t(v.size()));
        for (const T& e : v) add(e);
    }
    template <class T> void add(const SharedVector<T>& v) { add(v.get()); }
    template <class T> void add(const std::optional<T>& o) {
        add(bool(o));
        if (o) add(*o);
    }
    template <class T> void add(const std::shared_ptr<T>& p) {
        add(bool(p));
        if (p) add(*p);
    }
    template <class... T> void add(const std::variant<T...>& v) {
        add(uint64_t(v.index()));
        std::visit([this](const auto& x) { add(x); }, v);
    }
    template <class T> void add(const BlendEntry<T>& e) { add(e.value), add(e.item); }

    // Appearance as shadows and patches see it: pigments and the patterns choosing them
    // (finishes, normals and interiors are left out: see each caller for why that is enough).
    void add(const Pattern& p) {
        add(p.kind), add(p.frequency), add(p.phase), add(p.wave), add(p.wave_exponent);
        add(p.noise_generator), add(p.steps.steps), add(p.uv_mapping);
    }
    void add(const Pigment& p) {
        add(p.pattern), add(p.colour), add(p.colour_map), add(p.pigment_map), add(p.list_form);
    }
    void add(const Texture& t) {
        add(t.pigment), add(t.pattern), add(t.texture_map), add(t.list_form);
    }
    // An object's geometry, placement, flags and pigments, with its children, clips and bounds.
    void add(const Object& o) {
        add(o.shape), add(o.transform), add(o.texture), add(o.interior_texture);
        add(o.clipped_by), add(o.bounded_by);
        for (bool b : {o.inverse, o.hollow, o.no_shadow, o.no_image, o.no_reflection,
                       o.double_illuminate, o.no_radiosity})
            add(b);
    }
    void add(const Csg& c) { add(c.op), add(c.children); }
    void add(const UnsupportedShape& u) { add(u.what.feature); }

private:
    struct Visitor {
        ContentHash* h;
        template <class V> void operator()(const char*, const V& v) const { h->add(v); }
    };
    uint64_t h_ = 1469598103934665603ULL;
};

}  // namespace lumen::scene

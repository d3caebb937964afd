// How each pattern kind perturbs a normal. POV-Ray gives a few kinds a perturbation of their
// own (bumps, dents, wrinkles, ripples, waves, quilted, facets and average); a normal with any
// other kind leans against the slope of the kind's value, sampled around the point
// (render/normal.cpp). A normal renders when its form does: a dedicated form once lumen
// implements it, a differenced kind exactly when the pattern table renders the kind (so a
// kind that lights up for pigments lights up for normals too).
#pragma once
#include <cstddef>
#include <utility>
#include <variant>

#include "scene/pattern_kinds.hpp"

namespace lumen::scene {

// Differenced unless specialised below.
template <class Kind> struct NormalForm {
    static constexpr bool dedicated = false;
    static constexpr bool rendered = PatternTraits<Kind>::info.rendered;
};

// Dedicated forms (render/patterns/normal_forms.cpp): bumps and wrinkles need only POV's
// vector noise, dents the scene's noise_generator, ripples and waves its number_of_waves.
template <bool Rendered> struct DedicatedForm {
    static constexpr bool dedicated = true;
    static constexpr bool rendered = Rendered;
};
template <> struct NormalForm<pattern::Bumps> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::Wrinkles> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::Dents> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::Ripples> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::Waves> : DedicatedForm<true> {};

template <> struct NormalForm<pattern::Quilted> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::Average> : DedicatedForm<true> {};  // its map, weighted
template <> struct NormalForm<pattern::Facets> : DedicatedForm<true> {};
template <> struct NormalForm<pattern::BumpMap> : DedicatedForm<true> {};  // the image's heights

namespace normal_form_detail {
template <std::size_t... I>
constexpr bool rendered_at(PatternType type, std::index_sequence<I...>) {
    bool out = false;
    ((int(type) == int(I) ? (out = NormalForm<std::variant_alternative_t<I, PatternKind>>::rendered)
                          : false),
     ...);
    return out;
}
}  // namespace normal_form_detail

// Whether lumen renders a normal { } of this pattern type.
constexpr bool normal_rendered(PatternType type) {
    return normal_form_detail::rendered_at(
        type, std::make_index_sequence<std::variant_size_v<PatternKind>>{});
}

}  // namespace lumen::scene

// Pattern dispatch: world point -> pattern space through the transforms and warps, the kind's
// raw value (render/pattern_kinds.cpp), then frequency, phase and wave for continuous kinds.
#include "render/pattern.hpp"

#include <cmath>
#include <numbers>

#include "render/pattern_kinds.hpp"

namespace lumen::render {
namespace {

using scene::Colour;
using scene::PatternType;

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

// The steps act on the pattern first to last, so a world point goes through them last to
// first. Warps (and turbulence with an amount) are the noise issue's: the interp reports a
// pattern that has them unsupported, so they never reach a render and leave the point as is.
glm::dvec3 to_pattern_space(const scene::PatternSteps& steps, glm::dvec3 p) {
    for (auto it = steps.steps.rbegin(); it != steps.steps.rend(); ++it)
        std::visit(Overloaded{[&](const scene::Transform& t) {
                                  if (!t.is_identity()) p = t.inv_point(p);
                              },
                              [](const auto&) {}},
                   *it);
    return p;
}

double raw_value(const scene::PatternKind& kind, const glm::dvec3& p) {
    return std::visit(
        [&](const auto& k) -> double {
            using Kind = std::decay_t<decltype(k)>;
            if constexpr (scene::PatternTraits<Kind>::info.rendered)
                return evaluate(k, p);
            else
                return 0.0;  // reported unsupported by the interp: never rendered
        },
        kind);
}

double apply_wave(const scene::Pattern& pat, double v) {
    using scene::WaveType;
    switch (pat.wave) {
        case WaveType::Ramp: return v;
        case WaveType::Sine: return (1 + std::sin(2 * std::numbers::pi * v)) / 2;
        case WaveType::Triangle: return v < 0.5 ? 2 * v : 2 - 2 * v;
        case WaveType::Scallop: return std::fabs(std::sin(std::numbers::pi * v));
        case WaveType::Cubic: return v * v * (3 - 2 * v);
        case WaveType::Poly: return std::pow(v, pat.wave_exponent);
    }
    return v;
}

Colour rgb(double r, double g, double b) { return {r, g, b, 0, 0}; }

// The default colour maps, one per name used in the table's default_map column.
const scene::ColourMap& grey_ramp_map() {
    static const scene::ColourMap m{{0, rgb(0, 0, 0)}, {1, rgb(1, 1, 1)}};
    return m;
}
const scene::ColourMap& checker_map() {
    static const scene::ColourMap m{{0, rgb(0, 0, 1)}, {1, rgb(0, 1, 0)}};
    return m;
}
const scene::ColourMap& brick_map() {
    static const scene::ColourMap m{{0, rgb(0.5, 0.5, 0.5)}, {1, rgb(0.6, 0.15, 0.15)}};
    return m;
}
const scene::ColourMap& hexagon_map() {
    static const scene::ColourMap m{{0, rgb(0, 0, 1)}, {1, rgb(0, 1, 0)}, {2, rgb(1, 0, 0)}};
    return m;
}
const scene::ColourMap& square_map() {
    static const scene::ColourMap m{
        {0, rgb(1, 0, 0)}, {1, rgb(0, 1, 0)}, {2, rgb(0, 0, 1)}, {3, rgb(1, 1, 0)}};
    return m;
}
const scene::ColourMap& triangular_map() {
    static const scene::ColourMap m{{0, rgb(1, 0, 0)}, {1, rgb(0, 1, 0)}, {2, rgb(0, 0, 1)},
                                    {3, rgb(1, 1, 0)}, {4, rgb(0, 1, 1)}, {5, rgb(1, 0, 1)}};
    return m;
}
// Measured from povray renders: cyan -> yellow -> magenta -> cyan.
const scene::ColourMap& radial_map() {
    static const scene::ColourMap m{
        {0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1, rgb(0, 1, 1)}};
    return m;
}

}  // namespace

double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point) {
    return pattern_value_at(pattern, to_pattern_space(pattern, world_point));
}

glm::dvec3 to_pattern_space(const scene::Pattern& pattern, const glm::dvec3& world_point) {
    return to_pattern_space(pattern.steps, world_point);
}

double pattern_value_at(const scene::Pattern& pattern, const glm::dvec3& pattern_point) {
    double v = raw_value(pattern.kind, pattern_point);
    if (is_discrete(pattern.type())) return v;
    v = std::fmod(v * pattern.frequency + pattern.phase, 1.00001);
    if (v < 0) v -= std::floor(v);
    return apply_wave(pattern, v);
}

const scene::ColourMap& default_colour_map(scene::PatternType type) {
    switch (type) {
#define LUMEN_PATTERN_MAP(Kind, keyword, entries, map, ...) \
    case PatternType::Kind: return map##_map();
        LUMEN_PATTERN_KINDS(LUMEN_PATTERN_MAP)
#undef LUMEN_PATTERN_MAP
    }
    return grey_ramp_map();
}

scene::Colour lookup_colour_map(const scene::ColourMap& map, double v) {
    const BlendWeights b = blend_weights(map, v);
    if (map.empty()) return {};
    const Colour& lo = map[b.lower].item;
    if (b.upper_weight == 0) return lo;
    const Colour& hi = map[b.upper].item;
    const double w = b.upper_weight;
    return {lo.r + w * (hi.r - lo.r), lo.g + w * (hi.g - lo.g), lo.b + w * (hi.b - lo.b),
            lo.f + w * (hi.f - lo.f), lo.t + w * (hi.t - lo.t)};
}

}  // namespace lumen::render

// Pattern dispatch: world point -> pattern space through the transforms and warps, the kind's
// raw value (render/pattern_kinds.cpp), then frequency, phase and wave for continuous kinds.
#include "render/pattern.hpp"

#include <cmath>

#include <glm/common.hpp>

#include "noise/waveforms.hpp"
#include "render/pattern_kinds.hpp"
#include "render/patterns/fractals.hpp"
#include "render/patterns/image_lookup.hpp"
#include "render/patterns/noise_kinds.hpp"
#include "render/patterns/pattern_sources.hpp"
#include "render/patterns/pavement.hpp"
#include "render/patterns/periodic.hpp"
#include "render/patterns/surface_patterns.hpp"
#include "render/patterns/tilings.hpp"
#include "render/patterns/warps.hpp"

namespace lumen::render {
namespace {

using scene::Colour;
using scene::PatternType;

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

// Adds the turbulence displacement to p (POV's TP += DTurbulence(TP) * amount).
glm::dvec3 turbulent(const scene::TurbulenceParams& t, const glm::dvec3& p) {
    if (t.amount == glm::dvec3(0)) return p;
    return p + noise::dturbulence(p, t) * t.amount;
}

// Marble and wood take their classic turbulence into their formula instead of being displaced.
bool displaced_by_classic_turbulence(PatternType type) {
    return type != PatternType::Marble && type != PatternType::Wood;
}

// The steps act on the pattern first to last, so a world point goes through them last to
// first; POV then clamps each coordinate to +-1e17.
glm::dvec3 to_pattern_space(const scene::Pattern& pattern, glm::dvec3 p) {
    const scene::PatternSteps& steps = pattern.steps;
    for (auto it = steps.steps.rbegin(); it != steps.steps.rend(); ++it)
        std::visit(Overloaded{[&](const scene::Transform& t) {
                                  if (!t.is_identity()) p = t.inv_point(p);
                              },
                              [&](const scene::warp::ClassicTurbulence& t) {
                                  if (displaced_by_classic_turbulence(pattern.type()))
                                      p = turbulent(t, p);
                              },
                              [&](const scene::warp::Turbulence& t) { p = turbulent(t, p); },
                              [&](const scene::warp::Repeat& w) { p = warp_point(w, p); },
                              [&](const scene::warp::BlackHole& w) { p = warp_point(w, p); },
                              [&](const scene::warp::Mapping& w) { p = warp_point(w, p); },
                              [](const auto&) {}},
                   *it);
    return glm::clamp(p, glm::dvec3(-1e17), glm::dvec3(1e17));
}

double raw_value(const scene::Pattern& pattern, const glm::dvec3& p, const SurfacePoint* surface) {
    return std::visit(
        [&](const auto& k) -> double {
            using Kind = std::decay_t<decltype(k)>;
            if constexpr (!scene::PatternTraits<Kind>::info.rendered)
                return 0.0;  // reported unsupported by the interp: never rendered
            else if constexpr (requires { evaluate(k, p, surface); })
                return evaluate(k, p, surface);  // slope, aoi
            else if constexpr (requires { evaluate(k, p, pattern); })
                return evaluate(k, p, pattern);  // noise kinds need the pattern's settings
            else
                return evaluate(k, p);
        },
        pattern.kind);
}

double apply_wave(const scene::Pattern& pat, double v) {
    using scene::WaveType;
    switch (pat.wave) {
        case WaveType::Ramp: return v;
        case WaveType::Sine: return (1 + noise::cycloidal(v)) / 2;
        case WaveType::Triangle: return noise::triangle_wave(v);
        case WaveType::Scallop: return std::fabs(noise::cycloidal(v / 2));
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
// POV-Ray's built-in maps of bozo, wood, marble and agate.
const scene::ColourMap& bozo_map() {
    static const scene::ColourMap m{{0.4, rgb(1, 1, 1)}, {0.4, rgb(0, 1, 0)}, {0.6, rgb(0, 1, 0)},
                                    {0.6, rgb(0, 0, 1)}, {0.8, rgb(0, 0, 1)}, {0.8, rgb(1, 0, 0)}};
    return m;
}
const scene::ColourMap& wood_map() {
    static const scene::ColourMap m{{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.066)}};
    return m;
}
const scene::ColourMap& marble_map() {
    static const scene::ColourMap m{
        {0, rgb(0.9, 0.8, 0.8)}, {0.9, rgb(0.9, 0.08, 0.08)}, {0.9, rgb(0, 0, 0)}};
    return m;
}
const scene::ColourMap& agate_map() {
    static const scene::ColourMap m{{0, rgb(1, 1, 1)},         {0.5, rgb(0.95, 0.75, 0.5)},
                                    {0.5, rgb(0.9, 0.7, 0.5)}, {0.6, rgb(0.9, 0.7, 0.4)},
                                    {0.6, rgb(1, 0.7, 0.4)},   {1, rgb(0.6, 0.3, 0)}};
    return m;
}
// Measured from povray renders: cyan -> yellow -> magenta -> cyan.
const scene::ColourMap& radial_map() {
    static const scene::ColourMap m{
        {0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1, rgb(0, 1, 1)}};
    return m;
}

}  // namespace

double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point,
                     const SurfacePoint* surface) {
    return pattern_value_at(pattern, to_pattern_space(pattern, world_point), surface);
}

glm::dvec3 pattern_point(const scene::Pattern& pattern, const glm::dvec3& world_point) {
    return to_pattern_space(pattern, world_point);
}

double pattern_value_at(const scene::Pattern& pattern, const glm::dvec3& pattern_point,
                        const SurfacePoint* surface) {
    double v = raw_value(pattern, pattern_point, surface);
    if (is_discrete(pattern.type())) return v;
    // POV's period is 1.00001, not 1: far from the origin the bands drift. Frequency 0 (quilted
    // without one given, ...) skips the step.
    if (pattern.frequency != 0) {
        v = std::fmod(v * pattern.frequency + pattern.phase, 1.00001);
        if (v < 0) v -= std::floor(v);
    }
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

// POV keeps map colours in single precision and blends them there: the difference and the
// sum in float, the weight (from float keys) in double.
scene::Colour lookup_colour_map(const scene::ColourMap& map, double v) {
    const BlendWeights b = blend_weights(map, v);
    if (map.empty()) return {};
    const Colour& lo = map[b.lower].item;
    if (b.upper_weight == 0)
        return {float(lo.r), float(lo.g), float(lo.b), float(lo.f), float(lo.t)};
    const Colour& hi = map[b.upper].item;
    const double w = b.upper_weight;
    auto blend = [w](double a, double c) -> double {
        const float diff = float(c) - float(a);
        return float(a) + float(w * double(diff));
    };
    return {blend(lo.r, hi.r), blend(lo.g, hi.g), blend(lo.b, hi.b), blend(lo.f, hi.f),
            blend(lo.t, hi.t)};
}

}  // namespace lumen::render

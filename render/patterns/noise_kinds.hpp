// The raw values of the noise-based pattern kinds (POV-Ray 3.7's formulas, to the bit), one
// family per file in render/patterns/. Unlike the kinds of render/pattern_kinds.hpp they need
// more of the pattern than the point: the noise generator, the pattern's own (classic)
// turbulence, and for ripples and waves the frequency, phase and scene's number of waves.
#pragma once
#include <glm/vec3.hpp>

#include "noise/noise.hpp"
#include "scene/pattern.hpp"

namespace lumen::render {

// The generator the pattern's noise uses: its own noise_generator, else the scene's.
inline noise::Generator generator_of(const scene::Pattern& pattern) {
    return noise::resolve_generator(pattern.noise_generator,
                                    pattern.globals ? pattern.globals->noise_generator : 2);
}

// The parameters of the pattern's classic turbulence, or POV's defaults (amount 0, 6 octaves,
// omega 0.5, lambda 2) where it has none.
inline const scene::TurbulenceParams& classic_turbulence_of(const scene::Pattern& pattern) {
    static const scene::TurbulenceParams none;
    const scene::TurbulenceParams* t = pattern.steps.classic_turbulence();
    return t ? *t : none;
}

namespace pattern = scene::pattern;

// render/patterns/noise_patterns.cpp
double evaluate(const pattern::Bozo&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Spotted&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Bumps&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Dents&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Granite&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Wrinkles&, const glm::dvec3& p, const scene::Pattern& pat);
// render/patterns/turbulent_patterns.cpp
double evaluate(const pattern::Marble&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Wood&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Agate& k, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Spiral1& k, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Spiral2& k, const glm::dvec3& p, const scene::Pattern& pat);
// render/patterns/cellular_patterns.cpp
double evaluate(const pattern::Cells&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Crackle& k, const glm::dvec3& p, const scene::Pattern& pat);
// render/patterns/wave_patterns.cpp
double evaluate(const pattern::Ripples&, const glm::dvec3& p, const scene::Pattern& pat);
double evaluate(const pattern::Waves&, const glm::dvec3& p, const scene::Pattern& pat);

}  // namespace lumen::render

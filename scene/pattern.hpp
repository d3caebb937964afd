// Patterns shared by pigments, normals and textures: the kind with its own parameters
// (scene/pattern_kinds.hpp), the parameters common to continuous patterns, and the ordered
// transforms and warps (scene/pattern_steps.hpp).
#pragma once
#include <memory>
#include <optional>

#include "scene/blend_map.hpp"
#include "scene/colour.hpp"
#include "scene/pattern_kinds.hpp"
#include "scene/pattern_steps.hpp"
#include "scene/unsupported.hpp"

namespace lumen::scene {

enum class WaveType { Ramp, Sine, Triangle, Scallop, Cubic, Poly };

// The scene-wide settings a pattern's value depends on. They are known only once the whole
// scene is read (POV-Ray applies a global_settings written after the pattern, and the default
// generator follows the final #version), so the interp gives every pattern of a scene the
// same shared record and fills it in at the end.
struct PatternGlobals {
    int noise_generator = 2;  // global_settings { noise_generator }: 1..3
    int number_of_waves = 10;  // global_settings { number_of_waves }
};

struct Pattern {
    PatternKind kind;                      // Plain = no pattern
    // Continuous patterns only (discrete ones accept and ignore them, as POV does):
    double frequency = 1.0, phase = 0.0;
    WaveType wave = WaveType::Ramp;
    double wave_exponent = 1.0;            // poly_wave exponent
    int noise_generator = 0;               // 0 = global_settings' choice; 1..3 as in POV
    std::shared_ptr<const PatternGlobals> globals;  // null = POV's defaults
    PatternSteps steps;                    // transforms and warps, pattern space -> world
    // `uv_mapping`: the pattern is evaluated at (u, v, 0) of the surface hit (render/hit.hpp)
    // through its own steps only; transforms from outside (the object's) do not reach it.
    bool uv_mapping = false;
    std::optional<Unsupported> unsupported;  // set when the pattern or a modifier is unsupported

    PatternType type() const { return PatternType(kind.index()); }
    bool is_plain() const { return std::holds_alternative<pattern::Plain>(kind); }
};

using ColourMap = BlendMap<Colour>;

}  // namespace lumen::scene

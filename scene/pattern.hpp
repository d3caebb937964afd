// Patterns shared by pigments, normals and textures (pattern.cpp in POV-Ray terms).
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/colour.hpp"
#include "scene/transform.hpp"
#include "scene/unsupported.hpp"

namespace lumen::scene {

enum class PatternType {
    Plain,  // no pattern: a solid colour / plain texture
    Checker, Gradient, Planar, Radial, Onion, Spherical, Cylindrical, Brick, Boxed, Hexagon,
    Square, Triangular,
    // noise-based and others, evaluated once the noise issue lands:
    Agate, Bozo, Bumps, Crackle, Dents, Granite, Leopard, Marble, Ripples, Spotted, Waves,
    Wood, Wrinkles, Quilted, Other
};

enum class WaveType { Ramp, Sine, Triangle, Scallop, Cubic, Poly };

struct Pattern {
    PatternType type = PatternType::Plain;
    glm::dvec3 gradient{1, 0, 0};          // gradient <v> (normalised)
    glm::dvec3 brick_size{8, 3, 4.5};      // brick
    double mortar = 0.5;                   // brick
    double frequency = 1.0, phase = 0.0;
    WaveType wave = WaveType::Ramp;
    double wave_exponent = 1.0;            // poly_wave exponent
    glm::dvec3 turbulence{0, 0, 0};        // turbulence amount (0 = none)
    int octaves = 6;
    double omega = 0.5, lambda = 2.0;
    Transform transform;                   // pattern space -> world (inverse maps world points)
    std::optional<Unsupported> unsupported;  // set when the pattern or a modifier is unsupported
};

struct ColourMapEntry {
    double value = 0;
    Colour colour;
};
using ColourMap = std::vector<ColourMapEntry>;

}  // namespace lumen::scene

// Pigment, Finish, Normal, Texture, Interior: POV's material model as plain data.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "scene/blend_map.hpp"
#include "scene/colour.hpp"
#include "scene/pattern.hpp"

namespace lumen::scene {

struct Pigment;
using PigmentPtr = std::shared_ptr<const Pigment>;
using PigmentMap = BlendMap<PigmentPtr>;

struct Pigment {
    Pattern pattern;                 // Plain = solid `colour`
    Colour colour{0, 0, 0, 0, 0};    // solid colour (default pigment is black rgbft 0)
    ColourMap colour_map;            // empty = the pattern's default map
    // pigment_map entries, or the list form `checker pigment{A} pigment{B}`;
    // for list forms, `value` is the index.
    PigmentMap pigment_map;
    bool list_form = false;          // `checker A, B` / `hexagon A, B, C` style
    SourceLoc loc;
};

struct Finish {
    glm::dvec3 ambient{0.1, 0.1, 0.1};
    glm::dvec3 emission{0, 0, 0};
    double diffuse = 0.6, diffuse_back = 0.0, brilliance = 1.0;
    double phong = 0.0, phong_size = 40.0;
    double specular = 0.0, roughness = 0.05;
    double metallic = 0.0;
    double crand = 0.0;
    glm::dvec3 reflection_min{0, 0, 0}, reflection_max{0, 0, 0};
    double reflection_falloff = 1.0;
    double reflection_exponent = 1.0;  // as written (`exponent E`); renderer uses R^(1/E)
    double reflection_metallic = 0.0;
    bool fresnel = false;
    bool conserve_energy = false;
    double irid_amount = 0.0, irid_thickness = 0.0, irid_turbulence = 0.0;
    std::optional<double> ior;       // obsolete finish{ior}: moved into the interior
    SourceLoc loc;
};
using FinishPtr = std::shared_ptr<const Finish>;

struct Normal;
using NormalPtr = std::shared_ptr<const Normal>;
using NormalMap = BlendMap<NormalPtr>;
// slope_map entries <height, slope>; density_map entries (read as unsupported until media
// render).
using SlopeMap = BlendMap<glm::dvec2>;
using DensityMap = BlendMap<Colour>;

// POV keeps the amount and accuracy in single precision: the interp rounds them to float.
struct Normal {
    Pattern pattern;                 // Plain = no perturbation
    double amount = 0.5;             // bump size
    double accuracy = 0.02;          // sampling distance of the pattern's slope
    bool no_bump_scale = false;      // bump_size not scaled with the object
    // normal_map, or the list form `checker normal{A} ...`: entries are evaluated at the
    // pattern-space point of this normal, so this normal's transforms are not copied into them.
    NormalMap normal_map;
    // The pattern's value -> the height whose slope tilts the normal. POV keeps one map per
    // normal: a slope_map and a normal_map replace each other, the last written wins.
    SlopeMap slope_map;
    SourceLoc loc;
};

struct Media;
struct Texture;
using TexturePtr = std::shared_ptr<const Texture>;
// Layers, bottom first: the last layer is the top one (POV layers textures in written order).
using LayeredTexture = std::vector<TexturePtr>;
using TextureMap = BlendMap<LayeredTexture>;

struct Texture {
    // Plain texture (pattern.type == Plain): pigment + finish + normal.
    PigmentPtr pigment;   // null = default pigment
    FinishPtr finish;     // null = default finish
    NormalPtr normal;     // null = none
    // Patterned texture: texture_map, or list form `checker texture{A} texture{B}`.
    Pattern pattern;
    TextureMap texture_map;
    bool list_form = false;
    SourceLoc loc;
};

struct Interior {
    double ior = 1.0;
    double caustics = 0.0;
    double dispersion = 1.0;
    int dispersion_samples = 7;
    double fade_distance = 0.0, fade_power = 0.0;
    glm::dvec3 fade_colour{0, 0, 0};
    std::vector<std::shared_ptr<const Media>> media;  // in the order written (scene/media.hpp)
    SourceLoc loc;
};

}  // namespace lumen::scene

// Pigment evaluation: solid colours, colour maps, pigment maps and list forms.
#pragma once
#include <glm/vec3.hpp>

#include "render/pattern.hpp"
#include "scene/texture.hpp"

namespace lumen::render {

// Colour of `pigment` at world point p; a null pigment is POV's default (black, rgbft 0).
// `surface`: where on a surface, for slope and aoi (null: none).
scene::Colour evaluate_pigment(const scene::Pigment* pigment, const glm::dvec3& p,
                               const SurfacePoint* surface = nullptr);

// Blends all five channels: a + w·(b − a).
scene::Colour mix(const scene::Colour& a, const scene::Colour& b, double w);

}  // namespace lumen::render

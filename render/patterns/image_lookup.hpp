// Image patterns (scene/pattern_kinds.hpp: image_map, image_pattern, bump_map, material_map):
// a pattern-space point wrapped onto the image by the map type, then the pixels around it
// interpolated, as POV-Ray 3.7 does (matched pixel by pixel against povray renders:
// tests/images).
//   planar 0: (x, y) -> (u, v), the image's bottom-left corner at the origin, tiled;
//   spherical 1: longitude from +x towards +z, latitude from -y to +y;
//   cylindrical 2: longitude as spherical, v = y;
//   torus 5: longitude, and the angle around a ring of major radius 1.
// `once` leaves everything outside the image off the map; else the image tiles.
#pragma once
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/colour.hpp"
#include "scene/pattern_kinds.hpp"

namespace lumen::render {

// Where p falls on the image: (column, row) in pixels from the top-left corner, inside the
// image; nothing when it is off the map.
std::optional<glm::dvec2> image_position(const scene::pattern::ImageSource& k, const glm::dvec3& p);

// The colour at a position (filter and transmit from alpha and the block's settings),
// interpolated as the block asks.
scene::Colour image_colour(const scene::pattern::ImageSource& k, const glm::dvec2& at);

// image_map's colour at p; off the map it is clear (rgbft 1, 1, 1, 0, 1): the ray goes on.
scene::Colour image_map_colour(const scene::pattern::ImageMap& k, const glm::dvec3& p);

// The height a bump_map sees at a position: the colour's grey, or with use_index on a palette
// image the palette index 0..255.
double bump_height(const scene::pattern::BumpMap& k, const glm::dvec2& at);

// The pattern values (render/pattern.cpp dispatches here): image_map and bump_map their grey;
// image_pattern its grey (or alpha with use_alpha) in [0, 1]; material_map the index of the
// texture it picks. Off the map all give 0.
double evaluate(const scene::pattern::ImageMap& k, const glm::dvec3& p);
double evaluate(const scene::pattern::ImagePattern& k, const glm::dvec3& p);
double evaluate(const scene::pattern::BumpMap& k, const glm::dvec3& p);
double evaluate(const scene::pattern::MaterialMap& k, const glm::dvec3& p);

}  // namespace lumen::render

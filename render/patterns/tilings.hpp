// Patterns that tile space or the x-z plane with a few cell kinds: cubic (six pyramids about
// the origin) and tiling N.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Cubic&, const glm::dvec3& p);
double evaluate(const scene::pattern::Tiling& k, const glm::dvec3& p);

// cubic's default colours: red, green, blue, yellow, cyan, magenta for +x, +y, +z, -x, -y, -z.
const scene::ColourMap& cubic_map();

}  // namespace lumen::render

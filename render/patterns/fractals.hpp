// The fractal patterns mandel, julia and magnet on the pattern point's (x, y).
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Mandel& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Julia& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Magnet& k, const glm::dvec3& p);

// mandel's default colour map (the others use the grey ramp).
const scene::ColourMap& mandel_map();

}  // namespace lumen::render

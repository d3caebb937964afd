// Patterns periodic in all three axes without noise: leopard and quilted.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern_kinds.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Leopard&, const glm::dvec3& p);
double evaluate(const scene::pattern::Quilted& k, const glm::dvec3& p);

}  // namespace lumen::render

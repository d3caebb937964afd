// The normal forms of the kinds POV-Ray perturbs directly instead of differencing their value
// (scene/normal_forms.hpp). Each adds its perturbation, scaled by the normal's amount, to n in
// pattern space at pattern-space point p; render/normal.cpp moves n in and out of that space.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern_kinds.hpp"

namespace lumen::render {

void add_form(const scene::pattern::Quilted& k, double amount, const glm::dvec3& p, glm::dvec3& n);

}  // namespace lumen::render

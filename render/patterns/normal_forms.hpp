// The normal forms of the kinds POV-Ray perturbs directly instead of differencing their value
// (scene/normal_forms.hpp). Each adds its perturbation, scaled by the normal's amount, to n in
// pattern space at pattern-space point p; render/normal.cpp moves n in and out of that space.
#pragma once
#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::render {

namespace pattern = scene::pattern;

// The noise forms: bumps leans the normal along POV's vector noise, dents by that vector times
// the cube of the scalar noise, wrinkles by ten octaves of its absolute value.
void add_form(const pattern::Bumps&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void add_form(const pattern::Dents&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void add_form(const pattern::Wrinkles&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
// The wave forms: concentric waves about POV's wave sources, the pattern's frequency and phase
// inside the wave (waves also scales each by its source's frequency).
void add_form(const pattern::Ripples&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
void add_form(const pattern::Waves&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void add_form(const pattern::Quilted& k, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);

}  // namespace lumen::render

// The normal forms of the kinds POV-Ray perturbs directly instead of differencing their value
// (scene/normal_forms.hpp). Each perturbs n in pattern space at pattern-space point p (most add
// a tilt scaled by the normal's amount; facets replaces n); render/normal.cpp moves n in and out
// of that space.
#pragma once
#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::render {

namespace pattern = scene::pattern;

// The noise forms: bumps leans the normal along POV's vector noise, dents by that vector times
// the cube of the scalar noise, wrinkles by ten octaves of its absolute value.
void apply_form(const pattern::Bumps&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void apply_form(const pattern::Dents&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void apply_form(const pattern::Wrinkles&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
// The wave forms: concentric waves about POV's wave sources, the pattern's frequency and phase
// inside the wave (waves also scales each by its source's frequency).
void apply_form(const pattern::Ripples&, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
void apply_form(const pattern::Waves&, const scene::Normal& normal, const glm::dvec3& p, glm::dvec3& n);
void apply_form(const pattern::Quilted& k, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
// facets ignores the amount. Without coords the normal snaps to the direction of the nearest
// crackle cell point of the normal over `size` (flat facets on curved surfaces); with coords c
// the cells are those of the point over `size`, and each tilts the normal by c times the part
// of POV's vector noise at its cell point that is tangent to the normal.
void apply_form(const pattern::Facets& k, const scene::Normal& normal, const glm::dvec3& p,
              glm::dvec3& n);
// bump_map: the image's heights times the amount (render/patterns/bump_map.cpp).
void apply_form(const pattern::BumpMap& k, const scene::Normal& normal, const glm::dvec3& p,
                glm::dvec3& n);

}  // namespace lumen::render

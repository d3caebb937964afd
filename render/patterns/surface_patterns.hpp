// Patterns of the surface rather than the point: slope (the normal's direction, optionally
// mixed with the height) and aoi (the angle the ray meets the surface at). Without a surface
// (null) they give 0.
#pragma once
#include <glm/vec3.hpp>

#include "render/pattern.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Slope& k, const glm::dvec3& p, const SurfacePoint* surface);
double evaluate(const scene::pattern::Aoi&, const glm::dvec3& p, const SurfacePoint* surface);

}  // namespace lumen::render

// What a ray that leaves the scene sees: the sky_sphere's pigments layered over the background
// colour (the last pigment on top, as a texture's layers). Shared by the tracer and by
// radiosity's gathers, whose escaping rays see the sky as POV's radiosity rays do.
#pragma once
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace lumen::render {

// The colour along unit `dir`; `through` (when not null) receives the filter through which
// the background shows (1 without a sky_sphere).
glm::dvec3 sky_colour(const scene::Scene& scene, const glm::dvec3& dir,
                      glm::dvec3* through = nullptr);

}  // namespace lumen::render

// Normal perturbation (`normal { }`): the shading normal of a texture layer.
#pragma once
#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::render {

// `raw` (the surface normal, facing the incoming ray) perturbed by `normal` at world point p,
// as POV-Ray does it: the normal goes into the pattern's space through the transposed
// transforms, is tilted there by the pattern's own form or by the slope of its value, and comes
// back through the inverse transforms. Unit length; `raw` itself where the perturbation
// degenerates (a zero or non-finite result).
glm::dvec3 perturbed_normal(const scene::Normal& normal, const glm::dvec3& raw,
                            const glm::dvec3& p);

// slope_map lookup: the height at pattern value v, a cubic Hermite curve between the two
// entries around v through their heights with their slopes (POV does not scale the slopes by
// the distance between the keys); the entry's height at a key or outside the keys.
double slope_height(const scene::SlopeMap& map, double v);

}  // namespace lumen::render

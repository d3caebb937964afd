// The (u, v) of a surface hit that uv_mapping textures are evaluated at, per shape as POV-Ray
// 3.7 gives it (measured against povray renders, see render/surface_uv.cpp). Computed only for
// hits whose texture uses uv_mapping (Node::needs_uv).
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/shapes/shape_data.hpp"

namespace lumen::render {

// `local`: the hit in the shape's own (untransformed) space; `world`: the same point in the
// scene; `hit`: what the shape's intersection reported (meshes, lathe and sor leave their
// parametric coordinates in hit.uv). Shapes without a uv of their own give (world x, world y).
glm::dvec2 surface_uv(const ShapeData& shape, const glm::dvec3& local, const glm::dvec3& world,
                      const ShapeHit& hit);

// The turn about +y of the direction (x, z) as a fraction of a circle in [0, 1): 0 along +x,
// 0.25 along +z, 0.75 along -z (0 when the direction is within 1e-10 of the axis).
double turn_fraction(double x, double z);

}  // namespace lumen::render

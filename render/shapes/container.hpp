// The contained_by box or sphere of an isosurface or a parametric, as POV-Ray 3.7 uses it:
// the span of a ray inside it (a box span starts at the ray's origin at the earliest), the
// outward normals where the ray enters and leaves, the inside test and the bounding box.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

inline constexpr double kFar = 2e10;  // POV-Ray's largest depth along a ray

// False when the ray misses the container or leaves it before depth 1e-6; `len` is |r.d|.
bool container_span(const scene::Container& c, const LocalRay& r, double len, double& t1,
                    double& t2, glm::dvec3& n1, glm::dvec3& n2);
bool in_container(const scene::Container& c, const glm::dvec3& p);
Aabb container_bounds(const scene::Container& c);

}  // namespace lumen::render

// Deterministic form factors: Lambert's contour formula for a point to a polygon, and its
// area average (graded Gauss-Legendre over the source) for patch to patch. Both assume the
// pair is unoccluded; occlusion enters through the ray-cast estimators (ray_cast.hpp).
#pragma once
#include <glm/vec3.hpp>

#include "render/radiosity/patch.hpp"

namespace lumen::render::radiosity {

// Form factor from a differential area at `x` with unit normal `n` to `target`:
// F = (1/2π) Σ_edges γ_e (n · ĝ_e), with the target first clipped to the half-space in front
// of x. Exact for unoccluded polygons; finite (0) for coplanar or degenerate targets, and
// finite when x lies on an edge or vertex of the target.
double point_to_polygon(const glm::dvec3& x, const glm::dvec3& n, const Patch& target);

struct QuadratureOptions {
    int order = 6;   // Gauss-Legendre points per cell and direction
    int grading = 3; // geometric refinement levels (factor 4) toward each edge of the source
};

// F_ij = (1/A_i) ∫_{A_i} F_{dA→j} dA, the source integrated over a fan of triangles with
// cells graded toward the edges (where shared-edge neighbours have a log singularity).
// Returns 0 for a degenerate source and clamps to [0, 1].
double patch_to_patch(const Patch& from, const Patch& to, const QuadratureOptions& q = {});

}  // namespace lumen::render::radiosity

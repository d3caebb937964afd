// Pattern evaluation and blend-map lookup.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

using scene::blend_weights;
using scene::BlendWeights;

// Where on a surface a pattern is evaluated, for the patterns that depend on more than the
// point: slope and aoi see the world hit point, the shading normal turned to face the ray, and
// the ray's direction (null, or not `oriented` as for shadow filters: they give 0);
// uv_mapping patterns see the hit's (u, v) (render/surface_uv.hpp).
struct SurfacePoint {
    glm::dvec3 point, normal, direction;
    glm::dvec2 uv{0};
    bool oriented = true;
    // Set by the patterns that read `normal`: the tracer re-evaluates a layer's pigment only
    // when it did and a normal perturbed since then (POV perturbs before it colours a layer).
    mutable bool normal_read = false;
};

// The point a pattern starts from: p, or (u, v, 0) of the surface under uv_mapping (POV-Ray
// ignores the hit point then; without a surface there is no uv and it takes the origin).
inline glm::dvec3 source_point(const scene::Pattern& pattern, const glm::dvec3& p,
                               const SurfacePoint* surface) {
    if (!pattern.uv_mapping) return p;
    return surface ? glm::dvec3(surface->uv, 0) : glm::dvec3(0);
}

// Discrete (block) patterns give an index, skip frequency/phase/waves and pick map entries by
// index: checker 0..1, brick 0..1 (mortar, brick), hexagon 0..2, square 0..3, triangular 0..5.
inline bool is_discrete(scene::PatternType type) { return scene::discrete_entries(type) > 0; }

// The pattern's value at world point p: maps p through the pattern's transforms and warps into
// pattern space, computes the kind's raw value and applies frequency/phase and the wave type
// (continuous patterns), so the result indexes a blend map directly.
double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point,
                     const SurfacePoint* surface = nullptr);
// The two halves of pattern_value: the world point mapped into pattern space, and the value
// at a point already there. A pigment's and a texture's map entries take their parent's
// pattern point as their world point (POV-Ray: they see the parent's transforms and warps);
// a normal samples its pattern's slope around one warped point, and POV does not warp the
// samples again.
glm::dvec3 pattern_point(const scene::Pattern& pattern, const glm::dvec3& world_point);
double pattern_value_at(const scene::Pattern& pattern, const glm::dvec3& pattern_point,
                        const SurfacePoint* surface = nullptr);

// The colour map a pattern uses when the scene gives none.
const scene::ColourMap& default_colour_map(scene::PatternType type);

// Colour-map lookup, blending all five channels.
scene::Colour lookup_colour_map(const scene::ColourMap& map, double v);

}  // namespace lumen::render

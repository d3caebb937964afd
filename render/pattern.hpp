// Pattern evaluation and blend-map lookup.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

using scene::blend_weights;
using scene::BlendWeights;

// Discrete (block) patterns give an index, skip frequency/phase/waves and pick map entries by
// index: checker 0..1, brick 0..1 (mortar, brick), hexagon 0..2, square 0..3, triangular 0..5.
inline bool is_discrete(scene::PatternType type) { return scene::discrete_entries(type) > 0; }

// The pattern's value at world point p: maps p through the pattern's transforms and warps into
// pattern space, computes the kind's raw value and applies frequency/phase and the wave type
// (continuous patterns), so the result indexes a blend map directly.
double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point);
// The two halves of pattern_value: the point in the pattern's own space (through its
// transforms and warps), and the value at such a point. A map's entries (pigment_map,
// texture_map, normal_map and the list forms) are evaluated at their parent's pattern point,
// as POV does: the parent's transforms and turbulence carry over to them. A normal samples
// its pattern's slope around one pattern point, without warping the samples again.
glm::dvec3 pattern_point(const scene::Pattern& pattern, const glm::dvec3& world_point);
double pattern_value_at(const scene::Pattern& pattern, const glm::dvec3& pattern_point);

// The colour map a pattern uses when the scene gives none.
const scene::ColourMap& default_colour_map(scene::PatternType type);

// Colour-map lookup, blending all five channels.
scene::Colour lookup_colour_map(const scene::ColourMap& map, double v);

}  // namespace lumen::render

// Pattern evaluation and blend-map lookup (POV-Ray 3.7's rules).
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

// Discrete (block) patterns give an index, skip frequency/phase/waves and pick map entries by
// index: checker 0..1, brick 0..1 (mortar, brick), hexagon 0..2, square 0..3, triangular 0..5.
bool is_discrete(scene::PatternType type);

// The pattern's value at world point p: maps p into pattern space, computes the raw value and
// applies frequency/phase and the wave type (continuous patterns), so the result indexes a
// blend map directly. Noise-based patterns are not evaluated here (they return 0).
double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point);

// The colour map a pattern uses when the scene gives none.
const scene::ColourMap& default_colour_map(scene::PatternType type);

// Two neighbouring blend-map entries and the weight of the upper one (POV's Search_Blend_Map):
// v at or above the last entry -> the last entry; below the first -> the first; an exact
// match -> that entry; otherwise a linear blend of the entry above v and the one before it.
struct BlendWeights {
    int lower = 0, upper = 0;
    double upper_weight = 0;  // 0 -> all `lower`
};
template <class Map>
BlendWeights blend_weights(const Map& map, double v) {
    const int n = int(map.size());
    if (n == 0) return {};
    if (v >= map[n - 1].value) return {n - 1, n - 1, 0};
    int i = 0;
    while (i < n && map[i].value < v) ++i;
    if (i == 0 || map[i].value == v) return {i, i, 0};
    const double span = map[i].value - map[i - 1].value;
    const double w = span > 0 ? (v - map[i - 1].value) / span : 1.0;
    return {i - 1, i, w};
}

// Colour-map lookup, blending all five channels.
scene::Colour lookup_colour_map(const scene::ColourMap& map, double v);

}  // namespace lumen::render

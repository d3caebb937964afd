// Blend maps: colour_map, pigment_map, normal_map, texture_map, slope_map and density_map are
// one structure, a list of [value item] entries kept in the order written (POV does not sort
// them), looked up by the pattern's value. List forms (`checker A, B`, `hexagon A, B, C`) are
// the same map with entries valued 0, 1, 2, ...
#pragma once
#include <vector>

namespace lumen::scene {

template <class T> struct BlendEntry {
    double value = 0;
    T item{};
};
template <class T> using BlendMap = std::vector<BlendEntry<T>>;

// Two neighbouring entries and the weight of the upper one (POV's map search): v at or above
// the last entry -> the last entry; below the first -> the first; an exact match -> the first
// entry with that value; otherwise a linear blend of the entry above v and the one before it.
struct BlendWeights {
    int lower = 0, upper = 0;
    double upper_weight = 0;  // 0 -> all `lower`
};

// POV stores the entries' values in single precision: they are compared and blended as such.
template <class T> BlendWeights blend_weights(const BlendMap<T>& map, double v) {
    const int n = int(map.size());
    if (n == 0) return {};
    auto key = [&](int i) { return double(float(map[i].value)); };
    if (v >= key(n - 1)) return {n - 1, n - 1, 0};
    int i = 0;
    while (i < n && key(i) < v) ++i;
    if (i == 0 || key(i) == v) return {i, i, 0};
    const double span = key(i) - key(i - 1);
    const double w = span > 0 ? (v - key(i - 1)) / span : 1.0;
    return {i - 1, i, w};
}

}  // namespace lumen::scene

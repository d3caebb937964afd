#include "render/pigment.hpp"

#include "render/pattern.hpp"

namespace lumen::render {

scene::Colour mix(const scene::Colour& a, const scene::Colour& b, double w) {
    return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b),
            a.f + w * (b.f - a.f), a.t + w * (b.t - a.t)};
}

scene::Colour evaluate_pigment(const scene::Pigment* pigment, const glm::dvec3& p) {
    if (!pigment) return {};
    if (pigment->pattern.is_plain()) return pigment->colour;
    const glm::dvec3 tp = pattern_point(pigment->pattern, p);
    const double v = pattern_value_at(pigment->pattern, tp);
    if (!pigment->pigment_map.empty()) {
        // pigment_map, or the list form whose entries are indexed 0, 1, 2...: the entries are
        // evaluated at this pattern's point.
        const BlendWeights b = blend_weights(pigment->pigment_map, v);
        const scene::Colour lo = evaluate_pigment(pigment->pigment_map[b.lower].item.get(), tp);
        if (b.upper_weight == 0) return lo;
        const scene::Colour hi = evaluate_pigment(pigment->pigment_map[b.upper].item.get(), tp);
        return mix(lo, hi, b.upper_weight);
    }
    const scene::ColourMap& map = pigment->colour_map.empty()
                                      ? default_colour_map(pigment->pattern.type())
                                      : pigment->colour_map;
    return lookup_colour_map(map, v);
}

}  // namespace lumen::render

#include "render/pigment.hpp"

#include "render/pattern.hpp"
#include "render/patterns/image_lookup.hpp"

namespace lumen::render {

namespace {

// `average pigment_map { [w P] ... }`: the entries' colours weighted by w (POV-Ray: a total
// weight of 0 gives black).
scene::Colour average_colour(const scene::PigmentMap& map, const glm::dvec3& tp,
                             const SurfacePoint* surface) {
    const double total = scene::average_total(map);
    if (total == 0) return {};
    scene::Colour sum{};
    for (const auto& e : map) {
        const scene::Colour c = evaluate_pigment(e.item.get(), tp, surface);
        const double w = e.value;
        sum = {sum.r + w * c.r, sum.g + w * c.g, sum.b + w * c.b, sum.f + w * c.f, sum.t + w * c.t};
    }
    return {sum.r / total, sum.g / total, sum.b / total, sum.f / total, sum.t / total};
}

}  // namespace

scene::Colour mix(const scene::Colour& a, const scene::Colour& b, double w) {
    return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b),
            a.f + w * (b.f - a.f), a.t + w * (b.t - a.t)};
}

// Map entries are evaluated at the pigment's pattern point: POV-Ray hands them the point its
// transforms and warps produced, and they apply their own on top.
scene::Colour evaluate_pigment(const scene::Pigment* pigment, const glm::dvec3& p,
                               const SurfacePoint* surface) {
    if (!pigment) return {};
    if (pigment->pattern.is_plain()) return pigment->colour;
    const glm::dvec3 tp =
        pattern_point(pigment->pattern, source_point(pigment->pattern, p, surface));
    if (std::holds_alternative<scene::pattern::Average>(pigment->pattern.kind))
        return average_colour(pigment->pigment_map, tp, surface);
    if (const auto* image = std::get_if<scene::pattern::ImageMap>(&pigment->pattern.kind))
        return image_map_colour(*image, tp);
    const double v = pattern_value_at(pigment->pattern, tp, surface);
    if (!pigment->pigment_map.empty()) {
        // pigment_map, or the list form whose entries are indexed 0, 1, 2...: the entries are
        // evaluated at this pattern's point.
        const BlendWeights b = blend_weights(pigment->pigment_map, v);
        const auto& map = pigment->pigment_map;
        const scene::Colour lo = evaluate_pigment(map[b.lower].item.get(), tp, surface);
        if (b.upper_weight == 0) return lo;
        const scene::Colour hi = evaluate_pigment(map[b.upper].item.get(), tp, surface);
        return mix(lo, hi, b.upper_weight);
    }
    const scene::ColourMap& map = pigment->colour_map.empty()
                                      ? default_colour_map(pigment->pattern.type())
                                      : pigment->colour_map;
    return lookup_colour_map(map, v);
}

}  // namespace lumen::render

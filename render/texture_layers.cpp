#include "render/texture_layers.hpp"

#include "render/pattern.hpp"
#include "render/pigment.hpp"

namespace lumen::render {

const scene::Finish& default_finish() {
    static const scene::Finish finish;
    return finish;
}

namespace {

const scene::Texture* top_layer(const scene::LayeredTexture& layers) {
    return layers.empty() ? nullptr : layers.back().get();
}

ResolvedLayer resolve_entry(const scene::LayeredTexture& layers, const glm::dvec3& p) {
    const scene::Texture* t = top_layer(layers);
    if (!t) return {scene::Colour{}, &default_finish(), nullptr, p};
    return resolve_layer(*t, p);
}

}  // namespace

ResolvedLayer resolve_layer(const scene::Texture& texture, const glm::dvec3& p) {
    if (texture.pattern.is_plain() || texture.texture_map.empty()) {
        return {evaluate_pigment(texture.pigment.get(), p),
                texture.finish ? texture.finish.get() : &default_finish(), texture.normal.get(), p};
    }
    // The entries are evaluated at this pattern's point.
    const glm::dvec3 tp = pattern_point(texture.pattern, p);
    const BlendWeights b = blend_weights(texture.texture_map, pattern_value_at(texture.pattern, tp));
    ResolvedLayer lo = resolve_entry(texture.texture_map[b.lower].item, tp);
    if (b.upper_weight == 0) return lo;
    ResolvedLayer hi = resolve_entry(texture.texture_map[b.upper].item, tp);
    ResolvedLayer out = b.upper_weight > 0.5 ? hi : lo;
    out.colour = mix(lo.colour, hi.colour, b.upper_weight);
    return out;
}

void resolve_layers(const scene::LayeredTexture* layers, const glm::dvec3& p,
                    ResolvedLayers& out) {
    out.clear();
    if (!layers || layers->empty()) {
        out.add({scene::Colour{}, &default_finish(), nullptr, p});
        return;
    }
    for (auto it = layers->rbegin(); it != layers->rend() && !out.full(); ++it)
        out.add(*it ? resolve_layer(**it, p)
                    : ResolvedLayer{scene::Colour{}, &default_finish(), nullptr, p});
}

glm::dvec3 surface_filter(const scene::LayeredTexture* layers, const glm::dvec3& p) {
    if (!layers || layers->empty()) return glm::dvec3(0);
    glm::dvec3 filter(1);
    for (const scene::TexturePtr& t : *layers) {
        if (!t) return glm::dvec3(0);
        filter *= layer_filter(resolve_layer(*t, p).colour);
        if (filter.x == 0 && filter.y == 0 && filter.z == 0) break;
    }
    return filter;
}

namespace {

bool colour_passes(const scene::Colour& c) { return c.f != 0 || c.t != 0; }

// Every colour the pigment can evaluate to, looked at without evaluating it (the default
// colour maps are opaque).
bool pigment_may_pass(const scene::Pigment* p) {
    if (!p) return false;  // the default pigment: black
    if (colour_passes(p->colour)) return true;
    for (const auto& e : p->colour_map)
        if (colour_passes(e.item)) return true;
    for (const auto& e : p->pigment_map)
        if (pigment_may_pass(e.item.get())) return true;
    return false;
}

bool texture_may_pass(const scene::Texture& t) {
    // A texture_map entry is resolved through one of its layers: any of them may count.
    for (const auto& e : t.texture_map)
        for (const scene::TexturePtr& layer : e.item)
            if (layer && texture_may_pass(*layer)) return true;
    return pigment_may_pass(t.pigment.get());
}

}  // namespace

bool may_pass_light(const scene::LayeredTexture* layers) {
    if (!layers || layers->empty()) return false;
    for (const scene::TexturePtr& t : *layers)
        if (!t || !texture_may_pass(*t)) return false;  // one opaque layer stops it all
    return true;
}

bool passes_all_light(const scene::LayeredTexture* layers) {
    if (!layers || layers->empty()) return false;
    for (const scene::TexturePtr& t : *layers) {
        if (!t || (!t->pattern.is_plain() && !t->texture_map.empty()))
            return false;
        const scene::Pigment* p = t->pigment.get();
        if (!p || !p->pattern.is_plain()) return false;
        const glm::dvec3 filter = layer_filter(p->colour);
        if (filter != glm::dvec3(1)) return false;
    }
    return true;
}

}  // namespace lumen::render

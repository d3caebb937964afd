#include "render/texture_layers.hpp"

#include "render/pattern.hpp"
#include "render/pigment.hpp"
#include "scene/image_map.hpp"

namespace lumen::render {

const scene::Finish& default_finish() {
    static const scene::Finish finish;
    return finish;
}

namespace {

const scene::Texture* top_layer(const scene::LayeredTexture& layers) {
    return layers.empty() ? nullptr : layers.back().get();
}

ResolvedLayer plain_layer(const scene::Colour& c, const glm::dvec3& p) {
    return {c, &default_finish(), nullptr, p, NormalFrame::none(), nullptr, false};
}

ResolvedLayer resolve_entry(const scene::LayeredTexture& layers, const glm::dvec3& p,
                            const SurfacePoint* surface) {
    const scene::Texture* t = top_layer(layers);
    if (!t) return plain_layer(scene::Colour{}, p);
    return resolve_layer(*t, p, surface);
}

// `average texture_map`: the entries' colours weighted by their values, with the finish and
// normal of the heaviest entry (as a blend takes the nearer entry's).
ResolvedLayer resolve_average(const scene::TextureMap& map, const glm::dvec3& p,
                              const SurfacePoint* surface) {
    const double total = scene::average_total(map);
    if (total == 0) return plain_layer(scene::Colour{}, p);
    ResolvedLayer out = plain_layer(scene::Colour{}, p);
    double heaviest = -1;
    for (const auto& e : map) {
        const ResolvedLayer l = resolve_entry(e.item, p, surface);
        const double w = e.value / total;
        const scene::Colour& c = l.colour;
        out.colour = {out.colour.r + w * c.r, out.colour.g + w * c.g, out.colour.b + w * c.b,
                      out.colour.f + w * c.f, out.colour.t + w * c.t};
        if (w > heaviest) {
            heaviest = w;
            out.finish = l.finish, out.normal = l.normal;
            out.point = l.point, out.frame = l.frame;
        }
    }
    return out;
}

// The entries around the value at tp, blended: the colours mixed, the finish and normal of
// the heavier entry.
ResolvedLayer resolve_blend(const scene::Texture& texture, const glm::dvec3& tp,
                            const SurfacePoint* surface) {
    const double v = pattern_value_at(texture.pattern, tp, surface);
    const BlendWeights b = blend_weights(texture.texture_map, v);
    ResolvedLayer lo = resolve_entry(texture.texture_map[b.lower].item, tp, surface);
    if (b.upper_weight == 0) return lo;
    ResolvedLayer hi = resolve_entry(texture.texture_map[b.upper].item, tp, surface);
    ResolvedLayer out = b.upper_weight > 0.5 ? hi : lo;
    out.colour = mix(lo.colour, hi.colour, b.upper_weight);
    return out;
}

}  // namespace

ResolvedLayer resolve_layer(const scene::Texture& texture, const glm::dvec3& world_point,
                            const SurfacePoint* surface) {
    const glm::dvec3 p = source_point(texture.pattern, world_point, surface);
    if (texture.pattern.is_plain() || texture.texture_map.empty()) {
        const scene::Normal* normal = texture.normal.get();
        return {evaluate_pigment(texture.pigment.get(), p, surface),
                texture.finish ? texture.finish.get() : &default_finish(), normal,
                normal ? source_point(normal->pattern, p, surface) : p, NormalFrame::none(),
                nullptr, false};
    }
    // The entries are evaluated at this pattern's point, their normals in its frame.
    const glm::dvec3 tp = pattern_point(texture.pattern, p);
    ResolvedLayer out = std::holds_alternative<scene::pattern::Average>(texture.pattern.kind)
                            ? resolve_average(texture.texture_map, tp, surface)
                            : resolve_blend(texture, tp, surface);
    if (out.normal) out.frame = NormalFrame::of(texture.pattern).then(out.frame);
    return out;
}

void resolve_layers(const scene::LayeredTexture* layers, const glm::dvec3& p,
                    ResolvedLayers& out, const SurfacePoint* surface) {
    out.clear();
    if (!layers || layers->empty()) {
        out.add(plain_layer(scene::Colour{}, p));
        return;
    }
    for (auto it = layers->rbegin(); it != layers->rend() && !out.full(); ++it) {
        if (!*it) {
            out.add(plain_layer(scene::Colour{}, p));
            continue;
        }
        if (surface) surface->normal_read = false;
        ResolvedLayer layer = resolve_layer(**it, p, surface);
        layer.source = it->get();
        layer.reads_normal = surface && surface->normal_read;
        out.add(layer);
    }
}

glm::dvec3 surface_filter(const scene::LayeredTexture* layers, const glm::dvec3& p,
                          const SurfacePoint* surface) {
    if (!layers || layers->empty()) return glm::dvec3(0);
    glm::dvec3 filter(1);
    for (const scene::TexturePtr& t : *layers) {
        if (!t) return glm::dvec3(0);
        filter *= layer_filter(resolve_layer(*t, p, surface).colour);
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
    if (const auto* image = std::get_if<scene::pattern::ImageMap>(&p->pattern.kind))
        if (image->data && image->data->may_pass_light) return true;
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

namespace {

bool pigment_uses_uv(const scene::Pigment* p) {
    if (!p) return false;
    if (p->pattern.uv_mapping) return true;
    if (const auto* k = std::get_if<scene::pattern::PigmentPattern>(&p->pattern.kind))
        if (pigment_uses_uv(k->pigment.get())) return true;
    for (const auto& e : p->pigment_map)
        if (pigment_uses_uv(e.item.get())) return true;
    return false;
}

bool normal_uses_uv(const scene::Normal* n) {
    if (!n) return false;
    if (n->pattern.uv_mapping) return true;
    for (const auto& e : n->normal_map)
        if (normal_uses_uv(e.item.get())) return true;
    return false;
}

bool texture_uses_uv(const scene::Texture& t) {
    if (t.pattern.uv_mapping || pigment_uses_uv(t.pigment.get()) || normal_uses_uv(t.normal.get()))
        return true;
    for (const auto& e : t.texture_map)
        if (uses_uv_mapping(&e.item)) return true;
    return false;
}

}  // namespace

bool uses_uv_mapping(const scene::LayeredTexture* layers) {
    if (!layers) return false;
    for (const scene::TexturePtr& t : *layers)
        if (t && texture_uses_uv(*t)) return true;
    return false;
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

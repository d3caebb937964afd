#include "render/radiosity/surface_light.hpp"

#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "render/interior_list.hpp"
#include "render/shadows.hpp"
#include "render/texture_layers.hpp"

namespace lumen::render::radiosity {

glm::dvec3 ambient_emission(const scene::Scene& scene) {
    return scene.language_version < 3.7 ? scene.globals.ambient_light : glm::dvec3(0);
}

SurfaceMaterial surface_material(const scene::LayeredTexture* texture, const glm::dvec3& p,
                                 const glm::dvec3& ambient_emission) {
    ResolvedLayers layers;
    resolve_layers(texture, p, layers);
    SurfaceMaterial m;
    m.brilliance = layers[0].finish->brilliance;
    // Layers as the tracer stacks them: each seen through the filter and transmit of those
    // above it (a sky of clouds with transmit 1 over a blue layer emits the blue).
    glm::dvec3 filter(1);
    for (int i = 0; i < layers.count(); ++i) {
        const ResolvedLayer& layer = layers[i];
        const glm::dvec3 rgb(layer.colour.r, layer.colour.g, layer.colour.b);
        const double opacity = 1 - layer.colour.f - layer.colour.t;
        const scene::Finish& f = *layer.finish;
        m.rho += filter * rgb * f.diffuse * opacity;
        m.emission += filter * rgb * (glm::dvec3(f.emission) + f.ambient * ambient_emission) * opacity;
        filter *= layer_filter(layer.colour);
        if (filter == glm::dvec3(0)) break;  // opaque: the layers below are hidden
    }
    m.rho = glm::max(glm::dvec3(0), m.rho);
    m.emission = glm::max(glm::dvec3(0), m.emission);
    return m;
}

bool never_diffuse(const scene::LayeredTexture* texture) {
    if (!texture || texture->empty()) return false;  // the default: 0.6
    for (const auto& layer : *texture) {
        if (!layer) return false;
        if (!layer->texture_map.empty()) {
            for (const auto& entry : layer->texture_map)
                if (!never_diffuse(&entry.item)) return false;
        } else if (!layer->finish || layer->finish->diffuse != 0) {
            return false;
        }
    }
    return true;
}

glm::dvec3 direct_light_at(const std::vector<LightSource>& lights, const Intersector& geometry,
                           const glm::dvec3& p, const glm::dvec3& n, double brilliance,
                           TraceCounters& counters, glm::dvec3* back) {
    const InteriorList outside{};
    glm::dvec3 H(0);
    for (const LightSource& l : lights) {
        LightSample ls;
        // The patches do not know their light_groups: a group's lights are left out of them.
        if (l.group != 0 || !illuminate(l, p, ls)) continue;
        double c = glm::dot(n, ls.dir);
        glm::dvec3* side = &H;
        if (c <= 0) {
            if (!back) continue;
            c = -c;
            side = back;
            if (c <= 0) continue;
        }
        glm::dvec3 lc = ls.colour * (brilliance == 1 ? c : std::pow(c, brilliance));
        if (!l.shadowless) lc *= shadow_filter(geometry, p, ls.dir, ls.distance, outside, counters);
        *side += lc;
    }
    return H;
}

}  // namespace lumen::render::radiosity

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
    const ResolvedLayer& top = layers[0];
    const glm::dvec3 rgb(top.colour.r, top.colour.g, top.colour.b);
    const double opacity = 1 - top.colour.f - top.colour.t;
    const scene::Finish& f = *top.finish;
    SurfaceMaterial m;
    m.rho = glm::max(glm::dvec3(0), rgb * f.diffuse * opacity);
    m.emission = glm::max(glm::dvec3(0),
                          rgb * (glm::dvec3(f.emission) + f.ambient * ambient_emission) * opacity);
    m.brilliance = f.brilliance;
    return m;
}

bool never_diffuse(const scene::LayeredTexture* texture) {
    if (!texture || texture->empty() || !texture->back()) return false;  // the default: 0.6
    const scene::Texture& top = *texture->back();
    if (!top.texture_map.empty()) {
        for (const auto& entry : top.texture_map)
            if (!never_diffuse(&entry.item)) return false;
        return true;
    }
    return top.finish && top.finish->diffuse == 0;
}

glm::dvec3 direct_light_at(const std::vector<LightSource>& lights, const Intersector& geometry,
                           const glm::dvec3& p, const glm::dvec3& n, double brilliance,
                           TraceCounters& counters, glm::dvec3* back) {
    const InteriorList outside{};
    glm::dvec3 H(0);
    for (const LightSource& l : lights) {
        LightSample ls;
        if (!illuminate(l, p, ls)) continue;
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

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

namespace {

// Light l's unshadowed term at p: false where it does not reach p (outside a spotlight, in a
// light group) or arrives from behind n without `two_sided`; `behind` says it did.
bool unshadowed(const LightSource& l, const glm::dvec3& p, const glm::dvec3& n,
                double brilliance, bool two_sided, LightSample& ls, glm::dvec3& term,
                bool& behind) {
    // The patches do not know their light_groups: a group's lights are left out of them.
    if (l.group != 0 || !illuminate(l, p, ls)) return false;
    double c = glm::dot(n, ls.dir);
    behind = c <= 0;
    if (behind) {
        if (!two_sided) return false;
        c = -c;
        if (c <= 0) return false;
    }
    term = ls.colour * (brilliance == 1 ? c : std::pow(c, brilliance));
    return true;
}

}  // namespace

glm::dvec3 direct_light_at(const std::vector<LightSource>& lights, const Intersector& geometry,
                           const glm::dvec3& p, const glm::dvec3& n, double brilliance,
                           TraceCounters& counters, glm::dvec3* back) {
    const InteriorList outside{};
    glm::dvec3 H(0);
    for (const LightSource& l : lights) {
        LightSample ls;
        glm::dvec3 lc;
        bool behind = false;
        if (!unshadowed(l, p, n, brilliance, back != nullptr, ls, lc, behind)) continue;
        if (!l.shadowless) lc *= shadow_filter(geometry, p, ls.dir, ls.distance, outside, counters);
        *(behind ? back : &H) += lc;
    }
    return H;
}

glm::dvec3 direct_light_one_of(const std::vector<LightSource>& lights,
                               const Intersector& geometry, const glm::dvec3& p,
                               const glm::dvec3& n, double brilliance, double u,
                               TraceCounters& counters) {
    struct Candidate {
        LightSample ls;
        glm::dvec3 term;
        double weight;
    };
    thread_local std::vector<Candidate> shadowed;
    shadowed.clear();
    glm::dvec3 H(0);
    double total = 0;
    for (const LightSource& l : lights) {
        Candidate c;
        bool behind = false;
        if (!unshadowed(l, p, n, brilliance, false, c.ls, c.term, behind)) continue;
        if (l.shadowless) {
            H += c.term;
            continue;
        }
        c.weight = c.term.x + c.term.y + c.term.z;
        if (!(c.weight > 0)) continue;
        total += c.weight;
        shadowed.push_back(c);
    }
    if (shadowed.empty()) return H;
    // The light chosen with probability weight / total stands for all of them.
    double at = u * total;
    size_t k = 0;
    while (k + 1 < shadowed.size() && at >= shadowed[k].weight) at -= shadowed[k++].weight;
    const Candidate& c = shadowed[k];
    const InteriorList outside{};
    return H + c.term * (total / c.weight) *
                   shadow_filter(geometry, p, c.ls.dir, c.ls.distance, outside, counters);
}

}  // namespace lumen::render::radiosity

#include "render/shadows.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "render/texture_layers.hpp"

namespace lumen::render {
namespace {

constexpr double kShadowTolerance = 1e-3;
constexpr double kBlack = 1e-10;
constexpr int kMaxShadowSurfaces = 256;  // bounds the loop on pathological scenes

bool is_black(const glm::dvec3& c) { return c.x < kBlack && c.y < kBlack && c.z < kBlack; }

}  // namespace

glm::dvec3 interior_fade(const scene::Interior& in, double depth, bool shadow_ray) {
    if (std::fabs(in.fade_distance) <= 1e-10) return glm::dvec3(1);
    if (shadow_ray && in.fade_power <= 0) return glm::dvec3(1);
    const glm::dvec3 fc = in.fade_colour;
    if (in.fade_power >= 1000) return glm::exp(-(glm::dvec3(1) - fc) * (depth / in.fade_distance));
    return fc + (glm::dvec3(1) - fc) / (1 + std::pow(depth / in.fade_distance, in.fade_power));
}

glm::dvec3 shadow_filter(const Intersector& geometry, const glm::dvec3& point,
                         const glm::dvec3& dir, double distance, const InteriorList& interiors,
                         TraceCounters& counters) {
    glm::dvec3 filter(1);
    InteriorList inside = interiors;
    Ray ray{point, dir};
    double remaining = distance;
    Hit hit;  // one for the whole loop: intersect() sets every field of a hit it reports
    for (int i = 0; i < kMaxShadowSurfaces; ++i) {
        const double t_max = remaining - kShadowTolerance;
        if (t_max <= kShadowTolerance) break;
        ++counters.shadow_rays;
        if (!geometry.intersect(ray, kShadowTolerance, t_max, hit, true)) break;
        filter *= surface_filter(facing_texture(hit, dir), hit.point);
        if (is_black(filter)) return glm::dvec3(0);
        // Fake caustics brighten light passing a transparent surface head-on.
        if (hit.interior && hit.interior->caustics != 0)
            filter *= 1 + std::pow(std::fabs(glm::dot(hit.normal, dir)), 45 * hit.interior->caustics);
        const int where = inside.find(hit.interior_id);
        if (where >= 0 && hit.interior) filter *= interior_fade(*hit.interior, hit.t, true);
        inside.toggle(hit.interior_id, hit.interior);
        ray.origin = hit.point;
        remaining -= hit.t;
    }
    return filter;
}

}  // namespace lumen::render

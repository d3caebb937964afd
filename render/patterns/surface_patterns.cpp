// Matched against povray 3.7 (tests/patterns/slope_aoi.pov): the normal faces the ray, the
// pattern's transforms move only the altitude (they do not turn the slope direction), and
// point_at aims from the world hit point.
#include "render/patterns/surface_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

// [lo, hi] stretched to [0, 1]; an empty range leaves v.
double stretch(double v, const glm::dvec2& range) {
    return range.x != range.y ? (v - range.x) / (range.y - range.x) : v;
}

// Back into [0, 1): POV-Ray keeps exactly 1 just below it and wraps the rest.
double wrap_unit(double v) {
    if (v < 0) return 1 + std::fmod(v, 1.0);
    return std::fmod(v, 1.0);
}

}  // namespace

double evaluate(const scene::pattern::Slope& k, const glm::dvec3& p, const SurfacePoint* s) {
    if (!s || !s->oriented) return 0;
    s->normal_read = true;
    glm::dvec3 towards = k.direction;
    if (k.point_at) {
        const glm::dvec3 d = k.direction - s->point;
        const double len = glm::length(d);
        towards = len > 0 ? d / len : glm::dvec3(0);
    }
    const double cosine = std::clamp(glm::dot(s->normal, towards), -1.0, 1.0);
    const double v1 = stretch((std::asin(cosine) * 2 / std::numbers::pi + 1) / 2, k.range);
    if (k.altitude_length == 0) return v1 == 1 ? 1 - kEpsilon : wrap_unit(v1);
    const double v2 = stretch(glm::dot(p, k.altitude), k.altitude_range);
    const double v = (k.length * v1 + k.altitude_length * v2) / (k.length + k.altitude_length);
    return v >= 1 && v < 1 + kEpsilon ? v - kEpsilon : wrap_unit(v);
}

// 0.5 where the ray meets the surface edge-on, 1 head-on (the normal faces the ray).
double evaluate(const scene::pattern::Aoi&, const glm::dvec3&, const SurfacePoint* s) {
    if (!s || !s->oriented) return 0;
    s->normal_read = true;
    const double cosine = std::clamp(glm::dot(s->normal, s->direction), -1.0, 1.0);
    return std::acos(cosine) / std::numbers::pi;
}

}  // namespace lumen::render

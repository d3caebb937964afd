// Disc: the plane through the centre, accepted between the hole and the outer radius.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/shapes/disc.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

DiscShape make_disc(const scene::Disc& d) {
    DiscShape out{d.center, d.normal, d.radius * d.radius, d.hole * d.hole, true};
    double len = glm::length(d.normal);
    out.valid = len > 0 && std::isfinite(len) && d.radius > 0 && std::isfinite(d.radius) &&
                std::isfinite(d.hole) && std::isfinite(glm::dot(d.center, d.center));
    if (out.valid) out.normal /= len;
    return out;
}

bool intersect(const DiscShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    double denom = glm::dot(s.normal, r.d);
    if (!s.valid || denom == 0) return false;
    double t = glm::dot(s.normal, s.centre - r.o) / denom;
    if (!(t > tmin && t < tmax)) return false;
    glm::dvec3 v = r.at(t) - s.centre;
    double d2 = glm::dot(v, v);
    if (d2 > s.radius2 || d2 < s.hole2) return false;
    h.t = t;
    h.normal = s.normal;
    return true;
}

Aabb bounds(const DiscShape& s) {
    if (!s.valid) return {};
    glm::dvec3 spread = glm::sqrt(glm::max(glm::dvec3(0), 1.0 - s.normal * s.normal));
    double radius = std::sqrt(s.radius2);
    return {s.centre - spread * radius, s.centre + spread * radius};
}

// A similarity keeps a disc a disc.
bool ShapeTraits<scene::Disc>::bake(const scene::Disc& d, const scene::Transform& xf,
                                    DiscShape& out) {
    const double k = similarity_scale(xf);
    if (!(k > 0)) return false;
    out = make_disc({xf.point(d.center), xf.normal(d.normal), d.radius * k, d.hole * k});
    return true;
}

}  // namespace lumen::render

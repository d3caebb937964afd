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

// POV-Ray's box: the square of side 2r around the disc, kDiscBoxThickness deep on each side,
// in the disc's frame, whose z axis is the normal and whose x and y axes are where the
// shortest rotation from z onto the normal takes them. Probed with povray: intersections of a
// box with a disc (normals y and <1, 2, 3>) show exactly the box's extent. The box matters:
// an intersection with a disc is bounded by it, so a ray that never meets it (one reflected
// up off the disc from inside, say) misses the whole intersection, in POV-Ray too.
Aabb bounds(const DiscShape& s) {
    if (!s.valid) return {};
    const glm::dvec3 n = s.normal;
    glm::dvec3 u(1, 0, 0), v(0, -1, 0);  // normal -z: half a turn about x
    if (1 + n.z > 1e-12) {
        const double k = 1 / (1 + n.z);
        u = {1 - n.x * n.x * k, -n.x * n.y * k, -n.x};
        v = {-n.x * n.y * k, 1 - n.y * n.y * k, -n.y};
    }
    const double radius = std::sqrt(s.radius2);
    const glm::dvec3 reach = radius * (glm::abs(u) + glm::abs(v)) + s.thickness * glm::abs(n);
    return {s.centre - reach, s.centre + reach};
}

// A similarity keeps a disc a disc.
bool ShapeTraits<scene::Disc>::bake(const scene::Disc& d, const scene::Transform& xf,
                                    DiscShape& out) {
    const double k = similarity_scale(xf);
    if (!(k > 0)) return false;
    out = make_disc({xf.point(d.center), xf.normal(d.normal), d.radius * k, d.hole * k});
    out.thickness *= k;
    return true;
}

}  // namespace lumen::render

// Plane n.p = d: infinite, so it always lands in the unbounded list.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/shapes/plane.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

PlaneShape make_plane(const scene::Plane& p) {
    PlaneShape out{p.normal, p.distance, true};
    double len = glm::length(p.normal);
    out.valid = len > 0 && std::isfinite(len) && std::isfinite(p.distance);
    if (out.valid) out.normal /= len;
    return out;
}

bool intersect(const PlaneShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    double denom = glm::dot(s.normal, r.d);
    if (!s.valid || denom == 0) return false;  // parallel rays miss (no 0/0)
    double t = (s.distance - glm::dot(s.normal, r.o)) / denom;
    if (!(t > tmin && t < tmax)) return false;
    h.t = t;
    h.normal = s.normal;
    return true;
}

// POV counts points within 1e-10 of the plane as inside (so a clip plane through a face
// keeps that face).
bool inside(const PlaneShape& s, const glm::dvec3& p) {
    return s.valid && glm::dot(s.normal, p) - s.distance < 1e-10;
}

Aabb bounds(const PlaneShape& s) { return s.valid ? Aabb::everything() : Aabb{}; }

Aabb solid_bounds(const PlaneShape& s) {
    Aabb box = bounds(s);
    if (!s.valid) return box;
    for (int a = 0; a < 3; ++a) {
        if (s.normal[(a + 1) % 3] != 0 || s.normal[(a + 2) % 3] != 0) continue;
        // Inside is n·p < d (within the 1e-10 inside() allows): one bound along this axis.
        if (s.normal[a] > 0) box.hi[a] = s.distance + 1e-10;
        else box.lo[a] = -s.distance - 1e-10;
    }
    return box;
}

Aabb complement_solid_bounds(const PlaneShape& s) {
    Aabb box = Aabb::everything();
    if (!s.valid) return box;  // never inside: inverted, inside everywhere
    for (int a = 0; a < 3; ++a) {
        if (s.normal[(a + 1) % 3] != 0 || s.normal[(a + 2) % 3] != 0) continue;
        // Inverted, inside is n·p - d >= 1e-10: one bound along this axis (with room to spare).
        if (s.normal[a] > 0) box.lo[a] = s.distance - 1e-10;
        else box.hi[a] = -s.distance + 1e-10;
    }
    return box;
}

// Any affine map keeps a plane a plane.
bool ShapeTraits<scene::Plane>::bake(const scene::Plane& p, const scene::Transform& xf,
                                     PlaneShape& out) {
    PlaneShape local = make_plane(p);
    if (!local.valid) return false;
    glm::dvec3 n = glm::normalize(xf.normal(local.normal));
    out = make_plane({n, glm::dot(n, xf.point(local.normal * local.distance))});
    return true;
}

}  // namespace lumen::render

// Sphere: the quadratic solved without cancellation (the discriminant from the ray's closest
// approach to the centre, the near root as c/q), accurate for small spheres far away.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/sphere.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {
namespace {
// Squared half-chord (scene units²) at or below which a ray counts as tangent and misses.
constexpr double kTangentEpsilon = 1e-10;
}  // namespace

SphereShape make_sphere(const scene::Sphere& s) {
    SphereShape out{s.center, s.radius, s.radius * s.radius, true};
    out.valid = s.radius > 0 && std::isfinite(s.radius) && std::isfinite(s.center.x) &&
                std::isfinite(s.center.y) && std::isfinite(s.center.z);
    return out;
}

bool intersect(const SphereShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    glm::dvec3 oc = r.o - s.centre;
    double a = glm::dot(r.d, r.d);
    double b = glm::dot(oc, r.d);
    // |oc - (b/a) d| is the distance of the closest approach: no large-number subtraction.
    glm::dvec3 perp = oc - (b / a) * r.d;
    const double half_chord2 = s.radius2 - glm::dot(perp, perp);
    // A tangent ray misses, as in POV-Ray: the squared half chord must exceed a tiny epsilon.
    if (!(half_chord2 > kTangentEpsilon)) return false;
    double disc = a * half_chord2;
    double q = -(b + std::copysign(std::sqrt(disc), b));
    double c = glm::dot(oc, oc) - s.radius2;
    double t0 = q != 0 ? c / q : 0, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    double t = t0 > tmin ? t0 : t1;
    if (!(t > tmin && t < tmax)) return false;
    h.t = t;
    h.normal = (r.at(t) - s.centre) / s.radius;
    return true;
}

bool inside(const SphereShape& s, const glm::dvec3& p) {
    glm::dvec3 v = p - s.centre;
    return s.valid && glm::dot(v, v) < s.radius2;
}

Aabb bounds(const SphereShape& s) {
    if (!s.valid) return {};
    return {s.centre - s.radius, s.centre + s.radius};
}

// A similarity keeps a sphere a sphere.
bool ShapeTraits<scene::Sphere>::bake(const scene::Sphere& s, const scene::Transform& xf,
                                      SphereShape& out) {
    const double k = similarity_scale(xf);
    if (!(k > 0)) return false;
    out = make_sphere({xf.point(s.center), s.radius * k});
    return true;
}

}  // namespace lumen::render

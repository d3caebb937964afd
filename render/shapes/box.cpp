// Box: slab test (a zero direction component divides to ±inf), the face normal from the slab
// that gave the entry or exit.
#include <cmath>

#include <glm/common.hpp>

#include "render/shapes/box.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

BoxShape make_box(const scene::Box& b) {
    BoxShape out{{glm::min(b.min, b.max), glm::max(b.min, b.max)}, true};
    out.valid = out.box.finite();
    return out;
}

bool intersect(const BoxShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    double enter = -Aabb::inf, exit = Aabb::inf;
    int enter_axis = 0, exit_axis = 0;
    for (int i = 0; i < 3; ++i) {
        // Divide (not multiply by 1/d): a face then gets the same depth as a plane through it,
        // bit for bit, so coplanar surfaces tie exactly and scene order decides, as in POV.
        double a = (s.box.lo[i] - r.o[i]) / r.d[i];
        double c = (s.box.hi[i] - r.o[i]) / r.d[i];
        if (a > c) std::swap(a, c);
        if (a > enter) { enter = a; enter_axis = i; }
        if (c < exit) { exit = c; exit_axis = i; }
    }
    if (!(enter <= exit)) return false;
    double t;
    int axis;
    if (enter > tmin) { t = enter; axis = enter_axis; }
    else { t = exit; axis = exit_axis; }
    if (!(t > tmin && t < tmax)) return false;
    h.t = t;
    h.normal = glm::dvec3(0);
    // Entering faces the ray (normal against d); leaving, along d.
    double sign = (t == enter) == (r.d[axis] > 0) ? -1.0 : 1.0;
    h.normal[axis] = sign;
    return true;
}

bool inside(const BoxShape& s, const glm::dvec3& p) {
    return s.valid && s.box.contains(p);
}

Aabb bounds(const BoxShape& s) { return s.valid ? s.box : Aabb{}; }

// Only an axis scaling (and translation) keeps a box axis-aligned.
bool ShapeTraits<scene::Box>::bake(const scene::Box& b, const scene::Transform& xf,
                                   BoxShape& out) {
    if (!is_axis_scaling(linear_part(xf))) return false;
    glm::dvec3 a = xf.point(b.min), c = xf.point(b.max);
    out = make_box({glm::min(a, c), glm::max(a, c)});
    return true;
}

}  // namespace lumen::render

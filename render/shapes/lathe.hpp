// lathe: a spline of points <radius, height> turned about the y axis. It has no caps: the
// surface is the turned curve alone, closed only where the curve closes.
#pragma once
#include "render/shapes/shape.hpp"
#include "render/shapes/spline_curve.hpp"

namespace lumen::render {

struct LatheShape {
    Curve curve;  // in (radius, height)
    double rmax = 0;
    bool valid = false;
    Aabb box;
};

LatheShape make_lathe(const scene::Lathe& l);
bool intersect(const LatheShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const LatheShape& s, const glm::dvec3& p);
Aabb bounds(const LatheShape& s);
inline Aabb solid_bounds(const LatheShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Lathe> : PreparedBy<scene::Lathe, LatheShape, make_lathe, &kDepthSwept> {
    // Not baked: traced in the lathe's own space, about its axis.
    static bool bake(const scene::Lathe&, const scene::Transform&, LatheShape&) { return false; }
};

}  // namespace lumen::render

// prism: a spline outline in the xz plane swept along y between two heights, straight up
// (linear_sweep) or as a cone from the origin (conic_sweep), capped unless open.
#pragma once
#include <cstdint>
#include "render/shapes/shape.hpp"
#include "render/shapes/spline_curve.hpp"

namespace lumen::render {

struct PrismShape {
    Curve curve;  // in (x, z); for conic, the outline at y = 1
    double h1 = 0, h2 = 1;
    bool conic = false, open = false;
    bool valid = false;  // an unclosed or degenerate outline is never hit
    Aabb box;
    uint64_t serial = 0;  // no other prism made in this run has it (prism.cpp's last-ray hits)
};

PrismShape make_prism(const scene::Prism& p);
bool intersect(const PrismShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const PrismShape& s, const glm::dvec3& p);
Aabb bounds(const PrismShape& s);
inline Aabb solid_bounds(const PrismShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Prism> : PreparedBy<scene::Prism, PrismShape, make_prism, &kDepthSwept> {
    // Not baked: the outline is traced in the prism's own space under its transform.
    static bool bake(const scene::Prism&, const scene::Transform&, PrismShape&) { return false; }
};

}  // namespace lumen::render

// sor: a surface of revolution about y whose squared radius is a cubic in the height on each
// segment, capped by discs at both ends unless open.
#pragma once
#include <vector>

#include "render/shapes/shape.hpp"

namespace lumen::render {

struct SorSegment {
    double a = 0, b = 0, c = 0, d = 0;  // r^2(y) = ((a y + b) y + c) y + d
    double y1 = 0, y2 = 0;
    double rmax = 0;  // the largest radius over [y1, y2]
    double r2(double y) const { return ((a * y + b) * y + c) * y + d; }
};

struct SorShape {
    std::vector<SorSegment> segments;
    double ymin = 0, ymax = 0, base_r2 = 0, cap_r2 = 0, rmax = 0;
    bool open = false, valid = false;
    Aabb box;
};

SorShape make_sor(const scene::Sor& s);
bool intersect(const SorShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const SorShape& s, const glm::dvec3& p);
Aabb bounds(const SorShape& s);
inline Aabb solid_bounds(const SorShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Sor> : PreparedBy<scene::Sor, SorShape, make_sor, &kDepthSwept> {
    // Not baked: traced in its own space, about its axis.
    static bool bake(const scene::Sor&, const scene::Transform&, SorShape&) { return false; }
};

}  // namespace lumen::render

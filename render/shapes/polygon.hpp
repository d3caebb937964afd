// Polygon: closed planar loops, even-odd filled, no inside.
#pragma once
#include <vector>

#include "render/shapes/shape.hpp"

namespace lumen::render {

struct PolygonShape {
    glm::dvec3 normal{0, 1, 0};
    double distance = 0;
    int axis_u = 0, axis_v = 2;                 // the dominant-axis projection plane
    std::vector<glm::dvec2> edges;              // pairs of projected end points
    Aabb box;
    bool valid = true;
};
PolygonShape make_polygon(const scene::Polygon& p);
bool intersect(const PolygonShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
inline bool inside(const PolygonShape&, const glm::dvec3&) { return false; }  // no inside
Aabb bounds(const PolygonShape& s);
inline Aabb solid_bounds(const PolygonShape&) { return {}; }

template <>
struct ShapeTraits<scene::Polygon>
    : PreparedBy<scene::Polygon, PolygonShape, make_polygon, &kDepthPolygon> {
    static bool bake(const scene::Polygon& p, const scene::Transform& xf, PolygonShape& out);
};

}  // namespace lumen::render

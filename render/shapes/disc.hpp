// Disc: a flat ring (outer radius, optional hole) with no inside.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct DiscShape {
    glm::dvec3 centre{0}, normal{0, 1, 0};
    double radius2 = 1, hole2 = 0;
    bool valid = true;
};
DiscShape make_disc(const scene::Disc& d);
bool intersect(const DiscShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
inline bool inside(const DiscShape&, const glm::dvec3&) { return false; }  // no inside
Aabb bounds(const DiscShape& s);
inline Aabb solid_bounds(const DiscShape&) { return {}; }

template <> struct ShapeTraits<scene::Disc> : PreparedBy<scene::Disc, DiscShape, make_disc> {
    static bool bake(const scene::Disc& d, const scene::Transform& xf, DiscShape& out);
};

}  // namespace lumen::render

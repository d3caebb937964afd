// Box: an axis-aligned box in object space.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct BoxShape { Aabb box; bool valid = true; };
BoxShape make_box(const scene::Box& b);
bool intersect(const BoxShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const BoxShape& s, const glm::dvec3& p);
Aabb bounds(const BoxShape& s);
inline Aabb solid_bounds(const BoxShape& s) { return bounds(s); }

template <> struct ShapeTraits<scene::Box> : PreparedBy<scene::Box, BoxShape, make_box> {
    static bool bake(const scene::Box& b, const scene::Transform& xf, BoxShape& out);
};

}  // namespace lumen::render

// ovus: the bottom sphere below the lemon, the lemon (the inner part of a spindle torus about
// y) between the heights where it touches the spheres, the top sphere above.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct OvusShape {
    double bottom = 1, top = 0.5;
    scene::Ovus::Lemon lemon{};
    bool valid = false;
};

OvusShape make_ovus(const scene::Ovus& o);
bool intersect(const OvusShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const OvusShape& s, const glm::dvec3& p);
Aabb bounds(const OvusShape& s);
inline Aabb solid_bounds(const OvusShape& s) { return bounds(s); }

template <> struct ShapeTraits<scene::Ovus> : PreparedBy<scene::Ovus, OvusShape, make_ovus> {
    static bool bake(const scene::Ovus&, const scene::Transform&, OvusShape&) { return false; }
};

}  // namespace lumen::render

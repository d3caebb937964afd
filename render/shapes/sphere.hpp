// Sphere: centre and radius.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct SphereShape { glm::dvec3 centre{0}; double radius = 1, radius2 = 1; bool valid = true; };
SphereShape make_sphere(const scene::Sphere& s);
bool intersect(const SphereShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const SphereShape& s, const glm::dvec3& p);
Aabb bounds(const SphereShape& s);
inline Aabb solid_bounds(const SphereShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Sphere> : PreparedBy<scene::Sphere, SphereShape, make_sphere> {
    static bool bake(const scene::Sphere& s, const scene::Transform& xf, SphereShape& out);
};

}  // namespace lumen::render

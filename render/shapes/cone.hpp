// Cylinder and cone share one canonical frame and one intersector: axis along local z from 0
// to `length`, radius r0 at z = 0 and r1 at z = length (equal for a cylinder).
#pragma once
#include <glm/mat3x3.hpp>

#include "render/shapes/shape.hpp"

namespace lumen::render {

struct ConeShape {
    glm::dmat3 to_axis{1.0};  // rotation taking object space (minus base) to the axis frame
    glm::dvec3 base{0};
    double length = 1, r0 = 1, r1 = 1;
    bool open = false, valid = true;
};
// A cylinder is traced as the cone with equal radii; its own type keeps ShapeData's
// alternatives one per listed shape.
struct CylinderShape : ConeShape {};

CylinderShape make_cylinder(const scene::Cylinder& c);
ConeShape make_cone(const scene::Cone& c);
bool intersect(const ConeShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const ConeShape& s, const glm::dvec3& p);
Aabb bounds(const ConeShape& s);
inline Aabb solid_bounds(const ConeShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Cylinder> : PreparedBy<scene::Cylinder, CylinderShape, make_cylinder> {
    static bool bake(const scene::Cylinder& c, const scene::Transform& xf, CylinderShape& out);
};

template <> struct ShapeTraits<scene::Cone> : PreparedBy<scene::Cone, ConeShape, make_cone> {
    static bool bake(const scene::Cone& c, const scene::Transform& xf, ConeShape& out);
};

}  // namespace lumen::render

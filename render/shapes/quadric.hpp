// quadric: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, inside where
// <= 0. As in POV-Ray the object transform is folded into the coefficients (bake), so the
// quadratic is formed with the world ray.
#pragma once
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct QuadricShape {
    glm::dvec3 square{1}, mixed{0}, linear{0};  // (A, B, C), (D xy, E xz, F yz), (G, H, I)
    double constant = 1;
    bool valid = true;
};

QuadricShape make_quadric(const scene::Quadric& q);
bool intersect(const QuadricShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const QuadricShape& s, const glm::dvec3& p);
Aabb bounds(const QuadricShape& s);
inline Aabb solid_bounds(const QuadricShape& s) { return bounds(s); }

template <>
struct ShapeTraits<scene::Quadric> : PreparedBy<scene::Quadric, QuadricShape, make_quadric> {
    static bool bake(const scene::Quadric& q, const scene::Transform& xf, QuadricShape& out);
};

}  // namespace lumen::render

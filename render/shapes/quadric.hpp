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
// The box of the inside (f <= 0) where the form allows one: ellipsoids, and any quadric
// without mixed terms between the planes of a CSG intersection (bounds_within).
Aabb bounds(const QuadricShape& s);
inline Aabb solid_bounds(const QuadricShape& s) { return bounds(s); }
// The box of the inside within `clip`, for a quadric without mixed terms (else `clip`): along
// each axis, where f can still be <= 0 given the least the other axes' terms can add in the
// clip box (a cylinder between two planes gets its radius; a cone or hyperboloid its widest
// circle between them). Widened by a millionth, as hits near tangency are rounded.
Aabb bounds_within(const QuadricShape& s, const Aabb& clip);

template <>
struct ShapeTraits<scene::Quadric> : PreparedBy<scene::Quadric, QuadricShape, make_quadric> {
    static bool bake(const scene::Quadric& q, const scene::Transform& xf, QuadricShape& out);
};

}  // namespace lumen::render

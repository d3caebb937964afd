// poly, cubic and quartic: the surface F(x, y, z) = 0 of a polynomial of order 2..35, solved
// along the ray with POV-Ray's solver rules (render/pov_polynomial.hpp). POV-Ray never bounds
// it; lumen bounds the surfaces it can prove bounded (render/shapes/poly_bounds.hpp).
#pragma once
#include <vector>

#include "render/shapes/poly_bounds.hpp"
#include "render/shapes/shape.hpp"

namespace lumen::render {

struct PolyShape {
    int order = 2;
    std::vector<double> coeffs;  // POV-Ray's term order (scene::Poly)
    bool sturm = false;
    bool valid = false;
    // The non-zero terms c x^i y^j z^k, in that order: the per-ray expansion visits only these
    // (a sextic has 84 terms, x^6 + y^6 + z^6 - c has 4).
    using Term = PolyTerm;
    std::vector<Term> terms;
    Aabb box = Aabb::everything();  // render/shapes/poly_bounds.hpp
};

PolyShape make_poly(const scene::Poly& p);
bool intersect(const PolyShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h);
bool inside(const PolyShape& s, const glm::dvec3& p);
Aabb bounds(const PolyShape& s);
inline Aabb solid_bounds(const PolyShape& s) { return bounds(s); }

// F at p, and its gradient.
double poly_value(const PolyShape& s, const glm::dvec3& p);
glm::dvec3 poly_gradient(const PolyShape& s, const glm::dvec3& p);
// The roots along o + k d (d unit) that POV-Ray keeps: k > 1e-4, duplicates dropped,
// unordered. Returns the count (<= order).
int poly_roots(const PolyShape& s, const glm::dvec3& o, const glm::dvec3& d, double* ks);

template <> struct ShapeTraits<scene::Poly> : PreparedBy<scene::Poly, PolyShape, make_poly> {
    // Not baked: POV-Ray solves in the polynomial's own space, with the direction normalised.
    static bool bake(const scene::Poly&, const scene::Transform&, PolyShape&) { return false; }
};

}  // namespace lumen::render

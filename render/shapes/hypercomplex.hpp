// The 4-D algebras julia_fractal iterates in. Quaternions (i^2 = j^2 = k^2 = ijk = -1) and
// hypercomplex numbers (i^2 = j^2 = -1, k^2 = +1, ij = k, commutative) are both kept as
// glm::dvec4 (x, y, z, w) = x + y i + z j + w k.
//
// A hypercomplex number splits into two independent complex numbers (its duplex form),
//     a = (x - w) + (y + z) i,   b = (x + w) + (y - z) i,
// so that f(h) for any complex function f is f applied to a and to b. POV-Ray iterates in the
// 4-D form, converting to the duplex form and back at every step; near the set's boundary the
// orbit depends on that rounding, so lumen does the same arithmetic in the same order.
#pragma once
#include <complex>

#include <glm/vec4.hpp>

#include "scene/shapes.hpp"

namespace lumen::render {

using Complex = std::complex<double>;

inline glm::dvec4 quaternion_product(const glm::dvec4& p, const glm::dvec4& q) {
    return {p.x * q.x - p.y * q.y - p.z * q.z - p.w * q.w,
            p.x * q.y + p.y * q.x + p.z * q.w - p.w * q.z,
            p.x * q.z - p.y * q.w + p.z * q.x + p.w * q.y,
            p.x * q.w + p.y * q.z - p.z * q.y + p.w * q.x};
}

inline glm::dvec4 hypercomplex_product(const glm::dvec4& p, const glm::dvec4& q) {
    return {p.x * q.x - p.y * q.y - p.z * q.z + p.w * q.w,
            p.y * q.x + p.x * q.y - p.w * q.z - p.z * q.w,
            p.z * q.x - p.w * q.y + p.x * q.z - p.y * q.w,
            p.w * q.x + p.z * q.y + p.y * q.z + p.x * q.w};
}

// sqr's escape norm and step, inline for the march (the general forms below use them).
inline double hypercomplex_sqr_norm2(const glm::dvec4& h) {
    return (h.x * h.x + h.w * h.w) + (h.y * h.y + h.z * h.z);
}
inline glm::dvec4 hypercomplex_sqr_step(const glm::dvec4& h, const glm::dvec4& c) {
    const double yz = h.y * h.y + h.z * h.z, xw = h.x * h.x + h.w * h.w;
    return {xw - yz + c.x, 2.0 * (h.x * h.y - h.z * h.w) + c.y,
            2.0 * (h.x * h.z - h.w * h.y) + c.z, 2.0 * (h.x * h.w + h.y * h.z) + c.w};
}

// |h|^2, summed as POV-Ray's escape test sums it for `fn` (sqr pairs x with w, y with z).
double hypercomplex_norm2(scene::JuliaFunction fn, const glm::dvec4& h);

// One step of the iteration: f(h) + c (sqr and cube both square: POV-Ray's hypercomplex cube
// iterates z^2 + c; measured, its inside test agrees with sqr's everywhere).
glm::dvec4 hypercomplex_step(scene::JuliaFunction fn, const glm::dvec4& h, const glm::dvec4& c,
                             const Complex& exponent);

// The factor each iterate after the first contributes to POV-Ray's derivative chain: h for
// sqr and cube, -1/h^2 for reciprocal, and f(h) itself (not f') for the other functions.
glm::dvec4 hypercomplex_chain_factor(scene::JuliaFunction fn, const glm::dvec4& h,
                                     const Complex& exponent);

// The complex function `fn` as POV-Ray evaluates it (its formulas and branches; pwr: z^e).
Complex julia_complex_function(scene::JuliaFunction fn, const Complex& z, const Complex& e);

}  // namespace lumen::render

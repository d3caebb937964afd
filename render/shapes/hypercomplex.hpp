// The 4-D algebras julia_fractal iterates in. Quaternions (i^2 = j^2 = k^2 = ijk = -1) are
// kept as glm::dvec4 (x, y, z, w). Hypercomplex numbers (i^2 = j^2 = -1, k^2 = +1, ij = k,
// commutative) split into two independent complex numbers,
//     a = (x - w) + (y + z) i,   b = (x + w) + (y - z) i,
// so that h -> f(h) is f applied to a and to b: every function POV-Ray offers (exp, sin, ...)
// is the complex one on each half. |h|^2 = (|a|^2 + |b|^2) / 2.
#pragma once
#include <complex>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "scene/shapes.hpp"

namespace lumen::render {

using Complex = std::complex<double>;

// ---- quaternions ------------------------------------------------------------------------
inline glm::dvec4 quaternion_product(const glm::dvec4& p, const glm::dvec4& q) {
    return {p.x * q.x - p.y * q.y - p.z * q.z - p.w * q.w,
            p.x * q.y + p.y * q.x + p.z * q.w - p.w * q.z,
            p.x * q.z - p.y * q.w + p.z * q.x + p.w * q.y,
            p.x * q.w + p.y * q.z - p.z * q.y + p.w * q.x};
}

// ---- hypercomplex numbers as a pair of complex numbers -----------------------------------
struct Bicomplex {
    Complex a, b;
};

inline Bicomplex to_bicomplex(const glm::dvec4& h) {
    return {{h.x - h.w, h.y + h.z}, {h.x + h.w, h.y - h.z}};
}
inline glm::dvec4 from_bicomplex(const Bicomplex& p) {
    const Complex u = 0.5 * (p.a + p.b), v = 0.5 * (p.b - p.a);  // h = u + v k
    return {u.real(), u.imag(), -v.imag(), v.real()};
}
inline double norm2(const Bicomplex& p) { return 0.5 * (std::norm(p.a) + std::norm(p.b)); }
// The 4-D dot product of two hypercomplex numbers, in pair form.
inline double dot(const Bicomplex& p, const Bicomplex& q) {
    return 0.5 * ((p.a * std::conj(q.a)).real() + (p.b * std::conj(q.b)).real());
}

// f(z) and f'(z) of julia_fractal's function `fn` (pwr: z^e, e the complex exponent).
Complex julia_function(scene::JuliaFunction fn, const Complex& z, const Complex& e);
Complex julia_derivative(scene::JuliaFunction fn, const Complex& z, const Complex& e);

}  // namespace lumen::render

// The complex functions julia_fractal's hypercomplex iteration applies to each half, with
// their derivatives (for the distance estimate and the normal). Principal branches.
#include "render/shapes/hypercomplex.hpp"

namespace lumen::render {

using scene::JuliaFunction;

Complex julia_function(JuliaFunction fn, const Complex& z, const Complex& e) {
    switch (fn) {
        case JuliaFunction::Sqr: return z * z;
        case JuliaFunction::Cube: return z * z * z;
        case JuliaFunction::Exp: return std::exp(z);
        case JuliaFunction::Reciprocal: return 1.0 / z;
        case JuliaFunction::Sin: return std::sin(z);
        case JuliaFunction::Asin: return std::asin(z);
        case JuliaFunction::Sinh: return std::sinh(z);
        case JuliaFunction::Asinh: return std::asinh(z);
        case JuliaFunction::Cos: return std::cos(z);
        case JuliaFunction::Acos: return std::acos(z);
        case JuliaFunction::Cosh: return std::cosh(z);
        case JuliaFunction::Acosh: return std::acosh(z);
        case JuliaFunction::Tan: return std::tan(z);
        case JuliaFunction::Atan: return std::atan(z);
        case JuliaFunction::Tanh: return std::tanh(z);
        case JuliaFunction::Atanh: return std::atanh(z);
        case JuliaFunction::Ln: return std::log(z);
        case JuliaFunction::Pwr: return std::exp(e * std::log(z));
    }
    return z * z;
}

Complex julia_derivative(JuliaFunction fn, const Complex& z, const Complex& e) {
    const Complex one(1, 0);
    switch (fn) {
        case JuliaFunction::Sqr: return 2.0 * z;
        case JuliaFunction::Cube: return 3.0 * z * z;
        case JuliaFunction::Exp: return std::exp(z);
        case JuliaFunction::Reciprocal: return -one / (z * z);
        case JuliaFunction::Sin: return std::cos(z);
        case JuliaFunction::Asin: return one / std::sqrt(one - z * z);
        case JuliaFunction::Sinh: return std::cosh(z);
        case JuliaFunction::Asinh: return one / std::sqrt(one + z * z);
        case JuliaFunction::Cos: return -std::sin(z);
        case JuliaFunction::Acos: return -one / std::sqrt(one - z * z);
        case JuliaFunction::Cosh: return std::sinh(z);
        case JuliaFunction::Acosh: return one / (std::sqrt(z - one) * std::sqrt(z + one));
        case JuliaFunction::Tan: { const Complex c = std::cos(z); return one / (c * c); }
        case JuliaFunction::Atan: return one / (one + z * z);
        case JuliaFunction::Tanh: { const Complex c = std::cosh(z); return one / (c * c); }
        case JuliaFunction::Atanh: return one / (one - z * z);
        case JuliaFunction::Ln: return one / z;
        case JuliaFunction::Pwr: return e * std::exp((e - one) * std::log(z));
    }
    return 2.0 * z;
}

}  // namespace lumen::render

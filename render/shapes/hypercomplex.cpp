// POV-Ray's hypercomplex arithmetic for julia_fractal, operation for operation: the orbit of
// a point near the set's boundary depends on the rounding, and the march's silhouettes on the
// orbit. The complex functions are evaluated by POV-Ray's own formulas (principal branches,
// its special cases), not by <complex>, whose rounding differs.
#include "render/shapes/hypercomplex.hpp"

#include <cmath>

namespace lumen::render {

using scene::JuliaFunction;

namespace {

struct Cx {  // a complex number with POV-Ray's operations
    double x = 0, y = 0;
};

Cx mul(const Cx& a, const Cx& b) { return {a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x}; }

// a / b; b = 0 leaves the result as it was (POV-Ray's result is unset then; lumen keeps `a`).
Cx div(const Cx& a, const Cx& b) {
    const double mod = b.x * b.x + b.y * b.y;
    if (mod == 0) return a;
    const double xm = b.x / mod, ym = -b.y / mod;
    return {a.x * xm - a.y * ym, a.x * ym + a.y * xm};
}

Cx ln(const Cx& z) { return {std::log(std::sqrt(z.x * z.x + z.y * z.y)), std::atan2(z.y, z.x)}; }

Cx root(const Cx& z) {
    if (z.x == 0 && z.y == 0) return {};
    const double mag = std::sqrt(std::sqrt(z.x * z.x + z.y * z.y));
    const double theta = std::atan2(z.y, z.x) / 2;
    return {mag * std::cos(theta), mag * std::sin(theta)};
}

Cx atanh(const Cx& z) {
    if (z.x == 0) return {0, std::atan(z.y)};
    if (std::fabs(z.x) == 1 && z.y == 0) return z;  // POV-Ray leaves the result unset
    if (std::fabs(z.x) < 1 && z.y == 0) return {std::log((1 + z.x) / (1 - z.x)) / 2, 0};
    const Cx l = ln(div({1 + z.x, z.y}, {1 - z.x, -z.y}));
    return {0.5 * l.x, 0.5 * l.y};
}

Cx atan(const Cx& z) {
    if (z.x == 0 && z.y == 0) return {};
    if (z.y == 0) return {std::atan(z.x), 0};
    if (z.x == 0) {
        const Cx t = atanh({z.y, 0});
        return {-t.y, t.x};
    }
    const Cx iz{-z.y, z.x};
    const Cx l = ln(div({1 - iz.x, -iz.y}, {1 + iz.x, iz.y}));
    return {-l.y * 0.5, 0.5 * l.x};
}

Cx evaluate(JuliaFunction fn, const Cx& z, const Cx& e) {
    switch (fn) {
        case JuliaFunction::Exp: {
            const double ex = std::exp(z.x);
            return {ex * std::cos(z.y), ex * std::sin(z.y)};
        }
        case JuliaFunction::Ln: return ln(z);
        case JuliaFunction::Sin: return {std::sin(z.x) * std::cosh(z.y), std::cos(z.x) * std::sinh(z.y)};
        case JuliaFunction::Sinh: return {std::sinh(z.x) * std::cos(z.y), std::cosh(z.x) * std::sin(z.y)};
        case JuliaFunction::Cos: return {std::cos(z.x) * std::cosh(z.y), -std::sin(z.x) * std::sinh(z.y)};
        case JuliaFunction::Cosh: return {std::cosh(z.x) * std::cos(z.y), std::sinh(z.x) * std::sin(z.y)};
        case JuliaFunction::Asin: {  // -i ln(i z + sqrt(1 - z^2))
            const Cx z2 = mul(z, z);
            Cx t = root({1 - z2.x, -z2.y});
            t = ln({t.x - z.y, t.y + z.x});
            return {t.y, -t.x};
        }
        case JuliaFunction::Acos: {  // -i ln(z + sqrt(z^2 - 1))
            const Cx z2 = mul(z, z);
            Cx t = root({z2.x - 1, z2.y});
            t = ln({t.x + z.x, t.y + z.y});
            return {t.y, -t.x};
        }
        case JuliaFunction::Asinh: {  // ln(z + sqrt(z^2 + 1))
            const Cx z2 = mul(z, z);
            const Cx t = root({z2.x + 1, z2.y});
            return ln({t.x + z.x, t.y + z.y});
        }
        case JuliaFunction::Acosh: {  // ln(z + sqrt(z^2 - 1))
            const Cx z2 = mul(z, z);
            const Cx t = root({z2.x - 1, z2.y});
            return ln({z.x + t.x, z.y + t.y});
        }
        case JuliaFunction::Tan: {
            const double x = 2 * z.x, y = 2 * z.y, d = std::cos(x) + std::cosh(y);
            if (d == 0) return z;  // POV-Ray leaves the result unset
            return {std::sin(x) / d, std::sinh(y) / d};
        }
        case JuliaFunction::Tanh: {
            const double x = 2 * z.x, y = 2 * z.y, d = std::cosh(x) + std::cos(y);
            if (d == 0) return z;
            return {std::sinh(x) / d, std::sin(y) / d};
        }
        case JuliaFunction::Atan: return atan(z);
        case JuliaFunction::Atanh: return atanh(z);
        case JuliaFunction::Pwr: {
            if (z.x == 0 && z.y == 0) return {};
            const Cx t = mul(ln(z), e);
            const double ex = t.x < -690 ? 0 : std::exp(t.x);
            return {ex * std::cos(t.y), ex * std::sin(t.y)};
        }
        case JuliaFunction::Sqr: return mul(z, z);
        case JuliaFunction::Cube: return mul(mul(z, z), z);
        case JuliaFunction::Reciprocal: return div({1, 0}, z);
    }
    return z;
}

glm::dvec4 square(const glm::dvec4& h) {
    return {h.x * h.x - h.y * h.y - h.z * h.z + h.w * h.w, 2.0 * (h.x * h.y - h.z * h.w),
            2.0 * (h.z * h.x - h.w * h.y), 2.0 * (h.w * h.x + h.z * h.y)};
}

// 1/h; a zero divisor (h on the null cone) leaves h (POV-Ray's result is unset then).
glm::dvec4 reciprocal(const glm::dvec4& h) {
    const double x = h.x, y = h.y, z = h.z, w = h.w;
    const double det = ((x - w) * (x - w) + (y + z) * (y + z)) * ((x + w) * (x + w) + (y - z) * (y - z));
    if (det == 0) return h;
    const double mod = x * x + y * y + z * z + w * w, t = x * w - y * z;
    return {(x * mod - 2 * w * t) / det, (-y * mod - 2 * z * t) / det,
            (-z * mod - 2 * y * t) / det, (w * mod - 2 * x * t) / det};
}

// f applied to each half of the duplex form, and back.
glm::dvec4 duplex_apply(JuliaFunction fn, const glm::dvec4& h, const Complex& exponent) {
    const Cx e{exponent.real(), exponent.imag()};
    const Cx ra = evaluate(fn, {h.x - h.w, h.y + h.z}, e);
    const Cx rb = evaluate(fn, {h.x + h.w, h.y - h.z}, e);
    return {.5 * (ra.x + rb.x), .5 * (ra.y + rb.y), .5 * (ra.y - rb.y), .5 * (rb.x - ra.x)};
}

}  // namespace

double hypercomplex_norm2(JuliaFunction fn, const glm::dvec4& h) {
    if (fn == JuliaFunction::Sqr) return hypercomplex_sqr_norm2(h);
    return h.x * h.x + h.y * h.y + h.z * h.z + h.w * h.w;
}

glm::dvec4 hypercomplex_step(JuliaFunction fn, const glm::dvec4& h, const glm::dvec4& c,
                             const Complex& exponent) {
    switch (fn) {
        case JuliaFunction::Sqr: return hypercomplex_sqr_step(h, c);
        case JuliaFunction::Cube: return square(h) + c;
        case JuliaFunction::Reciprocal: return reciprocal(h) + c;
        default: return duplex_apply(fn, h, exponent) + c;
    }
}

glm::dvec4 hypercomplex_chain_factor(JuliaFunction fn, const glm::dvec4& h,
                                     const Complex& exponent) {
    switch (fn) {
        case JuliaFunction::Sqr:
        case JuliaFunction::Cube: return h;
        case JuliaFunction::Reciprocal: return -square(reciprocal(h));
        default: return duplex_apply(fn, h, exponent);
    }
}

Complex julia_complex_function(JuliaFunction fn, const Complex& z, const Complex& e) {
    const Cx r = evaluate(fn, {z.real(), z.imag()}, {e.real(), e.imag()});
    return {r.x, r.y};
}

}  // namespace lumen::render

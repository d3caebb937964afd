// Iteration, escape tests and the interior/exterior colouring rules follow POV-Ray 3.7,
// checked pixel for pixel against povray renders (tests/patterns/fractal_*.pov), including
// its quirks: the escape count is 0-based, interior type 6 is a² + b²·factor, and magnet
// escapes when the orbit passes close to 1 as well as when it grows large.
#include "render/patterns/fractals.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace lumen::render {
namespace {

namespace pattern = scene::pattern;

struct Complex {
    double a, b;
};

// The orbit's end: the step it escaped at (or the iteration count), where it ended and the
// least squared distance from 0 it reached.
struct Orbit {
    int steps;
    bool escaped;
    Complex z;
    double min_dist2;
};

// A type or modulus written as a float, truncated; out of any int's range (or NaN) it is -1.
int truncated(double v) { return v > -1e9 && v < 1e9 ? int(v) : -1; }

double exterior_value(const pattern::Fractal& k, const Orbit& o) {
    const double f = k.exterior.y;
    const double a = o.z.a, b = o.z.b;
    switch (truncated(k.exterior.x)) {
        case 0: return f;
        case 1: return double(o.steps) / k.iterations;
        case 2: return a * f;
        case 3: return b * f;
        case 4: return a * a * f;
        case 5: return b * b * f;
        case 6: return std::sqrt(a * a + b * b) * f;
        case 7: return double(o.steps % std::max(1, truncated(f))) / f;
        case 8: return double(o.steps % std::max(1, truncated(1 + f))) / f;
    }
    return 0;
}

double interior_value(const pattern::Fractal& k, const Orbit& o) {
    const double f = k.interior.y;
    const double a = o.z.a, b = o.z.b;
    switch (truncated(k.interior.x)) {
        case 0: return f;
        case 1: return std::sqrt(o.min_dist2) * f;
        case 2: return a * f;
        case 3: return b * f;
        case 4: return a * a * f;
        case 5: return b * b * f;
        case 6: return a * a + b * b * f;  // sic: POV-Ray's precedence
    }
    return 0;
}

double value_of(const pattern::Fractal& k, const Orbit& o) {
    return o.escaped ? exterior_value(k, o) : interior_value(k, o);
}

// Binomial coefficients C(n, k) for the generic powers (n up to 33).
using BinomialRow = std::array<double, 34>;
const std::array<BinomialRow, 34>& binomials() {
    static const std::array<BinomialRow, 34> table = [] {
        std::array<BinomialRow, 34> t{};
        for (int n = 0; n < 34; ++n) {
            t[n][0] = 1;
            for (int j = 1; j <= n; ++j) t[n][j] = t[n - 1][j - 1] + (j < n ? t[n - 1][j] : 0);
        }
        return t;
    }();
    return table;
}

// z^e for e = 5..33 by the binomial expansion, terms in increasing powers of b.
Complex power(Complex z, int e) {
    const BinomialRow& c = binomials()[e];
    double pa[34], pb[34];
    pa[0] = pb[0] = 1;
    for (int i = 1; i <= e; ++i) pa[i] = pa[i - 1] * z.a, pb[i] = pb[i - 1] * z.b;
    Complex r{0, 0};
    for (int k = 0; k <= e; ++k) {
        const double term = ((k & 2) ? -c[k] : c[k]) * pa[e - k] * pb[k];
        if (k & 1) r.b += term;
        else r.a += term;
    }
    return r;
}

// One step z <- z^e + c of mandel and julia.
Complex step(Complex z, Complex c, int e) {
    const double a = z.a, b = z.b;
    switch (e) {
        case 2: return {a * a - b * b + c.a, 2 * a * b + c.b};
        case 3: return {a * a * a - 3 * a * b * b + c.a, 3 * a * a * b - b * b * b + c.b};
        case 4: {
            const double a2 = a * a, b2 = b * b;
            return {a2 * a2 - 6 * a2 * b2 + b2 * b2 + c.a, 4 * a2 * a * b - 4 * a * b2 * b + c.b};
        }
        default: {
            const Complex p = power(z, e);
            return {p.a + c.a, p.b + c.b};
        }
    }
}

// mandel and julia: escape once |z|² exceeds 4.
double polynomial_fractal(const pattern::Fractal& k, Complex z, Complex c) {
    Orbit o{k.iterations, false, z, z.a * z.a + z.b * z.b};
    for (int n = 0; n < k.iterations; ++n) {
        o.z = step(o.z, c, k.exponent);
        const double d2 = o.z.a * o.z.a + o.z.b * o.z.b;
        o.min_dist2 = std::min(o.min_dist2, d2);
        if (d2 > 4) {
            o.steps = n;
            o.escaped = true;
            break;
        }
    }
    return value_of(k, o);
}

Complex mul(Complex x, Complex y) { return {x.a * y.a - x.b * y.b, x.a * y.b + x.b * y.a}; }
Complex div(Complex x, Complex y) {
    const double d = y.a * y.a + y.b * y.b;
    return {(x.a * y.a + x.b * y.b) / d, (x.b * y.a - x.a * y.b) / d};
}

// One magnet step: z <- w², w the type's rational function of z and c.
Complex magnet_step(Complex z, Complex c, int type) {
    Complex w;
    if (type == 1) {  // (z² + c − 1) / (2z + c − 2)
        const Complex z2 = mul(z, z);
        w = div({z2.a + c.a - 1, z2.b + c.b}, {2 * z.a + c.a - 2, 2 * z.b + c.b});
    } else {  // (z³ + 3(c−1)z + (c−1)(c−2)) / (3z² + 3(c−2)z + (c−1)(c−2) + 1)
        const Complex z2 = mul(z, z), z3 = mul(z2, z);
        const Complex c1{c.a - 1, c.b}, c2{c.a - 2, c.b};
        const Complex c1z = mul(c1, z), c2z = mul(c2, z), c12 = mul(c1, c2);
        w = div({z3.a + 3 * c1z.a + c12.a, z3.b + 3 * c1z.b + c12.b},
                {3 * z2.a + 3 * c2z.a + c12.a + 1, 3 * z2.b + 3 * c2z.b + c12.b});
    }
    return mul(w, w);
}

}  // namespace

double evaluate(const pattern::Mandel& k, const glm::dvec3& p) {
    return polynomial_fractal(k, {p.x, p.y}, {p.x, p.y});
}

double evaluate(const pattern::Julia& k, const glm::dvec3& p) {
    return polynomial_fractal(k, {p.x, p.y}, {k.c.x, k.c.y});
}

// Escapes when |z|² exceeds 10000 or z comes within 0.01 of 1 (the fixed point).
double evaluate(const pattern::Magnet& k, const glm::dvec3& p) {
    const Complex c = k.julia ? Complex{k.c.x, k.c.y} : Complex{p.x, p.y};
    const Complex z0 = k.julia ? Complex{p.x, p.y} : Complex{0, 0};
    Orbit o{k.iterations, false, z0, k.julia ? z0.a * z0.a + z0.b * z0.b : 10000.0};
    for (int n = 0; n < k.iterations; ++n) {
        o.z = magnet_step(o.z, c, k.type);
        const double d2 = o.z.a * o.z.a + o.z.b * o.z.b;
        o.min_dist2 = std::min(o.min_dist2, d2);
        if (d2 > 10000 || (o.z.a - 1) * (o.z.a - 1) + o.z.b * o.z.b < 1e-4) {
            o.steps = n;
            o.escaped = true;
            break;
        }
    }
    return value_of(k, o);
}

const scene::ColourMap& mandel_map() {
    static const scene::ColourMap m{{0.001, {0, 0, 0, 0, 0}},
                                    {0.001, {0, 1, 1, 0, 0}},
                                    {0.012, {1, 1, 0, 0, 0}},
                                    {0.015, {1, 0, 1, 0, 0}},
                                    {0.1, {0, 1, 1, 0, 0}}};
    return m;
}

}  // namespace lumen::render

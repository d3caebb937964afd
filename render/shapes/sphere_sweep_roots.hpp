// The polynomials of sphere_sweep's segments (render/shapes/sphere_sweep.cpp) and where they
// vanish, found by Bernstein subdivision: on a piece of the parameter range, the signs of
// the Bernstein coefficients bound the roots there (no sign change: none; one: exactly one,
// bracketed by the piece's ends), so only pieces with two or more changes are split. This
// stops at once on the many pieces with no root, where the derivative-interval solver of
// render/polynomial.hpp would descend through every derivative first.
#pragma once

namespace lumen::render {

// A polynomial of degree <= 10, lowest power first.
struct SweepPoly {
    static constexpr int kMax = 10;
    double c[kMax + 1]{};
    int n = 0;
};

SweepPoly operator*(const SweepPoly& a, const SweepPoly& b);
SweepPoly add(const SweepPoly& a, double k, const SweepPoly& b);  // a + k b
SweepPoly derivative(const SweepPoly& a);
SweepPoly constant(double x);

// False when p <= 0 all over [0, 1] (its Bernstein coefficients bound it there).
bool positive_somewhere(const SweepPoly& p);

// Parameters in [lo, hi] where p may vanish, unordered, at most `room` of them: each simple
// root, refined to double precision, and where two roots (or a double root) lie closer than
// 1e-10 times the range, the middle of the piece holding them. Returns the count.
int root_candidates(const SweepPoly& p, double lo, double hi, double* out, int room);

}  // namespace lumen::render

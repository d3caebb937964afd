// Real roots of low-degree polynomials, robust enough for grazing rays (torus quartic).
#pragma once

namespace lumen::render {

// Roots of a*t^2 + 2*b_half*t + c = 0 with the cancellation-free formula; returns how many
// (0..2), ascending. A double root is returned once.
int solve_quadratic(double a, double b_half, double c, double roots[2]);

// Evaluates c[0] + c[1] t + ... + c[n] t^n (coefficients lowest power first).
double eval_poly(const double* c, int n, double t);

// Every real root of the degree-n polynomial (lowest power first, n <= 8) in [lo, hi],
// ascending. Roots are isolated between the roots of the derivative (found recursively), so
// each bracket is monotone and is refined by safeguarded Newton; this never misses a simple
// root and never returns NaN. A tangent (double) root counts only if the polynomial is 0 or
// changes sign there. Returns the count (<= n). With `max_roots`, only the lowest that many
// (a ray's nearest hit needs one): the same values, the later brackets left unrefined.
int solve_polynomial_in(const double* c, int n, double lo, double hi, double* roots,
                        int max_roots = 8);

// How many roots solve_polynomial_in would return (with every max_roots), found without
// refining them.
int count_roots_in(const double* c, int n, double lo, double hi);

// The degree of c (lowest power first) once the leading coefficients below `tiny` in
// magnitude are dropped, as POV-Ray's polynomial solver drops them (an absolute test, so a
// nearly degenerate cubic is solved as the quadratic or line it nearly is).
int significant_degree(const double* c, int n, double tiny = 1e-10);

// solve_polynomial_in after POV-Ray's leading-coefficient test (significant_degree).
int solve_significant_in(const double* c, int n, double lo, double hi, double* roots);

}  // namespace lumen::render

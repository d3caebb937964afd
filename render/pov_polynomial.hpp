// POV-Ray's polynomial solver, with its rules (poly, cubic, quartic): closed forms for degrees
// 2-4, a Sturm sequence search for higher degrees, for `sturm` and for quartics whose
// coefficients span more than 12 orders of magnitude. Images of those shapes depend on these
// rules (which roots a near-tangent ray gets, which t ~ 0 roots are dropped), so they are kept
// as POV-Ray has them rather than replaced by the sturdier render/polynomial.hpp.
#pragma once

namespace lumen::render {

// The largest degree the solver takes (POV-Ray's MAX_ORDER).
constexpr int kMaxPolyOrder = 35;

// Roots of c[0] t^n + c[1] t^(n-1) + ... + c[n] (HIGHEST power first, as POV-Ray stores them),
// n <= kMaxPolyOrder, written to roots (room for n), unordered; returns their count.
// - Leading coefficients below 1e-10 in magnitude are dropped (an absolute test).
// - eps > 0: for degree 3 and 4, when |c[n] / c[n-1]| < eps the root near 0 is divided out
//   and the rest solved.
// - The Sturm search returns only roots in [0, 1e7]; the closed forms return negative ones too.
int solve_pov_polynomial(int n, const double* c, double* roots, bool sturm, double eps);

namespace pov_solver {  // the pieces, for tests
int solve_quadratic(const double* c, double* roots);  // c[0] t^2 + c[1] t + c[2]
int solve_cubic(const double* c, double* roots);
int solve_quartic(const double* c, double* roots);
int sturm_roots(int n, const double* c, double* roots);  // roots in [0, 1e7]
bool difficult_coefficients(int n, const double* c);
}  // namespace pov_solver

}  // namespace lumen::render

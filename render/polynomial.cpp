// Root isolation by derivative sign intervals: between two consecutive critical points a
// polynomial is monotone, so it has at most one root there, found by bracketed Newton.
#include "render/polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace lumen::render {

int solve_quadratic(double a, double b_half, double c, double roots[2]) {
    if (a == 0) {
        if (b_half == 0) return 0;
        roots[0] = -c / (2 * b_half);
        return std::isfinite(roots[0]) ? 1 : 0;
    }
    double disc = b_half * b_half - a * c;
    if (disc < 0 || !std::isfinite(disc)) return 0;
    double q = -(b_half + std::copysign(std::sqrt(disc), b_half));
    if (q == 0) {  // b_half == 0 and c == 0: double root at 0
        roots[0] = 0;
        return 1;
    }
    double r0 = c / q, r1 = q / a;
    if (r0 > r1) std::swap(r0, r1);
    roots[0] = r0;
    if (r1 == r0) return 1;
    roots[1] = r1;
    return 2;
}

double eval_poly(const double* c, int n, double t) {
    double v = c[n];
    for (int i = n - 1; i >= 0; --i) v = v * t + c[i];
    return v;
}

namespace {

double eval_with_derivative(const double* c, int n, double t, double& deriv) {
    double v = c[n], d = 0;
    for (int i = n - 1; i >= 0; --i) {
        d = d * t + v;
        v = v * t + c[i];
    }
    deriv = d;
    return v;
}

// The single root of a monotone polynomial in [a, b] where fa and fb have opposite signs.
double refine_root(const double* c, int n, double a, double b, double fa) {
    double x = 0.5 * (a + b);
    for (int iter = 0; iter < 100; ++iter) {
        double d;
        double f = eval_with_derivative(c, n, x, d);
        if (f == 0) return x;
        if ((f < 0) == (fa < 0)) a = x; else b = x;
        double next = x - f / d;
        // Newton when it stays inside the bracket, bisection otherwise.
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::abs(next - x) <= 1e-15 * std::max(1.0, std::abs(x)) || b - a <= 0) return next;
        x = next;
    }
    return x;
}

}  // namespace

int solve_polynomial_in(const double* c, int n, double lo, double hi, double* roots,
                        int max_roots) {
    while (n > 0 && c[n] == 0) --n;  // drop vanishing leading terms
    if (n <= 0 || !(lo <= hi) || max_roots <= 0) return 0;
    if (n == 1) {
        double t = -c[0] / c[1];
        if (t >= lo && t <= hi) { roots[0] = t; return 1; }
        return 0;
    }
    if (n == 2) {
        double r[2];
        int k = solve_quadratic(c[2], 0.5 * c[1], c[0], r), m = 0;
        for (int i = 0; i < k && m < max_roots; ++i)
            if (r[i] >= lo && r[i] <= hi) roots[m++] = r[i];
        return m;
    }
    // Breakpoints: lo, the critical points inside (lo, hi), hi.
    double deriv[8], crit[8];
    for (int i = 1; i <= n; ++i) deriv[i - 1] = c[i] * i;
    int nc = solve_polynomial_in(deriv, n - 1, lo, hi, crit);
    double pts[10];
    int np = 0;
    pts[np++] = lo;
    for (int i = 0; i < nc; ++i)
        if (crit[i] > pts[np - 1] && crit[i] < hi) pts[np++] = crit[i];
    pts[np++] = hi;

    int m = 0;
    double fa = eval_poly(c, n, pts[0]);
    if (fa == 0) roots[m++] = pts[0];
    for (int i = 1; i < np && m < max_roots; ++i) {
        double fb = eval_poly(c, n, pts[i]);
        if (fb == 0) {
            roots[m++] = pts[i];
        } else if (fa != 0 && (fa < 0) != (fb < 0)) {
            roots[m++] = refine_root(c, n, pts[i - 1], pts[i], fa);
        }
        fa = fb;
    }
    return m;
}

int significant_degree(const double* c, int n, double tiny) {
    while (n > 0 && std::abs(c[n]) < tiny) --n;
    return n;
}

int solve_significant_in(const double* c, int n, double lo, double hi, double* roots) {
    return solve_polynomial_in(c, significant_degree(c, n), lo, hi, roots);
}

}  // namespace lumen::render

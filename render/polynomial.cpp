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

// Roots are passed to a sink as they are found, lowest first; a sink that answers false stops
// the search (a ray wants its nearest hit only, an inside test only how many there are).
using RootSink = bool (*)(void* context, double root);

bool each_root(const double* c, int n, double lo, double hi, bool refine, RootSink sink,
               void* context);

// The monotone pieces of a polynomial between consecutive breakpoints (lo, the critical
// points in order, hi): each piece holds at most one root.
struct PieceWalk {
    const double* c;
    int n;
    double hi, prev, f_prev;
    bool refine;
    RootSink sink;
    void* context;

    bool step(double x) {
        const double f = eval_poly(c, n, x);
        bool go_on = true;
        if (f == 0)
            go_on = sink(context, x);
        else if (f_prev != 0 && (f_prev < 0) != (f < 0))
            go_on = sink(context, refine ? refine_root(c, n, prev, x, f_prev) : x);
        prev = x;
        f_prev = f;
        return go_on;
    }
    static bool at_critical_point(void* walk, double x) {
        PieceWalk& w = *static_cast<PieceWalk*>(walk);
        if (!(x > w.prev && x < w.hi)) return true;
        return w.step(x);
    }
};

bool each_root(const double* c, int n, double lo, double hi, bool refine, RootSink sink,
               void* context) {
    while (n > 0 && c[n] == 0) --n;  // drop vanishing leading terms
    if (n <= 0 || !(lo <= hi)) return true;
    if (n == 1) {
        const double t = -c[0] / c[1];
        return !(t >= lo && t <= hi) || sink(context, t);
    }
    if (n == 2) {
        double r[2];
        const int k = solve_quadratic(c[2], 0.5 * c[1], c[0], r);
        for (int i = 0; i < k; ++i)
            if (r[i] >= lo && r[i] <= hi && !sink(context, r[i])) return false;
        return true;
    }
    // The critical points come from the derivative's roots, found the same way, in order.
    double deriv[8];
    for (int i = 1; i <= n; ++i) deriv[i - 1] = c[i] * i;
    PieceWalk walk{c, n, hi, lo, eval_poly(c, n, lo), refine, sink, context};
    if (walk.f_prev == 0 && !sink(context, lo)) return false;
    if (!each_root(deriv, n - 1, lo, hi, true, PieceWalk::at_critical_point, &walk)) return false;
    return walk.step(hi);
}

struct RootList {
    double* roots;
    int count, max;
    static bool add(void* list, double root) {
        RootList& l = *static_cast<RootList*>(list);
        l.roots[l.count++] = root;
        return l.count < l.max;
    }
};

bool count_one(void* count, double) {
    ++*static_cast<int*>(count);
    return true;
}

}  // namespace

int solve_polynomial_in(const double* c, int n, double lo, double hi, double* roots,
                        int max_roots) {
    if (max_roots <= 0) return 0;
    RootList list{roots, 0, max_roots};
    each_root(c, n, lo, hi, true, RootList::add, &list);
    return list.count;
}

int count_roots_in(const double* c, int n, double lo, double hi) {
    int count = 0;
    each_root(c, n, lo, hi, false, count_one, &count);
    return count;
}

int significant_degree(const double* c, int n, double tiny) {
    while (n > 0 && std::abs(c[n]) < tiny) --n;
    return n;
}

int solve_significant_in(const double* c, int n, double lo, double hi, double* roots) {
    return solve_polynomial_in(c, significant_degree(c, n), lo, hi, roots);
}

}  // namespace lumen::render

// POV-Ray 3.7's polynomial solver rules (its math/polysolv): the thresholds, the order of the
// roots and the cases where a root is lost or kept are what images depend on.
#include "render/pov_polynomial.hpp"

#include <algorithm>
#include <cmath>

namespace lumen::render {

namespace {

constexpr double kSmall = 1e-10;      // coefficient treated as 0; |disc| treated as 0
constexpr double kRelError = 1e-12;   // bisection and regula falsa stop
constexpr int kMaxIterations = 50;
constexpr double kMaxDistance = 1e7;  // the Sturm search covers [0, kMaxDistance]
constexpr double kDifficultRatio = 1e12;

// A polynomial with its coefficients LOWEST power first (the Sturm sequence's layout). Only
// c[0..order] is ever set or read: the coefficients are left uninitialised, since clearing a
// Sturm sequence of kMaxPolyOrder + 1 of them (10 KB) cost more than a sextic's whole search.
struct Poly {
    int order = 0;
    double c[kMaxPolyOrder + 1];
    double at(double x) const {
        double v = c[order];
        for (int i = order - 1; i >= 0; --i) v = v * x + c[i];
        return v;
    }
};

// r = u mod v, for v with leading coefficient +-1; remainder coefficients below kSmall are
// zeroed from the top. Returns the remainder's order (0 for a constant).
int remainder(const Poly& u, const Poly& v, Poly& r) {
    r.order = u.order;
    std::copy(u.c, u.c + u.order + 1, r.c);
    const int shift = u.order - v.order;
    if (v.c[v.order] < 0) {
        // Dividing by -v: the quotient's signs alternate, written into r as it goes.
        for (int k = shift - 1; k >= 0; k -= 2) r.c[k] = -r.c[k];
        for (int k = shift; k >= 0; --k)
            for (int j = v.order + k - 1; j >= k; --j)
                r.c[j] = -r.c[j] - r.c[v.order + k] * v.c[j - k];
    } else {
        for (int k = shift; k >= 0; --k)
            for (int j = v.order + k - 1; j >= k; --j) r.c[j] -= r.c[v.order + k] * v.c[j - k];
    }
    int k = v.order - 1;
    while (k >= 0 && std::fabs(r.c[k]) < kSmall) r.c[k--] = 0;
    r.order = k < 0 ? 0 : k;
    return r.order;
}

// The Sturm sequence of seq[0] (monic); returns the index of its last member.
int build_sturm(Poly* seq) {
    const int n = seq[0].order;
    seq[1].order = n - 1;
    const double f = std::fabs(seq[0].c[n] * n);
    for (int i = 1; i <= n; ++i) seq[1].c[i - 1] = seq[0].c[i] * i / f;
    int last = 2;
    while (remainder(seq[last - 2], seq[last - 1], seq[last])) {
        Poly& p = seq[last];
        const double g = -std::fabs(p.c[p.order]);
        for (int i = p.order; i >= 0; --i) p.c[i] /= g;
        ++last;
    }
    seq[last].c[0] = -seq[last].c[0];
    return last;
}

// Sign changes along the sequence at x (a zero value counts as a change, as POV-Ray counts).
int sign_changes(int last, const Poly* seq, double x) {
    int changes = 0;
    double prev = seq[0].at(x);
    for (int i = 1; i <= last; ++i) {
        double f = seq[i].at(x);
        if (prev == 0 || prev * f < 0) ++changes;
        prev = f;
    }
    return changes;
}

// Modified regula falsa on [a, b] (the stale end's value halved); false when it does not
// converge in kMaxIterations or the ends have the same sign.
bool regula_falsa(const Poly& p, double a, double b, double& root) {
    double fa = p.at(a), fb = p.at(b);
    if (fa * fb > 0) return false;
    if (std::fabs(fa) < kSmall) { root = a; return true; }
    if (std::fabs(fb) < kSmall) { root = b; return true; }
    double last = fa;
    for (int it = 0; it < kMaxIterations; ++it) {
        double x = (fb * a - fa * b) / (fb - fa);
        double fx = p.at(x);
        if (std::fabs(x) > kRelError ? std::fabs(fx / x) < kRelError : std::fabs(fx) < kRelError) {
            root = x;
            return true;
        }
        // Keep the end whose sign differs from f(x); halve the other end's value when the
        // same end moved twice.
        const bool stale = last * fx > 0;
        if ((fa < 0) == (fx < 0)) {
            a = x; fa = fx;
            if (stale) fb /= 2;
        } else {
            b = x; fb = fx;
            if (stale) fa /= 2;
        }
        if (std::fabs(b - a) < kRelError) { root = x; return true; }
        last = fx;
    }
    return false;
}

bool interval_small(double lo, double hi, double mid) {
    return std::fabs(mid) > kRelError ? std::fabs((hi - lo) / mid) < kRelError
                                      : std::fabs(hi - lo) < kRelError;
}

// Isolates the roots in [lo, hi] (n_lo and n_hi the sign changes there) by bisection. A count
// that becomes inconsistent gives up on the interval, as POV-Ray does.
int bisect(int last, const Poly* seq, double lo, double hi, int n_lo, int n_hi, double* roots) {
    double mid = lo;
    if (n_lo - n_hi == 1) {
        if (regula_falsa(seq[0], lo, hi, roots[0])) return 1;
        for (int it = 0; it < kMaxIterations; ++it) {
            mid = (lo + hi) / 2;
            int n_mid = sign_changes(last, seq, mid);
            if (n_mid < n_hi || n_mid > n_lo) return 0;
            if (interval_small(lo, hi, mid)) { roots[0] = mid; return 1; }
            if (n_lo == n_mid) lo = mid; else hi = mid;
        }
        roots[0] = mid;
        return 1;
    }
    for (int it = 0; it < kMaxIterations; ++it) {
        mid = (lo + hi) / 2;
        int n_mid = sign_changes(last, seq, mid);
        if (n_mid < n_hi || n_mid > n_lo) return 0;
        if (interval_small(lo, hi, mid)) { roots[0] = mid; return 1; }
        int below = n_lo - n_mid, above = n_mid - n_hi;
        if (below != 0 && above != 0) {
            int k = bisect(last, seq, lo, mid, n_lo, n_mid, roots);
            return k + bisect(last, seq, mid, hi, n_mid, n_hi, roots + k);
        }
        if (below == 0) lo = mid; else hi = mid;
    }
    roots[0] = mid;
    return 1;
}

}  // namespace

namespace pov_solver {

int solve_quadratic(const double* x, double* y) {
    double a = x[0], b = -x[1], c = x[2];
    if (a == 0) {
        if (b == 0) return 0;
        y[0] = c / b;
        return 1;
    }
    b /= a;
    c /= a;
    double d = b * b - 4 * c;
    if (d > -kSmall && d < kSmall) {  // a tangent: one root
        y[0] = 0.5 * b;
        return 1;
    }
    if (d < 0) return 0;
    d = std::sqrt(d);
    y[0] = (b + d) / 2;
    y[1] = (b - d) / 2;
    return 2;
}

// Trigonometric form for three real roots, Cardano's otherwise (acos not clamped, as in POV).
int solve_cubic(const double* x, double* y) {
    const double a0 = x[0];
    if (a0 == 0) return solve_quadratic(x + 1, y);
    double a1 = x[1], a2 = x[2], a3 = x[3];
    if (a0 != 1) { a1 /= a0; a2 /= a0; a3 /= a0; }
    const double a1sq = a1 * a1;
    const double q = (a1sq - 3 * a2) / 9;
    const double r = (a1 * (a1sq - 4.5 * a2) + 13.5 * a3) / 27;
    const double q3 = q * q * q, r2 = r * r;
    const double shift = a1 / 3;
    if (q3 - r2 >= 0) {
        const double theta = std::acos(r / std::sqrt(q3)) / 3;
        const double s = -2 * std::sqrt(q);
        y[0] = s * std::cos(theta) - shift;
        y[1] = s * std::cos(theta + 2.0943951023931954923084) - shift;
        y[2] = s * std::cos(theta + 4.1887902047863909846168) - shift;
        return 3;
    }
    const double s = std::pow(std::sqrt(r2 - q3) + std::fabs(r), 1.0 / 3.0);
    y[0] = (r < 0 ? (s + q / s) : -(s + q / s)) - shift;
    return 1;
}

// Vieta's method through the resolvent cubic, taking the first resolvent root returned.
int solve_quartic(const double* x, double* out) {
    double c1 = x[1], c2 = x[2], c3 = x[3], c4 = x[4];
    if (x[0] != 1) { c1 /= x[0]; c2 /= x[0]; c3 /= x[0]; c4 /= x[0]; }
    const double c12 = c1 * c1;
    const double p = -0.375 * c12 + c2;
    const double q = 0.125 * c12 * c1 - 0.5 * c1 * c2 + c3;
    const double r = -0.01171875 * c12 * c12 + 0.0625 * c12 * c2 - 0.25 * c1 * c3 + c4;
    const double cubic[4] = {1, -0.5 * p, -r, 0.5 * r * p - 0.125 * q * q};
    double zs[3];
    if (solve_cubic(cubic, zs) == 0) return 0;
    const double z = zs[0];
    double d1 = 2 * z - p, d2;
    if (d1 < 0) {
        if (d1 <= -kSmall) return 0;
        d1 = 0;
    }
    if (d1 < kSmall) {
        d2 = z * z - r;
        if (d2 < 0) return 0;
        d2 = std::sqrt(d2);
    } else {
        d1 = std::sqrt(d1);
        d2 = 0.5 * q / d1;
    }
    const double q1 = d1 * d1, q2 = -0.25 * c1;
    int n = 0;
    double disc = q1 - 4 * (z - d2);
    if (disc == 0) {
        out[n++] = -0.5 * d1 - q2;  // the sign of q2 here is POV-Ray's
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        out[n++] = -0.5 * (d1 + disc) + q2;
        out[n++] = -0.5 * (d1 - disc) + q2;
    }
    disc = q1 - 4 * (z + d2);
    if (disc == 0) {
        out[n++] = 0.5 * d1 - q2;
    } else if (disc > 0) {
        disc = std::sqrt(disc);
        out[n++] = 0.5 * (d1 + disc) + q2;
        out[n++] = 0.5 * (d1 - disc) + q2;
    }
    return n;
}

int sturm_roots(int n, const double* c, double* roots) {
    Poly seq[kMaxPolyOrder + 1];
    seq[0].order = n;
    for (int i = 0; i <= n; ++i) seq[0].c[n - i] = c[i] / c[0];
    const int last = build_sturm(seq);
    // Roots on the positive axis at all (sign changes at 0 and at +infinity)?
    int at_zero = 0, at_inf = 0;
    double lz = seq[0].c[0], li = seq[0].c[seq[0].order];
    for (int i = 1; i <= last; ++i) {
        double fz = seq[i].c[0], fi = seq[i].c[seq[i].order];
        if (li == 0 || li * fi < 0) ++at_inf;
        if (lz == 0 || lz * fz < 0) ++at_zero;
        lz = fz;
        li = fi;
    }
    if (at_zero - at_inf == 0) return 0;
    const int n_lo = sign_changes(last, seq, 0), n_hi = sign_changes(last, seq, kMaxDistance);
    if (n_lo - n_hi == 0) return 0;
    return bisect(last, seq, 0, kMaxDistance, n_lo, n_hi, roots);
}

// POV-Ray's test keeps the SIGNED value of the largest-magnitude coefficient seen so far
// (a quirk: a negative one makes every later comparison pass).
bool difficult_coefficients(int n, const double* x) {
    double biggest = 0;
    for (int i = 0; i <= n; ++i)
        if (std::fabs(x[i]) > biggest) biggest = x[i];
    if (biggest == 0) return false;
    for (int i = 0; i <= n; ++i)
        if (x[i] != 0 && std::fabs(biggest / x[i]) > kDifficultRatio) return true;
    return false;
}

}  // namespace pov_solver

int solve_pov_polynomial(int n, const double* c0, double* roots, bool sturm, double eps) {
    using namespace pov_solver;
    int lead = 0;
    while (lead < n && std::fabs(c0[lead]) < kSmall) ++lead;
    n -= lead;
    const double* c = c0 + lead;
    // A root within eps of 0 is divided out (c[n] ~ 0): the lower part is solved instead.
    const bool drop_zero_root = eps > 0 && n >= 3 && c[n - 1] != 0 && std::fabs(c[n] / c[n - 1]) < eps;
    switch (n) {
        case 0: return 0;
        case 1:
            if (c[0] == 0) return 0;
            roots[0] = -c[1] / c[0];
            return 1;
        case 2: return solve_quadratic(c, roots);
        case 3:
            if (drop_zero_root) return solve_quadratic(c, roots);
            return sturm ? sturm_roots(3, c, roots) : solve_cubic(c, roots);
        case 4:
            if (drop_zero_root) return sturm ? sturm_roots(3, c, roots) : solve_cubic(c, roots);
            if (sturm || difficult_coefficients(4, c)) return sturm_roots(4, c, roots);
            return solve_quartic(c, roots);
        default:
            // POV-Ray computes the reduced solve here and then overwrites it with the full one.
            return sturm_roots(n, c, roots);
    }
}

}  // namespace lumen::render

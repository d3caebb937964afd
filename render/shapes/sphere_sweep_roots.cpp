// Bernstein subdivision for sphere_sweep's polynomials (see the header).
#include "render/shapes/sphere_sweep_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace lumen::render {

namespace {

constexpr int kMax = SweepPoly::kMax;
using Table = std::array<std::array<double, kMax + 1>, kMax + 1>;

const Table& binomials() {  // [i][j] = i choose j
    static const Table t = [] {
        Table b{};
        for (int i = 0; i <= kMax; ++i) {
            b[i][0] = 1;
            for (int j = 1; j <= i; ++j) b[i][j] = b[i - 1][j - 1] + b[i - 1][j];
        }
        return b;
    }();
    return t;
}

// The Bernstein coefficients of p over [0, 1].
void to_bernstein(const SweepPoly& p, double* b) {
    const Table& C = binomials();
    for (int i = 0; i <= p.n; ++i) {
        b[i] = 0;
        for (int j = 0; j <= i; ++j) b[i] += C[i][j] / C[p.n][j] * p.c[j];
    }
}

// p(lo + (hi - lo) u) as a polynomial in u (a Taylor shift, then a scaling).
SweepPoly over(const SweepPoly& p, double lo, double hi) {
    SweepPoly q = p;
    for (int i = 0; i < q.n; ++i)
        for (int j = q.n - 1; j >= i; --j) q.c[j] += lo * q.c[j + 1];
    double w = 1;
    for (int i = 0; i <= q.n; ++i, w *= hi - lo) q.c[i] *= w;
    return q;
}

int sign_changes(const double* b, int n) {
    int changes = 0;
    double prev = 0;
    for (int i = 0; i <= n; ++i) {
        if (b[i] == 0) continue;
        if (prev != 0 && (b[i] < 0) != (prev < 0)) ++changes;
        prev = b[i];
    }
    return changes;
}

// The halves [0, 1/2] and [1/2, 1] of a Bernstein polynomial (de Casteljau).
void split(const double* b, int n, double* left, double* right) {
    double t[kMax + 1];
    std::copy(b, b + n + 1, t);
    for (int k = 0; k <= n; ++k) {
        left[k] = t[0];
        right[n - k] = t[n - k];
        for (int i = 0; i < n - k; ++i) t[i] = 0.5 * (t[i] + t[i + 1]);
    }
}

// The root of q in [a, b], where q changes sign once: safeguarded Newton.
double refine(const SweepPoly& q, double a, double b) {
    auto eval = [&](double u, double& slope) {
        double v = q.c[q.n], d = 0;
        for (int i = q.n - 1; i >= 0; --i) d = d * u + v, v = v * u + q.c[i];
        slope = d;
        return v;
    };
    double slope;
    const bool a_negative = eval(a, slope) < 0;
    double x = 0.5 * (a + b);
    for (int iter = 0; iter < 80; ++iter) {
        const double f = eval(x, slope);
        if (f == 0) return x;
        ((f < 0) == a_negative ? a : b) = x;
        double next = x - f / slope;
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::abs(next - x) <= 1e-15 || !(b > a)) return next;
        x = next;
    }
    return x;
}

}  // namespace

SweepPoly operator*(const SweepPoly& a, const SweepPoly& b) {
    SweepPoly p;
    p.n = a.n + b.n;
    for (int i = 0; i <= a.n; ++i)
        for (int j = 0; j <= b.n; ++j) p.c[i + j] += a.c[i] * b.c[j];
    return p;
}

SweepPoly add(const SweepPoly& a, double k, const SweepPoly& b) {
    SweepPoly p = a;
    p.n = std::max(a.n, b.n);
    for (int i = 0; i <= b.n; ++i) p.c[i] += k * b.c[i];
    return p;
}

SweepPoly derivative(const SweepPoly& a) {
    SweepPoly p;
    p.n = std::max(a.n - 1, 0);
    for (int i = 1; i <= a.n; ++i) p.c[i - 1] = i * a.c[i];
    return p;
}

SweepPoly constant(double x) {
    SweepPoly p;
    p.c[0] = x;
    return p;
}

bool positive_somewhere(const SweepPoly& p) {
    double b[kMax + 1];
    to_bernstein(p, b);
    return std::any_of(b, b + p.n + 1, [](double x) { return x > 0; });
}

int root_candidates(const SweepPoly& p, double lo, double hi, double* out, int room) {
    if (!(hi > lo) || p.n < 1) return 0;
    const SweepPoly q = over(p, lo, hi);
    const int n = q.n;
    struct Piece {
        double b[kMax + 1];
        double u0, u1;
    };
    Piece stack[64];
    to_bernstein(q, stack[0].b);
    stack[0].u0 = 0, stack[0].u1 = 1;
    int sp = 1, found = 0;
    auto emit = [&](double u) {
        if (found < room) out[found++] = lo + (hi - lo) * u;
    };
    // A coefficient exactly 0 at a piece's end is a root there, emitted once.
    if (stack[0].b[0] == 0) emit(0);
    if (stack[0].b[n] == 0) emit(1);
    while (sp > 0) {
        const Piece piece = stack[--sp];
        const int changes = sign_changes(piece.b, n);
        if (changes == 0) continue;
        if (changes == 1 && piece.b[0] != 0 && piece.b[n] != 0) {
            emit(refine(q, piece.u0, piece.u1));
            continue;
        }
        const double mid = 0.5 * (piece.u0 + piece.u1);
        if (piece.u1 - piece.u0 < 1e-10 || sp + 2 > 64) {
            emit(mid);
            continue;
        }
        Piece left, right;
        split(piece.b, n, left.b, right.b);
        left.u0 = piece.u0, left.u1 = right.u0 = mid, right.u1 = piece.u1;
        if (left.b[n] == 0) emit(mid);
        stack[sp++] = right;
        stack[sp++] = left;
    }
    return found;
}

}  // namespace lumen::render

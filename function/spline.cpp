#include "function/spline.hpp"

#include <algorithm>

namespace lumen::fn {

namespace {

using Value = std::array<double, 5>;

Value lerp(const Value& a, const Value& b, double w) {
    Value r;
    for (int c = 0; c < 5; ++c) r[c] = a[c] + w * (b[c] - a[c]);
    return r;
}

// POV's segment: 0 when t <= t_0, n when t >= t_{n-1}, else the first index with t_i >= t.
size_t segment(const std::vector<Spline::Entry>& e, double t) {
    if (t <= e.front().t) return 0;
    if (t >= e.back().t) return e.size();
    size_t i = 0;
    while (e[i].t < t) ++i;
    return i;
}

Value linear(const std::vector<Spline::Entry>& e, double t) {
    const size_t i = segment(e, t);
    if (i == 0) return e.front().v;
    if (i == e.size()) return e.back().v;
    return lerp(e[i - 1].v, e[i].v, (t - e[i - 1].t) / (e[i].t - e[i - 1].t));
}

// The parabola through points a, b, c at t, as POV-Ray fits it (a t² + b t + c from the
// closed-form Lagrange coefficients, evaluated (a t + b) t + c).
Value parabola(const Spline::Entry& p0, const Spline::Entry& p1, const Spline::Entry& p2,
               double t) {
    const double t0 = p0.t, t1 = p1.t, t2 = p2.t;
    const double d0 = (t0 - t1) * (t0 - t2), d1 = (t1 - t0) * (t1 - t2), d2 = (t2 - t0) * (t2 - t1);
    Value r;
    for (int c = 0; c < 5; ++c) {
        const double k0 = p0.v[c] / d0, k1 = p1.v[c] / d1, k2 = p2.v[c] / d2;
        const double a = k0 + k1 + k2;
        const double b = -(k0 * (t1 + t2) + k1 * (t0 + t2) + k2 * (t0 + t1));
        const double cc = k0 * t1 * t2 + k1 * t0 * t2 + k2 * t0 * t1;
        r[c] = (a * t + b) * t + cc;
    }
    return r;
}

Value quadratic(const std::vector<Spline::Entry>& e, double t) {
    const size_t i = segment(e, t);
    if (i == 0) return e.front().v;
    if (i == e.size()) return e.back().v;
    if (e.size() == 2) return linear(e, t);
    if (i == 1) return parabola(e[0], e[1], e[2], t);
    return parabola(e[i - 2], e[i - 1], e[i], t);
}

// The natural spline's second derivatives at the knots, per component: the tridiagonal system
// with M_0 = M_{n-1} = 0, solved as POV-Ray solves it.
std::vector<Value> natural_moments(const std::vector<Spline::Entry>& e) {
    const size_t n = e.size();
    std::vector<Value> M(n, Value{});
    if (n < 3) return M;
    std::vector<double> h(n - 1), b(n - 1), u(n), v(n);
    for (int c = 0; c < 5; ++c) {
        for (size_t k = 0; k + 1 < n; ++k) {
            h[k] = e[k + 1].t - e[k].t;
            b[k] = (e[k + 1].v[c] - e[k].v[c]) / h[k];
        }
        u[1] = 2 * (h[0] + h[1]);
        v[1] = 6 * (b[1] - b[0]);
        for (size_t k = 2; k + 1 < n; ++k) {
            u[k] = 2 * (h[k] + h[k - 1]) - h[k - 1] * h[k - 1] / u[k - 1];
            v[k] = 6 * (b[k] - b[k - 1]) - h[k - 1] * v[k - 1] / u[k - 1];
        }
        for (size_t k = n - 2; k >= 1; --k) M[k][c] = (v[k] - h[k] * M[k + 1][c]) / u[k];
    }
    return M;
}

Value natural(const std::vector<Spline::Entry>& e, const std::vector<Value>& M, double t) {
    const size_t i = segment(e, t);
    if (i == 0) return e.front().v;
    if (i == e.size()) return e.back().v;
    const size_t j = i - 1;
    const double hj = e[j + 1].t - e[j].t, s = t - e[j].t;
    Value out;
    for (int c = 0; c < 5; ++c) {
        const double b = (e[j + 1].v[c] - e[j].v[c]) / hj;
        out[c] = e[j].v[c] + s * (-(hj / 6) * (M[j + 1][c] + 2 * M[j][c]) + b +
                                  s * (M[j][c] / 2 + s * (M[j + 1][c] - M[j][c]) / (6 * hj)));
    }
    return out;
}

// A non-uniform Catmull-Rom through the second to the next-to-last point.
Value cubic(const std::vector<Spline::Entry>& e, double t) {
    const size_t n = e.size();
    if (n == 1) return e[0].v;
    if (n == 2) return lerp(e[0].v, e[1].v, 0.5);
    if (t <= e[1].t) return e[1].v;
    if (t > e[n - 2].t) return e[n - 2].v;
    const size_t i = segment(e, t), j = i - 1;
    const double dt = e[j + 1].t - e[j].t, w = (t - e[j].t) / dt;
    auto slope = [&](size_t a, size_t b, int c) { return (e[b].v[c] - e[a].v[c]) / (e[b].t - e[a].t); };
    const double w2 = w * w, w3 = w2 * w;
    Value out;
    for (int c = 0; c < 5; ++c) {
        const double m0 = dt * (slope(j - 1, j, c) + slope(j, j + 1, c)) / 2;
        const double m1 = dt * (slope(j + 1, j + 2, c) + slope(j, j + 1, c)) / 2;
        out[c] = e[j].v[c] * (2 * w3 - 3 * w2 + 1) + e[j + 1].v[c] * (3 * w2 - 2 * w3) +
                 m0 * (w3 - 2 * w2 + w) + m1 * (w3 - w2);
    }
    return out;
}

}  // namespace

void Spline::add(double t, const Value& v, int components) {
    terms = std::clamp(std::max(terms, components), 2, 5);
    auto it = std::lower_bound(entries.begin(), entries.end(), t,
                               [](const Entry& e, double x) { return e.t < x; });
    if (it != entries.end() && it->t == t) {
        if (it + 1 != entries.end()) it->v = v;  // the largest t keeps its first value
        return;
    }
    entries.insert(it, Entry{t, v});
}

void Spline::prepare() { moments = natural_moments(entries); }

Value Spline::at(double t, SplineType kind) const {
    if (entries.empty()) return {};
    if (entries.size() == 1) return entries[0].v;
    switch (kind) {
        case SplineType::Linear: return linear(entries, t);
        case SplineType::Quadratic: return quadratic(entries, t);
        case SplineType::Cubic: return cubic(entries, t);
        case SplineType::Natural:
            // Prepared once (prepare()); a spline changed since is solved for this call alone.
            return moments.size() == entries.size() ? natural(entries, moments, t)
                                                    : natural(entries, natural_moments(entries), t);
    }
    return {};
}

}  // namespace lumen::fn

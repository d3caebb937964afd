// poly: the ray substituted into each term with binomial expansions (in POV-Ray's term order
// and summation order), then POV-Ray's solver with its 1e-4 root elimination.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/pov_polynomial.hpp"
#include "render/shapes/poly.hpp"

namespace lumen::render {

namespace {

constexpr double kPolyDepth = 1e-4;      // POV-Ray's DEPTH_TOLERANCE for poly (object space)
constexpr double kPolyInside = 1e-4;     // F below this is inside
constexpr double kRootTolerance = 1e-4;  // the solver's small-root elimination
constexpr double kCoeffLimit = 1e-20;    // order 2: a vanishing quadratic term

// Pascal's triangle up to kMaxPolyOrder.
struct Binomials {
    double c[kMaxPolyOrder + 1][kMaxPolyOrder + 1] = {};
    Binomials() {
        for (int n = 0; n <= kMaxPolyOrder; ++n) {
            c[n][0] = c[n][n] = 1;
            for (int k = 1; k < n; ++k) c[n][k] = c[n - 1][k - 1] + c[n - 1][k];
        }
    }
};
const Binomials kBinomials;

// Calls f(term, i, j, k) for every term x^i y^j z^k in POV-Ray's order.
template <class F> void for_each_term(int order, const F& f) {
    int term = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) f(term++, i, j, k);
}

// Order 2: POV-Ray's own quadratic (both roots, even for a tangent).
int quadratic_roots(const double* a, const glm::dvec3& o, const glm::dvec3& d, double* ks) {
    const double x = o.x, y = o.y, z = o.z, dx = d.x, dy = d.y, dz = d.z;
    double ac = a[0] * dx * dx + a[1] * dx * dy + a[2] * dx * dz + a[4] * dy * dy +
                a[5] * dy * dz + a[7] * dz * dz;
    double bc = 2 * a[0] * x * dx + a[1] * (x * dy + dx * y) + a[2] * (x * dz + dx * z) +
                a[3] * dx + 2 * a[4] * y * dy + a[5] * (y * dz + dy * z) + a[6] * dy +
                2 * a[7] * z * dz + a[8] * dz;
    double cc = a[0] * x * x + a[1] * x * y + a[2] * x * z + a[3] * x + a[4] * y * y +
                a[5] * y * z + a[6] * y + a[7] * z * z + a[8] * z + a[9];
    if (std::fabs(ac) < kCoeffLimit) {
        if (std::fabs(bc) < kCoeffLimit) return 0;
        ks[0] = -cc / bc;
        return 1;
    }
    double disc = bc * bc - 4 * ac * cc;
    if (disc < 0) return 0;
    disc = std::sqrt(disc);
    ks[0] = (-bc + disc) / (2 * ac);
    ks[1] = (-bc - disc) / (2 * ac);
    return 2;
}

// Orders 3 and up: the polynomial in k, highest power first, solved by POV-Ray's rules.
int general_roots(const PolyShape& s, const glm::dvec3& o, const glm::dvec3& d, double* ks) {
    const int n = s.order;
    double po[3][kMaxPolyOrder + 1], pd[3][kMaxPolyOrder + 1];
    for (int a = 0; a < 3; ++a) {
        po[a][0] = pd[a][0] = 1;
        for (int i = 1; i <= n; ++i) {
            po[a][i] = po[a][i - 1] * o[a];
            pd[a][i] = pd[a][i - 1] * d[a];
        }
    }
    // (o + k d)^i = sum_h C(i, h) d^(i-h) o^h k^(i-h): slot h of each axis's expansion.
    auto expand = [&](int axis, int power, double* out) {
        for (int h = 0; h <= power; ++h)
            out[h] = kBinomials.c[power][h] * pd[axis][power - h] * po[axis][h];
    };
    double eqn[kMaxPolyOrder + 1] = {};
    double ex[kMaxPolyOrder + 1], ey[kMaxPolyOrder + 1], ez[kMaxPolyOrder + 1];
    int last_i = -1, last_j = -1;
    for (const PolyShape::Term& t : s.terms) {
        if (t.i != last_i) { expand(0, t.i, ex); last_i = t.i; last_j = -1; }
        if (t.j != last_j) { expand(1, t.j, ey); last_j = t.j; }
        expand(2, t.k, ez);
        // Each product is ((c ex) ey) ez, summed into eqn in this order (as POV-Ray does).
        double* out = eqn + (n - (t.i + t.j + t.k));  // eqn[h]: the coefficient of k^(n - h)
        for (int a = 0; a <= t.i; ++a) {
            const double va = t.c * ex[a];
            for (int b = 0; b <= t.j; ++b) {
                const double vab = va * ey[b];
                double* slot = out + a + b;
                for (int e = 0; e <= t.k; ++e) slot[e] += vab * ez[e];
            }
        }
    }
    int lead = 0;
    while (lead <= n && eqn[lead] == 0) ++lead;
    const int degree = n - lead;
    if (degree <= 1) return 0;  // POV-Ray solves nothing below a quadratic here
    return solve_pov_polynomial(degree, eqn + lead, ks, s.sturm, kRootTolerance);
}

}  // namespace

PolyShape make_poly(const scene::Poly& p) {
    PolyShape out{p.order, p.coeffs, p.sturm, false, {}};
    out.valid = p.order >= 2 && p.order <= kMaxPolyOrder &&
                p.coeffs.size() == scene::Poly::term_count(p.order) &&
                std::all_of(p.coeffs.begin(), p.coeffs.end(), [](double c) { return std::isfinite(c); });
    if (out.valid)
        for_each_term(p.order, [&](int term, int i, int j, int k) {
            if (p.coeffs[term] != 0) out.terms.push_back({p.coeffs[term], i, j, k});
        });
    if (out.valid) out.box = poly_bound_box(out.terms, kPolyInside);
    return out;
}

int poly_roots(const PolyShape& s, const glm::dvec3& o, const glm::dvec3& d, double* ks) {
    double found[kMaxPolyOrder];
    const int n = s.order == 2 ? quadratic_roots(s.coeffs.data(), o, d, found)
                               : general_roots(s, o, d, found);
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (!(found[i] > kPolyDepth)) continue;  // also drops NaN
        if (std::find(found, found + i, found[i]) != found + i) continue;
        ks[m++] = found[i];
    }
    return m;
}

bool intersect(const PolyShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const double len = glm::length(r.d);
    if (!(len > 0) || !std::isfinite(len)) return false;
    double ks[kMaxPolyOrder];
    const int n = poly_roots(s, r.o, r.d / len, ks);
    double best = tmax;
    bool found = false;
    for (int i = 0; i < n; ++i) {
        double t = ks[i] / len;
        if (t > tmin && t < best) { best = t; found = true; }
    }
    if (!found) return false;
    h.t = best;
    h.normal = poly_gradient(s, r.at(best));
    if (!(glm::dot(h.normal, h.normal) > 0) || !std::isfinite(glm::dot(h.normal, h.normal)))
        h.normal = {0, 1, 0};  // a singular point (POV-Ray leaves a zero normal there)
    return true;
}

namespace {

// x^i, y^i, z^i for i = 0..order.
struct Powers {
    double px[kMaxPolyOrder + 1], py[kMaxPolyOrder + 1], pz[kMaxPolyOrder + 1];
    Powers(int order, const glm::dvec3& p) {
        px[0] = py[0] = pz[0] = 1;
        for (int i = 1; i <= order; ++i) {
            px[i] = px[i - 1] * p.x;
            py[i] = py[i - 1] * p.y;
            pz[i] = pz[i - 1] * p.z;
        }
    }
};

}  // namespace

double poly_value(const PolyShape& s, const glm::dvec3& p) {
    const Powers w(s.order, p);
    const double *px = w.px, *py = w.py, *pz = w.pz;
    double v = 0;
    for (const PolyShape::Term& t : s.terms) v += t.c * px[t.i] * py[t.j] * pz[t.k];
    return v;
}

glm::dvec3 poly_gradient(const PolyShape& s, const glm::dvec3& p) {
    const Powers w(s.order, p);
    const double *px = w.px, *py = w.py, *pz = w.pz;
    glm::dvec3 g(0);
    for (const auto& [c, i, j, k] : s.terms) {
        if (i > 0) g.x += i * c * px[i - 1] * py[j] * pz[k];
        if (j > 0) g.y += j * c * px[i] * py[j - 1] * pz[k];
        if (k > 0) g.z += k * c * px[i] * py[j] * pz[k - 1];
    }
    return g;
}

bool inside(const PolyShape& s, const glm::dvec3& p) {
    return s.valid && poly_value(s, p) < kPolyInside;
}

Aabb bounds(const PolyShape& s) { return s.valid ? s.box : Aabb{}; }

}  // namespace lumen::render

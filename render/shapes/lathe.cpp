// lathe, traced as POV-Ray traces it: for each segment the ray meets the turned curve where
// (S.y(w) - P.y)^2 (D.x^2 + D.z^2) + 2 D.y m (S.y(w) - P.y) + D.y^2 (P.x^2 + P.z^2 - S.x(w)^2)
// = 0 (m = D.x P.x + D.z P.z, D the unit direction), a polynomial of degree 2, 4 or 6 in w.
// A ray across the axis direction (|D.y| < 1e-10) makes that the square of S.y(w) = P.y, so
// that is solved instead and each root gives the two distances of the circle it sweeps.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/axial_search.hpp"
#include "render/shapes/lathe.hpp"
#include "scene/spline_segments.hpp"

namespace lumen::render {

namespace {

constexpr double kParallel = 1e-10;

// The product of two cubics (lowest power first) into out[0..6].
void multiply(const double (&a)[4], const double (&b)[4], double (&out)[7]) {
    std::fill(std::begin(out), std::end(out), 0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[i + j] += a[i] * b[j];
}

// POV-Ray's lathe normal (d.y x, -d.x rho, d.y z) for the curve's slope d at the hit, turned
// to face out; on the axis it is +-y.
glm::dvec3 lathe_normal(const CurveSegment& seg, double w, const glm::dvec3& hit) {
    glm::dvec2 t = seg.tangent(w);
    if (t == glm::dvec2(0)) t = seg.at(1) - seg.at(0);
    const double rho2 = hit.x * hit.x + hit.z * hit.z;
    if (rho2 <= 1e-10) return {0, t.x > 0 ? -seg.outward : seg.outward, 0};
    return seg.outward * glm::dvec3(t.y * hit.x, -t.x * std::sqrt(rho2), t.y * hit.z);
}

}  // namespace

LatheShape make_lathe(const scene::Lathe& l) {
    LatheShape out;
    for (const glm::dvec2& q : l.points)
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) return out;
    const scene::SplineWalk walk = scene::lathe_walk(l.spline, l.points);
    if (walk.starts.empty()) return out;
    out.curve = make_curve(l.spline, l.points, walk.starts, false);
    out.rmax = std::max(std::abs(out.curve.lo.x), std::abs(out.curve.hi.x));
    out.box = {{-out.rmax, out.curve.lo.y, -out.rmax}, {out.rmax, out.curve.hi.y, out.rmax}};
    out.valid = true;
    return out;
}

bool intersect(const LatheShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const std::optional<AxialSearch> search = AxialSearch::start(r, s.box, tmin, tmax);
    if (!search) return false;
    const glm::dvec3 D = search->D, P = search->P;
    const double len = search->len, k_min = search->k_min;
    const SlabRay& slab = search->slab;
    double best = search->best;
    glm::dvec3 normal(0);
    bool found = false;
    double along = 0;  // segment index + spline parameter of the best hit (uv_mapping's v)
    double index = 0;
    auto offer = [&](double k, const CurveSegment& seg, double w) {
        if (!(k > k_min && k < best && search->in_range(k))) return;
        best = k;
        found = true;
        normal = lathe_normal(seg, w, P + k * D);
        along = index + w;
    };
    const double rr = D.x * D.x + D.z * D.z, m = D.x * P.x + D.z * P.z;
    const double rho2 = P.x * P.x + P.z * P.z;
    for (const CurveSegment& seg : s.curve.segments) {
        index = double(&seg - s.curve.segments.data());
        const double ro = std::max(std::abs(seg.lo.x), std::abs(seg.hi.x));
        double k0, k1;
        if (!slab.hits(padded_box({{-ro, seg.lo.y, -ro}, {ro, seg.hi.y, ro}}), k_min, best, k0, k1))
            continue;
        // Where the ray is in the segment's box, its squared distance from the axis (convex
        // in k) must reach the band between the segment's least and greatest radius.
        const double ri = seg.lo.x > 0 ? seg.lo.x : seg.hi.x < 0 ? -seg.hi.x : 0;
        const auto radial2 = [&](double k) { return (rr * k + 2 * m) * k + rho2; };
        const double vertex = rr > 0 ? std::clamp(-m / rr, k0, k1) : k0;
        const double slack = 1e-9 * (1 + ro * ro + rho2 + rr * (k0 * k0 + k1 * k1));
        if (radial2(vertex) > ro * ro + slack) continue;
        if (std::max(radial2(k0), radial2(k1)) < ri * ri - slack) continue;
        double x[4], y[4];
        seg.coefficients(0, x);
        seg.coefficients(1, y);
        y[0] -= P.y;
        double w[6];
        if (std::abs(D.y) < kParallel) {
            const int n = solve_significant_in(y, 3, 0, 1, w);
            for (int i = 0; i < n; ++i) {
                const double radius = seg.at(w[i]).x, c = rho2 - radius * radius;
                double k[2];
                const int nk = solve_quadratic(rr, m, c, k);
                for (int j = 0; j < nk; ++j) offer(k[j], seg, w[i]);
            }
            continue;
        }
        double yy[7], xx[7], c[7];
        multiply(y, y, yy);
        multiply(x, x, xx);
        for (int i = 0; i < 7; ++i) c[i] = rr * yy[i] - D.y * D.y * xx[i];
        for (int i = 0; i < 4; ++i) c[i] += 2 * D.y * m * y[i];
        c[0] += D.y * D.y * rho2;
        const int n = solve_significant_in(c, 6, 0, 1, w);
        for (int i = 0; i < n; ++i) offer((seg.at(w[i]).y - P.y) / D.y, seg, w[i]);
    }
    if (!found) return false;
    h.t = best / len;
    h.normal = normal;
    h.uv = {0, along / double(s.curve.segments.size())};
    return true;
}

bool inside(const LatheShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    if (p.y < s.curve.lo.y || p.y > s.curve.hi.y || rho > s.rmax) return false;
    return inside_curve(s.curve, {rho, p.y}, 1e-10);
}

Aabb bounds(const LatheShape& s) { return s.box; }

}  // namespace lumen::render

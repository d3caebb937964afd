// sor as POV-Ray builds and traces it: segment i spans the heights of points i+1 and i+2,
// with r^2 and its slope there fixed by the points around them; the ray meets a segment
// where a cubic in the ray distance vanishes (x^2 + z^2 = r^2(y) along the ray).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/axial_search.hpp"
#include "render/shapes/sor.hpp"

namespace lumen::render {

namespace {

constexpr double kParallel = 1e-10;

// The cubic through (y1, v1) and (y2, v2) with slopes s1 and s2 there, in powers of y itself
// (as POV-Ray solves it, by the 4x4 system), coefficients below 1e-10 dropped.
SorSegment fit(double y1, double v1, double s1, double y2, double v2, double s2) {
    double m[4][5] = {{y1 * y1 * y1, y1 * y1, y1, 1, v1},
                      {y2 * y2 * y2, y2 * y2, y2, 1, v2},
                      {3 * y1 * y1, 2 * y1, 1, 0, s1},
                      {3 * y2 * y2, 2 * y2, 1, 0, s2}};
    for (int col = 0; col < 4; ++col) {  // Gauss-Jordan with partial pivoting
        int pivot = col;
        for (int row = col + 1; row < 4; ++row)
            if (std::abs(m[row][col]) > std::abs(m[pivot][col])) pivot = row;
        std::swap(m[col], m[pivot]);
        for (int row = 0; row < 4; ++row) {
            if (row == col || m[col][col] == 0) continue;
            const double f = m[row][col] / m[col][col];
            for (int k = col; k < 5; ++k) m[row][k] -= f * m[col][k];
        }
    }
    double x[4];
    for (int i = 0; i < 4; ++i) {
        x[i] = m[i][i] != 0 ? m[i][4] / m[i][i] : 0;
        if (std::abs(x[i]) < 1e-10) x[i] = 0;
    }
    SorSegment s{x[0], x[1], x[2], x[3], y1, y2, 0};
    double peak = std::max({s.r2(y1), s.r2(y2), 0.0});
    const double slope[3] = {s.c, 2 * s.b, 3 * s.a};
    double ys[2];
    const int n = solve_polynomial_in(slope, 2, y1, y2, ys);
    for (int i = 0; i < n; ++i) peak = std::max(peak, s.r2(ys[i]));
    s.rmax = std::sqrt(peak);
    return s;
}

}  // namespace

SorShape make_sor(const scene::Sor& in) {
    SorShape out;
    out.open = in.open;
    const auto& p = in.points;
    const size_t n = p.size();
    if (n < 4) return out;
    for (const glm::dvec2& q : p)
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) return out;
    for (size_t i = 0; i + 3 < n; ++i) {
        const double r1 = p[i + 1].x, r2 = p[i + 2].x;
        const double s1 = 2 * r1 * (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y);
        const double s2 = 2 * r2 * (p[i + 3].x - p[i + 1].x) / (p[i + 3].y - p[i + 1].y);
        SorSegment seg = fit(p[i + 1].y, r1 * r1, s1, p[i + 2].y, r2 * r2, s2);
        if (!std::isfinite(seg.a + seg.b + seg.c + seg.d)) return out;
        out.rmax = std::max(out.rmax, seg.rmax);
        out.segments.push_back(seg);
    }
    out.ymin = p[1].y;
    out.ymax = p[n - 2].y;
    out.base_r2 = std::max(0.0, out.segments.front().r2(out.ymin));
    out.cap_r2 = std::max(0.0, out.segments.back().r2(out.ymax));
    out.box = {{-out.rmax, out.ymin, -out.rmax}, {out.rmax, out.ymax, out.rmax}};
    out.valid = out.ymin < out.ymax;
    return out;
}

bool intersect(const SorShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const std::optional<AxialSearch> search = AxialSearch::start(r, s.box, tmin, tmax);
    if (!search) return false;
    const glm::dvec3 D = search->D, P = search->P;
    const double len = search->len, k_min = search->k_min;
    const SlabRay& slab = search->slab;
    double best = search->best;
    glm::dvec3 normal(0);
    bool found = false;
    double v = 0;  // uv_mapping's v of the best hit: the sides 0..1, base -1..0, cap 1..2
    auto offer = [&](double k, const glm::dvec3& n, double along) {
        if (!(k > k_min && k < best && search->in_range(k))) return;
        best = k;
        normal = n;
        v = along;
        found = true;
    };
    if (!s.open && std::abs(D.y) >= kParallel) {
        const struct { double y, r2, side; } discs[2] = {{s.ymin, s.base_r2, -1},
                                                          {s.ymax, s.cap_r2, 1}};
        for (const auto& disc : discs) {
            if (!(disc.r2 > 1e-4)) continue;
            const double k = (disc.y - P.y) / D.y;
            const double x = P.x + k * D.x, z = P.z + k * D.z, rr = x * x + z * z;
            if (rr > disc.r2) continue;
            const double f = std::sqrt(rr / disc.r2);  // out from the axis, 0..1
            offer(k, {0, disc.side, 0}, disc.side < 0 ? f - 1 : 2 - f);
        }
    }
    const double dxz = D.x * D.x + D.z * D.z, pd = P.x * D.x + P.z * D.z;
    const double segments = double(s.segments.size());
    for (const SorSegment& seg : s.segments) {
        const double index = double(&seg - s.segments.data());
        double lo, hi;
        const Aabb box{{-seg.rmax, seg.y1, -seg.rmax}, {seg.rmax, seg.y2, seg.rmax}};
        if (!slab.hits(padded_box(box), k_min, best, lo, hi)) continue;
        const double A = seg.a, B = seg.b, C = seg.c, y = P.y;
        const double c[4] = {y * (y * (A * y + B) + C) + seg.d - P.x * P.x - P.z * P.z,
                             D.y * (y * (3 * A * y + 2 * B) + C) - 2 * pd,
                             D.y * D.y * (3 * A * y + B) - dxz, A * D.y * D.y * D.y};
        double k[3];
        const int n = solve_significant_in(c, 3, lo, hi, k);
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 q = P + k[i] * D;
            if (!(q.y >= seg.y1 && q.y <= seg.y2)) continue;
            offer(k[i], {q.x, -0.5 * ((3 * A * q.y + 2 * B) * q.y + C), q.z},
                  (index + (q.y - seg.y1) / (seg.y2 - seg.y1)) / segments);
        }
    }
    if (!found) return false;
    h.t = best / len;
    h.normal = normal;
    h.uv = {0, v};
    return true;
}

bool inside(const SorShape& s, const glm::dvec3& p) {
    if (!s.valid || p.y < s.ymin || p.y > s.ymax) return false;
    const double rho2 = p.x * p.x + p.z * p.z;
    if (rho2 > s.rmax * s.rmax) return false;
    for (const SorSegment& seg : s.segments)
        if (p.y >= seg.y1 && p.y <= seg.y2) return rho2 <= seg.r2(p.y);
    return false;
}

Aabb bounds(const SorShape& s) { return s.box; }

}  // namespace lumen::render

// Interval arithmetic over patches of the cube's faces, each patch's values carried to the
// unit sphere (a degree-d part H_d(p / |p|) = H_d(p) / |p|^d); F(p) is then at least a
// polynomial in |p| whose last root bounds the surface.
#include "render/shapes/poly_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/interval.hpp"

namespace lumen::render {

namespace {

constexpr int kPatches = 24;          // per face edge: 6 * 24^2 patches
constexpr double kRounding = 1e-12;   // relative slack for the floating-point evaluation

// The range of H_d on the part of the unit sphere over one patch of a cube face.
Interval on_sphere(const std::vector<PolyTerm>& terms, int degree, const Interval xyz[3]) {
    Interval h{0, 0};
    double magnitude = 0;
    for (const PolyTerm& t : terms) {
        if (t.i + t.j + t.k != degree) continue;
        Interval v = power(xyz[0], t.i) * power(xyz[1], t.j) * power(xyz[2], t.k);
        v = v * Interval{t.c, t.c};
        h.lo += v.lo;
        h.hi += v.hi;
        magnitude += std::max(std::fabs(v.lo), std::fabs(v.hi));
    }
    h.lo -= kRounding * magnitude;
    h.hi += kRounding * magnitude;
    // |p|^d over the patch: |p|^2 lies in [1 + min of the others' squares, ...].
    Interval r2{0, 0};
    for (int a = 0; a < 3; ++a) {
        Interval s = power(xyz[a], 2);
        r2.lo += s.lo;
        r2.hi += s.hi;
    }
    const double a = std::pow(r2.lo, degree / 2.0), b = std::pow(r2.hi, degree / 2.0);
    if (h.lo >= 0) return {h.lo / b, h.hi / a};
    if (h.hi <= 0) return {h.lo / a, h.hi / b};
    return {h.lo / a, h.hi / a};
}

}  // namespace

Aabb poly_bound_box(const std::vector<PolyTerm>& terms, double inside_level) {
    int n = 0;
    for (const PolyTerm& t : terms) n = std::max(n, t.i + t.j + t.k);
    if (n == 0 || n % 2 == 1) return Aabb::everything();
    // low[d]: a lower bound of H_d on the sphere (low[n] > 0 is needed; 0 < d < n kept <= 0).
    std::vector<double> low(size_t(n) + 1, 0.0);
    low[size_t(n)] = std::numeric_limits<double>::infinity();
    for (const PolyTerm& t : terms)
        if (t.i + t.j + t.k == 0) low[0] += t.c;
    low[0] -= inside_level;
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-1.0, 1.0})
            for (int u = 0; u < kPatches; ++u)
                for (int v = 0; v < kPatches; ++v) {
                    Interval xyz[3];
                    xyz[axis] = {side, side};
                    const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
                    xyz[ua] = {-1 + 2.0 * u / kPatches, -1 + 2.0 * (u + 1) / kPatches};
                    xyz[va] = {-1 + 2.0 * v / kPatches, -1 + 2.0 * (v + 1) / kPatches};
                    for (int d = n; d >= 1; --d) {
                        double& l = low[size_t(d)];
                        l = std::min(l, on_sphere(terms, d, xyz).lo);
                        if (!(l >= -std::numeric_limits<double>::max())) return Aabb::everything();
                    }
                    if (!(low[size_t(n)] > 0)) return Aabb::everything();
                }
    // F(p) >= f(|p|) = sum low[d] r^d. f' has one positive root r* (its coefficients change
    // sign once), so f falls to r* and rises after: F > 0 beyond f's root past r*.
    auto f = [&](double r, int derivative) {
        double v = 0;
        for (int d = n; d >= derivative; --d)
            v = v * r + low[size_t(d)] * (derivative ? d : 1);
        return v;
    };
    auto first_positive = [&](int derivative, double from) {  // the root past `from`
        double hi = std::max(from, 1.0);
        while (!(f(hi, derivative) > 0)) {
            hi *= 2;
            if (hi > 1e15) return HUGE_VAL;
        }
        double lo = from;
        for (int it = 0; it < 64; ++it) {
            const double mid = 0.5 * (lo + hi);
            (f(mid, derivative) > 0 ? hi : lo) = mid;
        }
        return hi;
    };
    const double turn = first_positive(1, 0);
    const double r = f(turn, 0) > 0 ? turn : first_positive(0, turn);
    if (!(r < 1e15)) return Aabb::everything();
    const double padded = r * (1 + 1e-9) + 1e-12;
    return {glm::dvec3(-padded), glm::dvec3(padded)};
}

}  // namespace lumen::render

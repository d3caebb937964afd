// ovus: each of its three surfaces solved along the ray and kept only in its own height
// range; the lemon's quartic with the bracketing solver (render/polynomial.hpp), which
// neither misses a grazing root nor returns NaN.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/ovus.hpp"

namespace lumen::render {

namespace {

// The lemon's implicit function (rho + offset)^2 + (y - height)^2 - radius^2.
double lemon_value(const scene::Ovus::Lemon& l, const glm::dvec3& p) {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z), dy = p.y - l.height;
    return (rho + l.offset) * (rho + l.offset) + dy * dy - l.radius * l.radius;
}

glm::dvec3 lemon_normal(const scene::Ovus::Lemon& l, const glm::dvec3& p) {
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    if (!(rho > 0)) return {0, p.y > l.height ? 1.0 : -1.0, 0};
    const double k = (rho + l.offset) / rho;
    return {k * p.x, p.y - l.height, k * p.z};
}

// Roots of |o + t d - c|^2 = r^2, ascending (the caller keeps those in its range).
int sphere_roots(const glm::dvec3& c, double r, const LocalRay& ray, double* ts) {
    const glm::dvec3 v = ray.o - c;
    return solve_quadratic(glm::dot(ray.d, ray.d), glm::dot(v, ray.d), glm::dot(v, v) - r * r, ts);
}

}  // namespace

OvusShape make_ovus(const scene::Ovus& o) {
    OvusShape s;
    s.bottom = o.bottom;
    s.top = o.top;
    s.lemon = o.lemon();
    s.valid = o.bottom >= 0 && o.top >= 0 && o.top < 2 * o.bottom && std::isfinite(o.bottom + o.top);
    return s;
}

bool intersect(const OvusShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const scene::Ovus::Lemon& l = s.lemon;
    double best = tmax;
    glm::dvec3 normal(0);
    auto take = [&](double t, const glm::dvec3& n) {
        if (t > tmin && t < best) {
            best = t;
            normal = n;
        }
    };
    double ts[4];
    const glm::dvec3 top_centre(0, s.bottom, 0);
    for (int i = 0, n = sphere_roots(glm::dvec3(0), s.bottom, r, ts); i < n; ++i)
        if (r.at(ts[i]).y <= l.low) take(ts[i], r.at(ts[i]));
    for (int i = 0, n = sphere_roots(top_centre, s.top, r, ts); i < n; ++i)
        if (r.at(ts[i]).y >= l.high) take(ts[i], r.at(ts[i]) - top_centre);
    if (l.low < l.high) {
        // With q = o - (0, height, 0): S(t) = |q + t d|^2 + offset^2 - radius^2 equals
        // -2 offset rho(t) on the lemon, so S^2 = 4 offset^2 rho^2 with S <= 0.
        const glm::dvec3 q = r.o - glm::dvec3(0, l.height, 0);
        const double A = glm::dot(r.d, r.d), B = glm::dot(q, r.d);
        const double K = glm::dot(q, q) + l.offset * l.offset - l.radius * l.radius;
        const double a2 = r.d.x * r.d.x + r.d.z * r.d.z, b2 = r.o.x * r.d.x + r.o.z * r.d.z,
                     c2 = r.o.x * r.o.x + r.o.z * r.o.z, e2 = 4 * l.offset * l.offset;
        const double c[5] = {K * K - e2 * c2, 4 * B * K - 2 * e2 * b2,
                             4 * B * B + 2 * A * K - e2 * a2, 4 * A * B, A * A};
        const double lo = std::max(tmin, 0.0), hi = std::min(best, 1e7);
        for (int i = 0, n = hi > lo ? solve_polynomial_in(c, 4, lo, hi, ts) : 0; i < n; ++i) {
            const glm::dvec3 p = r.at(ts[i]);
            const double S = (A * ts[i] + 2 * B) * ts[i] + K;
            if (p.y >= l.low && p.y <= l.high && S <= 0) take(ts[i], lemon_normal(l, p));
        }
    }
    if (!(best < tmax)) return false;
    h.t = best;
    h.normal = normal;
    return true;
}

bool inside(const OvusShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    if (glm::dot(p, p) < s.bottom * s.bottom) return true;
    const glm::dvec3 v = p - glm::dvec3(0, s.bottom, 0);
    if (glm::dot(v, v) < s.top * s.top) return true;
    return p.y >= s.lemon.low && p.y <= s.lemon.high && lemon_value(s.lemon, p) < 0;
}

Aabb bounds(const OvusShape& s) {
    if (!s.valid) return {};
    const double w = std::max({s.bottom, s.top, s.lemon.radius - s.lemon.offset});
    return {{-w, -s.bottom, -w}, {w, s.bottom + s.top, w}};
}

}  // namespace lumen::render

// Torus (major radius R in the XZ plane around Y, tube radius r). The quartic is formed with a
// unit direction from a start point moved up to the bounding sphere, which keeps the
// coefficients well scaled for distant rays, and solved only over the sphere's chord.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/torus.hpp"

namespace lumen::render {

TorusShape make_torus(const scene::Torus& t) {
    TorusShape out{t.major, t.minor, true};
    out.valid = t.minor > 0 && t.major >= 0 && std::isfinite(t.major) && std::isfinite(t.minor);
    return out;
}

namespace {

// The tube lies within |y| <= minor and major - minor <= |xz| <= major + minor. A ray whose
// span [k0, k1] (unit direction d) crosses that slab only where its distance from the axis
// stays outside the ring (most rays through a large thin ring's bounding sphere) cannot meet
// it. Only a test, with a margin for the solver's rounding: the quartic keeps the chord.
bool misses_tube(const TorusShape& s, const glm::dvec3& o, const glm::dvec3& d, double k0,
                 double k1) {
    const double slab = s.minor + 1e-6 * (s.major + s.minor);
    if (std::fabs(d.y) > 1e-12) {
        double a = (-slab - o.y) / d.y, b = (slab - o.y) / d.y;
        if (a > b) std::swap(a, b);
        k0 = std::max(k0, a);
        k1 = std::min(k1, b);
        if (!(k0 <= k1)) return true;
    } else if (std::fabs(o.y) > slab) {
        return true;
    }
    // The squared distance from the axis is a quadratic in k: least at its vertex or an end,
    // greatest at an end.
    const double A = d.x * d.x + d.z * d.z, B = o.x * d.x + o.z * d.z, C = o.x * o.x + o.z * o.z;
    auto r2 = [&](double k) { return (A * k + 2 * B) * k + C; };
    const double e0 = r2(k0), e1 = r2(k1);
    double lo = std::min(e0, e1);
    const double hi = std::max(e0, e1);
    if (A > 0) {
        const double kv = -B / A;
        if (kv > k0 && kv < k1) lo = std::min(lo, r2(kv));
    }
    const double inner = std::max(0.0, s.major - slab), outer = s.major + slab;
    return hi < inner * inner || lo > outer * outer;
}

}  // namespace

bool intersect(const TorusShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    double len = glm::length(r.d);
    if (!(len > 0)) return false;
    glm::dvec3 d = r.d / len;
    // Chord of the bounding sphere (object-space distances k = t * len).
    double bound = s.major + s.minor;
    double b = glm::dot(r.o, d);
    glm::dvec3 perp = r.o - b * d;
    double disc = bound * bound - glm::dot(perp, perp);
    if (disc < 0) return false;
    double half = std::sqrt(disc);
    double k_in = -b - half, k_out = -b + half;
    double k_lo = std::max(k_in, tmin * len), k_hi = std::min(k_out, tmax * len);
    if (!(k_lo <= k_hi)) return false;
    if (misses_tube(s, r.o, d, k_lo, k_hi)) return false;
    // Quartic in s = k - k_in from p = the sphere entry point.
    glm::dvec3 p = r.o + k_in * d;
    double R2 = s.major * s.major;
    double f = glm::dot(p, d);
    double e = glm::dot(p, p) + R2 - s.minor * s.minor;
    double dxz = d.x * d.x + d.z * d.z;
    double pdxz = p.x * d.x + p.z * d.z;
    double pxz = p.x * p.x + p.z * p.z;
    double c[5] = {e * e - 4 * R2 * pxz, 4 * f * e - 8 * R2 * pdxz,
                   4 * f * f + 2 * e - 4 * R2 * dxz, 4 * f, 1};
    double roots[4];
    const double lo = k_lo - k_in, hi = k_hi - k_in;
    const auto distance = [&](double root) { return (root + k_in) / len; };
    const auto in_range = [&](double root) {
        const double t = distance(root);
        return t > tmin && t < tmax;
    };
    // The nearest root is nearly always the hit; the others are found only where it is not
    // (rounded onto tmin or tmax).
    int n = solve_polynomial_in(c, 4, lo, hi, roots, 1);
    if (n == 1 && !in_range(roots[0])) n = solve_polynomial_in(c, 4, lo, hi, roots);
    for (int i = 0; i < n; ++i) {
        if (!in_range(roots[i])) continue;
        const double t = distance(roots[i]);
        glm::dvec3 q = r.at(t);
        // Gradient of (|q|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), halved and divided by 2.
        double g = glm::dot(q, q) + R2 - s.minor * s.minor;
        h.t = t;
        h.normal = {q.x * (g - 2 * R2), q.y * g, q.z * (g - 2 * R2)};
        if (h.normal == glm::dvec3(0)) h.normal = {0, 1, 0};
        return true;
    }
    return false;
}

bool inside(const TorusShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    double ring = std::sqrt(p.x * p.x + p.z * p.z) - s.major;
    return ring * ring + p.y * p.y < s.minor * s.minor;
}

Aabb bounds(const TorusShape& s) {
    if (!s.valid) return {};
    double w = s.major + s.minor;
    return {{-w, -s.minor, -w}, {w, s.minor, w}};
}

}  // namespace lumen::render

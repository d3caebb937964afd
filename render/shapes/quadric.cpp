// quadric: POV-Ray's closed form (a tangent ray, discriminant <= 0, misses; no quadratic term
// leaves the linear root), hits in (1e-6, 1e7).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "render/shapes/quadric.hpp"

namespace lumen::render {

namespace {

constexpr double kMaxDistance = 1e7;

// The symmetric 4x4 matrix S with f(p) = (p, 1)^T S (p, 1), and back.
glm::dmat4 to_matrix(const QuadricShape& q) {
    glm::dmat4 s(0.0);
    s[0][0] = q.square.x;
    s[1][1] = q.square.y;
    s[2][2] = q.square.z;
    s[0][1] = s[1][0] = q.mixed.x / 2;
    s[0][2] = s[2][0] = q.mixed.y / 2;
    s[1][2] = s[2][1] = q.mixed.z / 2;
    s[0][3] = s[3][0] = q.linear.x / 2;
    s[1][3] = s[3][1] = q.linear.y / 2;
    s[2][3] = s[3][2] = q.linear.z / 2;
    s[3][3] = q.constant;
    return s;
}

QuadricShape from_matrix(const glm::dmat4& s) {
    QuadricShape q;
    q.square = {s[0][0], s[1][1], s[2][2]};
    q.mixed = {s[0][1] + s[1][0], s[0][2] + s[2][0], s[1][2] + s[2][1]};
    q.linear = {s[0][3] + s[3][0], s[1][3] + s[3][1], s[2][3] + s[3][2]};
    q.constant = s[3][3];
    return q;
}

bool finite(const QuadricShape& q) {
    auto ok = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    return ok(q.square) && ok(q.mixed) && ok(q.linear) && std::isfinite(q.constant);
}

}  // namespace

QuadricShape make_quadric(const scene::Quadric& q) {
    QuadricShape out{q.square, q.mixed, q.linear, q.constant, true};
    out.valid = finite(out);
    return out;
}

bool intersect(const QuadricShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    const glm::dvec3 &o = r.o, &d = r.d;
    const double A = s.square.x, B = s.square.y, C = s.square.z;
    const double D = s.mixed.x, E = s.mixed.y, F = s.mixed.z;
    const double G = s.linear.x, H = s.linear.y, I = s.linear.z;
    const double a = d.x * (A * d.x + D * d.y + E * d.z) + d.y * (B * d.y + F * d.z) +
                     d.z * C * d.z;
    const double b = d.x * (A * o.x + 0.5 * (D * o.y + E * o.z + G)) +
                     d.y * (B * o.y + 0.5 * (D * o.x + F * o.z + H)) +
                     d.z * (C * o.z + 0.5 * (E * o.x + F * o.y + I));
    const double c = o.x * (A * o.x + D * o.y + E * o.z + G) + o.y * (B * o.y + F * o.z + H) +
                     o.z * (C * o.z + I) + s.constant;
    double t0, t1;
    if (a != 0) {
        double disc = b * b - a * c;
        if (disc <= 0) return false;
        disc = std::sqrt(disc);
        t0 = (-b + disc) / a;
        t1 = (-b - disc) / a;
        if (t0 > t1) std::swap(t0, t1);
    } else {
        if (b == 0) return false;
        t0 = t1 = -0.5 * c / b;
    }
    double t;
    if (t0 > tmin && t0 < tmax && t0 < kMaxDistance) t = t0;
    else if (t1 > tmin && t1 < tmax && t1 < kMaxDistance) t = t1;
    else return false;
    const glm::dvec3 p = r.at(t);
    h.t = t;
    h.normal = {2 * A * p.x + D * p.y + E * p.z + G, D * p.x + 2 * B * p.y + F * p.z + H,
                E * p.x + F * p.y + 2 * C * p.z + I};
    if (h.normal == glm::dvec3(0)) h.normal = {1, 0, 0};  // undefined there: POV-Ray's choice
    return true;
}

bool inside(const QuadricShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    return p.x * (s.square.x * p.x + s.mixed.x * p.y + s.linear.x) +
               p.y * (s.square.y * p.y + s.mixed.z * p.z + s.linear.y) +
               p.z * (s.square.z * p.z + s.mixed.y * p.x + s.linear.z) + s.constant <=
           0;
}

Aabb bounds(const QuadricShape& s) { return s.valid ? bounds_within(s, Aabb::everything()) : Aabb{}; }

Aabb bounds_within(const QuadricShape& s, const Aabb& clip) {
    if (!s.valid || clip.empty()) return {};
    if (s.mixed != glm::dvec3(0)) return clip;
    constexpr double inf = Aabb::inf;
    // f = sum over axes of (A x + G) x, plus J. The least axis i's term takes in the clip box
    // (-inf where it falls without bound).
    auto term = [&](int i, double x) { return (s.square[i] * x + s.linear[i]) * x; };
    auto least = [&](int i) {
        const double A = s.square[i], G = s.linear[i], lo = clip.lo[i], hi = clip.hi[i];
        if (A > 0) return term(i, std::clamp(-G / (2 * A), lo, hi));
        if (A < 0) return std::isfinite(lo) && std::isfinite(hi) ? std::min(term(i, lo), term(i, hi)) : -inf;
        if (G > 0) return std::isfinite(lo) ? G * lo : -inf;
        if (G < 0) return std::isfinite(hi) ? G * hi : -inf;
        return 0.0;
    };
    const double floor[3] = {least(0), least(1), least(2)};
    Aabb out = clip;
    for (int j = 0; j < 3; ++j) {
        // Inside needs term_j(x) <= room.
        const double room = -s.constant - floor[(j + 1) % 3] - floor[(j + 2) % 3];
        if (!std::isfinite(room)) continue;
        const double A = s.square[j], G = s.linear[j];
        if (A > 0) {  // A (x - v)^2 <= room + A v^2
            const double v = -G / (2 * A);
            const double half = std::sqrt(std::max(0.0, room / A + v * v));
            const double margin = 1e-6 * (1 + std::fabs(v) + half);
            out.lo[j] = std::max(out.lo[j], v - half - margin);
            out.hi[j] = std::min(out.hi[j], v + half + margin);
        } else if (A == 0 && G != 0) {  // G x <= room
            const double x = room / G, margin = 1e-6 * (1 + std::fabs(x));
            if (G > 0) out.hi[j] = std::min(out.hi[j], x + margin);
            else out.lo[j] = std::max(out.lo[j], x - margin);
        }
    }
    return out;
}

// f_world(w) = f(M^-1 w): S' = M^-T S M^-1, exact for any invertible affine map.
bool ShapeTraits<scene::Quadric>::bake(const scene::Quadric& q, const scene::Transform& xf,
                                       QuadricShape& out) {
    QuadricShape local = make_quadric(q);
    if (!local.valid) return false;
    out = from_matrix(glm::transpose(xf.inv) * to_matrix(local) * xf.inv);
    out.valid = finite(out);
    return out.valid;
}

}  // namespace lumen::render

// Lambert's contour formula and its area average.
#include "render/radiosity/form_factor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "render/radiosity/quadrature.hpp"

namespace lumen::render::radiosity {

namespace {

// Sutherland-Hodgman against the plane n·(p − x) >= 0.
std::vector<glm::dvec3> clip_to_front(const std::vector<glm::dvec3>& poly, const glm::dvec3& x,
                                      const glm::dvec3& n) {
    std::vector<glm::dvec3> out;
    const size_t m = poly.size();
    out.reserve(m + 2);
    for (size_t i = 0; i < m; ++i) {
        const glm::dvec3& a = poly[i];
        const glm::dvec3& b = poly[(i + 1) % m];
        const double da = glm::dot(n, a - x), db = glm::dot(n, b - x);
        if (da >= 0) out.push_back(a);
        if ((da >= 0) != (db >= 0)) {
            const double t = da / (da - db);
            out.push_back(a + t * (b - a));
        }
    }
    return out;
}

}  // namespace

double point_to_polygon(const glm::dvec3& x, const glm::dvec3& n, const Patch& target) {
    if (target.degenerate()) return 0;
    const auto poly = clip_to_front(target.vertices, x, n);
    const size_t m = poly.size();
    if (m < 3) return 0;
    // A target in x's own tangent plane is seen edge-on (coplanar neighbours, z-fighting
    // copies, the patch itself): without this the contour sum of a point inside it is 2π.
    double height = 0, extent = 0;
    for (const auto& v : poly) {
        height = std::max(height, glm::dot(n, v - x));
        extent = std::max(extent, glm::length(v - x));
    }
    if (!(height > 1e-12 * extent)) return 0;
    double sum = 0;
    for (size_t i = 0; i < m; ++i) {
        const glm::dvec3 a = poly[i] - x, b = poly[(i + 1) % m] - x;
        const glm::dvec3 c = glm::cross(a, b);
        const double cl = glm::length(c);
        // x on the edge's line: the edge plane is undefined but its weight vanishes in the limit.
        if (!(cl > 1e-300)) continue;
        const double gamma = std::atan2(cl, glm::dot(a, b));
        sum += gamma * glm::dot(n, c) / cl;
    }
    const double f = std::abs(sum) / (2 * std::numbers::pi);
    return std::isfinite(f) ? std::clamp(f, 0.0, 1.0) : 0.0;
}

namespace {

// True when no part of `b` lies strictly in front of `a`'s plane.
bool behind(const Patch& a, const Patch& b) {
    const double scale = std::sqrt(a.area + b.area);
    for (const auto& v : b.vertices)
        if (glm::dot(a.normal, v - a.centroid) > 1e-12 * scale) return false;
    return true;
}

}  // namespace

double patch_to_patch(const Patch& from, const Patch& to, const QuadratureOptions& q) {
    if (from.degenerate() || to.degenerate()) return 0;
    // Pairs that cannot see each other's front cost nothing (most pairs in a big scene).
    if (behind(from, to) || behind(to, from)) return 0;
    const auto& rule = graded_rule(q.order, q.grading);
    double integral = 0;
    const auto& v = from.vertices;
    for (size_t k = 1; k + 1 < v.size(); ++k) {
        // Collapsed square: p = a + u (b − a) + u v (c − b), Jacobian u |(b − a) × (c − b)|.
        const glm::dvec3 a = v[0], ab = v[k] - v[0], bc = v[k + 1] - v[k];
        const double jac = glm::length(glm::cross(ab, bc));
        if (!(jac > 0)) continue;
        for (const auto& [u, wu] : rule)
            for (const auto& [w, ww] : rule) {
                const glm::dvec3 p = a + u * ab + u * w * bc;
                integral += wu * ww * u * jac * point_to_polygon(p, from.normal, to);
            }
    }
    const double f = integral / from.area;
    return std::isfinite(f) ? std::clamp(f, 0.0, 1.0) : 0.0;
}

}  // namespace lumen::render::radiosity

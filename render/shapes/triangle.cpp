// Triangle and smooth_triangle: two-sided Moller-Trumbore, no inside.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "render/shapes/triangle.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

bool make_triangle_core(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                        TriangleCore& out) {
    out = {a, b - a, c - a};
    glm::dvec3 n = glm::cross(out.e1, out.e2);
    double area2 = glm::dot(n, n);
    return area2 > 0 && std::isfinite(area2) && std::isfinite(glm::dot(a, a));
}

bool hit_triangle(const TriangleCore& s, const LocalRay& r, double tmin, double tmax, double& t,
                  double& u, double& v, double slack) {
    glm::dvec3 pvec = glm::cross(r.d, s.e2);
    double det = glm::dot(s.e1, pvec);
    if (det == 0) return false;  // ray in the triangle's plane
    double inv = 1.0 / det;
    glm::dvec3 tvec = r.o - s.p0;
    u = glm::dot(tvec, pvec) * inv;
    if (!(u >= -slack && u <= 1 + slack)) return false;
    glm::dvec3 qvec = glm::cross(tvec, s.e1);
    v = glm::dot(r.d, qvec) * inv;
    if (!(v >= -slack && u + v <= 1 + slack)) return false;
    t = glm::dot(s.e2, qvec) * inv;
    return t > tmin && t < tmax;
}

glm::dvec3 blend_normals(const std::array<glm::dvec3, 3>& n, const glm::dvec3& flat, double u,
                         double v) {
    glm::dvec3 b = (1 - u - v) * n[0] + u * n[1] + v * n[2];
    double len2 = glm::dot(b, b);
    return len2 > 0 && std::isfinite(len2) ? b : flat;
}

TriangleShape make_triangle(const scene::Triangle& t) {
    TriangleShape out;
    out.valid = make_triangle_core(t.p[0], t.p[1], t.p[2], out.core);
    out.normal = glm::cross(out.core.e1, out.core.e2);
    out.smooth = t.smooth;
    glm::dvec3 unit = out.valid ? glm::normalize(out.normal) : glm::dvec3(0, 1, 0);
    for (int i = 0; i < 3; ++i) {
        double len = glm::length(t.n[i]);
        out.n[i] = len > 0 && std::isfinite(len) ? t.n[i] / len : unit;
    }
    return out;
}

bool intersect(const TriangleShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    double t, u, v;
    if (!s.valid || !hit_triangle(s.core, r, tmin, tmax, t, u, v)) return false;
    h.t = t;
    h.normal = s.smooth ? blend_normals(s.n, s.normal, u, v) : s.normal;
    h.uv = {u, v};
    return true;
}

Aabb bounds(const TriangleShape& s) {
    if (!s.valid) return {};
    Aabb box;
    box.expand(s.core.p0);
    box.expand(s.core.p0 + s.core.e1);
    box.expand(s.core.p0 + s.core.e2);
    return box;
}

// Any affine map keeps a triangle a triangle.
bool ShapeTraits<scene::Triangle>::bake(const scene::Triangle& t, const scene::Transform& xf,
                                        TriangleShape& out) {
    scene::Triangle w = t;
    for (int i = 0; i < 3; ++i) {
        w.p[i] = xf.point(t.p[i]);
        w.n[i] = xf.normal(t.n[i]);
    }
    out = make_triangle(w);
    // Keep the side the object-space normal gave.
    if (glm::determinant(linear_part(xf)) < 0) out.normal = -out.normal;
    return true;
}

}  // namespace lumen::render

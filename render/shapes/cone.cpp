// Cylinder and cone (open or capped), solved in an axis frame where the axis is +z from 0 to
// `length`: side x^2 + y^2 = (r0 + k z)^2 with k = (r1 - r0) / length, caps at z = 0, length.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/polynomial.hpp"
#include "render/shapes/cone.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

namespace {

// Rows are an orthonormal basis whose third vector is the unit axis. The first two are POV-Ray's:
// its canonical shape is turned onto the axis by one rotation (about (a.y, -a.x, 0) by
// acos(-a.z), about x within 1e-10 of the z axis). Round-off of that rotation shows in normals
// that should have an exact zero: a cylinder along +z reports a normal z of about -1e-17 *
// normal.y, which `trace()` users print (language/trace.pov shows "-0.00"); probed with
// POV-Ray 3.7's trace().
glm::dmat3 frame_for(const glm::dvec3& a) {
    glm::dvec3 turn_axis;
    double angle;
    if (std::abs(a.z) > 1.0 - 1e-10) {
        turn_axis = {1, 0, 0};
        angle = a.z > 0 ? std::acos(-1.0) : 0.0;
    } else {
        turn_axis = glm::normalize(glm::dvec3(a.y, -a.x, 0));
        angle = std::acos(-a.z);
    }
    // Rodrigues: R = cos I + sin [k]x + (1 - cos) k k^T; u and v are R's first two columns.
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const glm::dvec3& k = turn_axis;
    glm::dvec3 u{t * k.x * k.x + c, t * k.x * k.y + s * k.z, t * k.x * k.z - s * k.y};
    glm::dvec3 v{t * k.x * k.y - s * k.z, t * k.y * k.y + c, t * k.y * k.z + s * k.x};
    // glm is column-major: the transpose of the column matrix (u v a) maps into the frame.
    return glm::transpose(glm::dmat3(u, v, a));
}

ConeShape make_axis_shape(glm::dvec3 base, glm::dvec3 cap, double r0, double r1, bool open) {
    ConeShape out;
    glm::dvec3 axis = cap - base;
    out.length = glm::length(axis);
    out.valid = out.length > 0 && std::isfinite(out.length) && r0 >= 0 && r1 >= 0 &&
                (r0 > 0 || r1 > 0) && std::isfinite(r0) && std::isfinite(r1);
    if (!out.valid) return out;
    out.to_axis = frame_for(axis / out.length);
    out.base = base;
    out.r0 = r0;
    out.r1 = r1;
    out.open = open;
    return out;
}

}  // namespace

CylinderShape make_cylinder(const scene::Cylinder& c) {
    return {make_axis_shape(c.base, c.cap, c.radius, c.radius, c.open)};
}

ConeShape make_cone(const scene::Cone& c) {
    return make_axis_shape(c.base, c.cap, c.base_radius, c.cap_radius, c.open);
}

bool intersect(const ConeShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    if (!s.valid) return false;
    glm::dvec3 o = s.to_axis * (r.o - s.base), d = s.to_axis * r.d;
    double k = (s.r1 - s.r0) / s.length;
    bool found = false;
    double best = tmax;
    glm::dvec3 normal{0};
    // Side: rho(t)^2 - (r0 + k z(t))^2 = 0.
    double rad0 = s.r0 + k * o.z;
    double a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    double b = o.x * d.x + o.y * d.y - k * d.z * rad0;
    double c = o.x * o.x + o.y * o.y - rad0 * rad0;
    double roots[2];
    int n = solve_quadratic(a, b, c, roots);
    for (int i = 0; i < n; ++i) {
        double t = roots[i];
        if (!(t > tmin && t < best)) continue;
        double z = o.z + t * d.z;
        if (z < 0 || z > s.length || s.r0 + k * z < 0) continue;  // outside the segment / nappe
        glm::dvec3 p = o + t * d;
        best = t;
        normal = {p.x, p.y, -k * (s.r0 + k * z)};
        found = true;
    }
    if (!s.open && d.z != 0) {
        const double zs[2] = {0, s.length}, rs[2] = {s.r0, s.r1};
        for (int i = 0; i < 2; ++i) {
            double t = (zs[i] - o.z) / d.z;
            if (!(t > tmin && t < best) || rs[i] <= 0) continue;
            double x = o.x + t * d.x, y = o.y + t * d.y;
            if (x * x + y * y > rs[i] * rs[i]) continue;
            best = t;
            normal = {0, 0, i == 0 ? -1.0 : 1.0};
            found = true;
        }
    }
    if (!found) return false;
    h.t = best;
    h.normal = glm::transpose(s.to_axis) * normal;  // back to object space (rotation)
    return true;
}

bool inside(const ConeShape& s, const glm::dvec3& p) {
    if (!s.valid) return false;
    glm::dvec3 q = s.to_axis * (p - s.base);
    if (q.z < 0 || q.z > s.length) return false;
    double rad = s.r0 + (s.r1 - s.r0) * (q.z / s.length);
    return q.x * q.x + q.y * q.y < rad * rad;
}

Aabb bounds(const ConeShape& s) {
    if (!s.valid) return {};
    // Each end disc of radius r around axis w spans r*sqrt(1 - w_i^2) along axis i.
    glm::dvec3 w = glm::transpose(s.to_axis)[2];
    glm::dvec3 spread = glm::sqrt(glm::max(glm::dvec3(0), 1.0 - w * w));
    glm::dvec3 cap = s.base + w * s.length;
    Aabb box;
    box.expand(s.base - spread * s.r0);
    box.expand(s.base + spread * s.r0);
    box.expand(cap - spread * s.r1);
    box.expand(cap + spread * s.r1);
    return box;
}

// A similarity keeps cylinders and cones round.
bool ShapeTraits<scene::Cylinder>::bake(const scene::Cylinder& c, const scene::Transform& xf,
                                        CylinderShape& out) {
    const double k = similarity_scale(xf);
    if (!(k > 0)) return false;
    out = make_cylinder({xf.point(c.base), xf.point(c.cap), c.radius * k, c.open});
    return true;
}

bool ShapeTraits<scene::Cone>::bake(const scene::Cone& c, const scene::Transform& xf,
                                    ConeShape& out) {
    const double k = similarity_scale(xf);
    if (!(k > 0)) return false;
    out = make_cone({xf.point(c.base), c.base_radius * k, xf.point(c.cap), c.cap_radius * k,
                     c.open});
    return true;
}

}  // namespace lumen::render

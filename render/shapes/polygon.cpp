// Polygon: hit its plane, then count edge crossings (even-odd) in the projection that drops
// the normal's dominant axis. Sub-polygons end where a point repeats their first point.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/shapes/polygon.hpp"
#include "render/shapes/linear_maps.hpp"

namespace lumen::render {

namespace {

bool same_point(const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 d = glm::abs(a - b);
    return d.x < 1e-10 && d.y < 1e-10 && d.z < 1e-10;
}

// Splits the written points into closed loops (the closing point is not repeated).
std::vector<std::vector<glm::dvec3>> loops_of(const std::vector<glm::dvec3>& pts) {
    std::vector<std::vector<glm::dvec3>> loops;
    std::vector<glm::dvec3> cur;
    for (const glm::dvec3& p : pts) {
        if (cur.size() >= 3 && same_point(p, cur.front())) {
            loops.push_back(std::move(cur));
            cur.clear();
        } else {
            cur.push_back(p);
        }
    }
    if (cur.size() >= 3) loops.push_back(std::move(cur));  // unclosed tail: close it
    return loops;
}

// Newell's normal of one loop: robust for any planar loop, length = twice its area.
glm::dvec3 newell(const std::vector<glm::dvec3>& loop) {
    glm::dvec3 n{0};
    for (size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3& a = loop[i];
        const glm::dvec3& b = loop[(i + 1) % loop.size()];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                        (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

}  // namespace

PolygonShape make_polygon(const scene::Polygon& poly) {
    PolygonShape out;
    auto loops = loops_of(poly.points);
    glm::dvec3 normal{0};
    for (const auto& loop : loops) {
        glm::dvec3 n = newell(loop);
        if (glm::dot(n, n) > glm::dot(normal, normal)) normal = n;
    }
    double len = glm::length(normal);
    out.valid = len > 0 && std::isfinite(len);
    if (!out.valid) return out;
    out.normal = normal / len;
    glm::dvec3 a = glm::abs(out.normal);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    out.axis_u = axis == 0 ? 1 : 0;
    out.axis_v = axis == 2 ? 1 : 2;
    out.distance = glm::dot(out.normal, loops.front().front());
    for (const auto& loop : loops) {
        for (size_t i = 0; i < loop.size(); ++i) {
            const glm::dvec3& p = loop[i];
            const glm::dvec3& q = loop[(i + 1) % loop.size()];
            out.edges.push_back({p[out.axis_u], p[out.axis_v]});
            out.edges.push_back({q[out.axis_u], q[out.axis_v]});
            out.box.expand(p);
        }
    }
    return out;
}

bool intersect(const PolygonShape& s, const LocalRay& r, double tmin, double tmax, ShapeHit& h) {
    double denom = glm::dot(s.normal, r.d);
    if (!s.valid || denom == 0) return false;
    double t = (s.distance - glm::dot(s.normal, r.o)) / denom;
    if (!(t > tmin && t < tmax)) return false;
    glm::dvec3 p = r.at(t);
    double u = p[s.axis_u], v = p[s.axis_v];
    bool in = false;
    for (size_t i = 0; i + 1 < s.edges.size(); i += 2) {
        const glm::dvec2& a = s.edges[i];
        const glm::dvec2& b = s.edges[i + 1];
        if ((a.y > v) != (b.y > v) && u < a.x + (v - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    if (!in) return false;
    h.t = t;
    h.normal = s.normal;
    return true;
}

Aabb bounds(const PolygonShape& s) { return s.valid ? s.box : Aabb{}; }

// Any affine map keeps a polygon a polygon.
bool ShapeTraits<scene::Polygon>::bake(const scene::Polygon& poly, const scene::Transform& xf,
                                       PolygonShape& out) {
    scene::Polygon w;
    for (const glm::dvec3& p : poly.points) w.points.push_back(xf.point(p));
    out = make_polygon(w);
    // Newell's normal follows the winding, which a mirror reverses relative to ours.
    PolygonShape local = make_polygon(poly);
    if (out.valid && local.valid && glm::dot(out.normal, xf.normal(local.normal)) < 0) {
        out.normal = -out.normal;
        out.distance = -out.distance;
    }
    return true;
}

}  // namespace lumen::render

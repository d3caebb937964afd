// Moves an object's transform into its shape where the shape stays the same kind in world
// space (any affine map for planes, triangles and polygons; similarities for spheres, discs,
// cylinders and cones; axis scalings for boxes). Baked shapes are traced with no per-ray
// matrix work, which is where most primitives of real scenes spend their transform cost.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "render/node.hpp"

namespace lumen::render {

namespace {

glm::dmat3 linear_part(const scene::Transform& xf) { return glm::dmat3(xf.m); }

// Uniform scale factor if the linear part is a rotation (or mirror) times a scale, else 0.
double similarity_scale(const glm::dmat3& m) {
    double s2 = glm::dot(m[0], m[0]);
    double tol = 1e-12 * s2;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(glm::dot(m[i], m[i]) - s2) > tol) return 0;
        for (int j = i + 1; j < 3; ++j)
            if (std::abs(glm::dot(m[i], m[j])) > tol) return 0;
    }
    return std::sqrt(s2);
}

bool is_axis_scaling(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (c != r && m[c][r] != 0) return false;
    return true;
}

}  // namespace

bool bake_transform(const scene::Shape& shape, const scene::Transform& xf, ShapeData& out) {
    glm::dmat3 m = linear_part(xf);
    double det = glm::determinant(m);
    if (!(det != 0) || !std::isfinite(det)) return false;
    if (auto* p = std::get_if<scene::Plane>(&shape)) {
        PlaneShape local = make_plane(*p);
        if (!local.valid) return false;
        glm::dvec3 n = glm::normalize(xf.normal(local.normal));
        out = make_plane({n, glm::dot(n, xf.point(local.normal * local.distance))});
        return true;
    }
    if (auto* t = std::get_if<scene::Triangle>(&shape)) {
        scene::Triangle w = *t;
        for (int i = 0; i < 3; ++i) {
            w.p[i] = xf.point(t->p[i]);
            w.n[i] = xf.normal(t->n[i]);
        }
        TriangleShape baked = make_triangle(w);
        if (det < 0) baked.normal = -baked.normal;  // keep the side the object-space normal gave
        out = baked;
        return true;
    }
    if (auto* poly = std::get_if<scene::Polygon>(&shape)) {
        scene::Polygon w;
        for (const glm::dvec3& p : poly->points) w.points.push_back(xf.point(p));
        PolygonShape baked = make_polygon(w);
        // Newell's normal follows the winding, which a mirror reverses relative to ours.
        PolygonShape local = make_polygon(*poly);
        if (baked.valid && local.valid && glm::dot(baked.normal, xf.normal(local.normal)) < 0) {
            baked.normal = -baked.normal;
            baked.distance = -baked.distance;
        }
        out = std::move(baked);
        return true;
    }
    if (auto* b = std::get_if<scene::Box>(&shape)) {
        if (!is_axis_scaling(m)) return false;
        glm::dvec3 a = xf.point(b->min), c = xf.point(b->max);
        out = make_box({glm::min(a, c), glm::max(a, c)});
        return true;
    }
    double s = similarity_scale(m);
    if (!(s > 0)) return false;
    if (auto* sp = std::get_if<scene::Sphere>(&shape)) {
        out = make_sphere({xf.point(sp->center), sp->radius * s});
    } else if (auto* d = std::get_if<scene::Disc>(&shape)) {
        out = make_disc({xf.point(d->center), xf.normal(d->normal), d->radius * s, d->hole * s});
    } else if (auto* c = std::get_if<scene::Cylinder>(&shape)) {
        out = make_cylinder({xf.point(c->base), xf.point(c->cap), c->radius * s, c->open});
    } else if (auto* c = std::get_if<scene::Cone>(&shape)) {
        out = make_cone({xf.point(c->base), c->base_radius * s, xf.point(c->cap),
                         c->cap_radius * s, c->open});
    } else {
        return false;  // torus, mesh: traced in object space
    }
    return true;
}

}  // namespace lumen::render

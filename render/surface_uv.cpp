// Each shape's uv under uv_mapping. Measured with povray 3.7 (ambient-1 gradient and checker
// pigments under uv_mapping, orthographic views; tests/textures/uv_mapping.pov):
// * sphere: u = turn of (x, z) about the centre (0.75 facing -z), v = 0.5 + asin(y)/pi of the
//   unit direction from the centre;
// * box: the unfolded cross of its faces, a 4 x 3 grid of cells (u across the x-min, z-max
//   (front), x-max and z-min faces, v up them; the y faces above and below the front one);
// * torus: u = 1 - (atan2(z, x) + pi)/(2 pi) about y, v the same turn about the tube;
// * mesh, mesh2, bicubic_patch, lathe, sor and parametric: what their intersection worked out
//   (a parametric's own u and v, those of the piece where its depth was found);
// * everything else: the world hit's x and y.
#include "render/surface_uv.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/shapes.hpp"

namespace lumen::render {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct UvQuery {
    const glm::dvec3& local;
    const glm::dvec3& world;
    const ShapeHit& hit;
};

template <class S> glm::dvec2 uv_of(const S&, const UvQuery& q) { return {q.world.x, q.world.y}; }

glm::dvec2 uv_of(const SphereShape& s, const UvQuery& q) {
    const glm::dvec3 d = q.local - s.centre;
    const double len = glm::length(d);
    if (!(len > 0)) return {0, 0.5};
    const glm::dvec3 n = d / len;
    return {turn_fraction(n.x, n.z), 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / std::numbers::pi};
}

// The face comes from the slab the intersection used (its normal's axis and sign).
glm::dvec2 uv_of(const BoxShape& s, const UvQuery& q) {
    const glm::dvec3 size = s.box.hi - s.box.lo;
    glm::dvec3 f = (q.local - s.box.lo) / size;
    for (int i = 0; i < 3; ++i)
        if (!(size[i] > 0)) f[i] = 0;
    const glm::dvec3& n = q.hit.normal;
    const int axis = n.x != 0 ? 0 : n.y != 0 ? 1 : 2;
    const bool low = n[axis] < 0;
    switch (axis) {
        case 0: return {low ? f.z / 4 : 0.75 - f.z / 4, 1.0 / 3 + f.y / 3};
        case 1: return {0.25 + f.x / 4, low ? f.z / 3 : 1 - f.z / 3};
        default: return {low ? 1 - f.x / 4 : 0.25 + f.x / 4, 1.0 / 3 + f.y / 3};
    }
}

glm::dvec2 uv_of(const TorusShape& s, const UvQuery& q) {
    const glm::dvec3& p = q.local;
    const double pi = std::numbers::pi;
    const double around = std::atan2(p.z, p.x), tube = std::atan2(p.y, std::hypot(p.x, p.z) - s.major);
    return {1 - (around + pi) / kTwoPi, (tube + pi) / kTwoPi};
}

glm::dvec2 uv_of(const MeshPtr&, const UvQuery& q) { return q.hit.uv; }
glm::dvec2 uv_of(const ParametricShape&, const UvQuery& q) { return q.hit.uv; }

// Swept shapes: v from the intersection (the curve parameter), u the turn about the axis.
glm::dvec2 uv_of(const LatheShape&, const UvQuery& q) {
    return {turn_fraction(q.local.x, q.local.z), q.hit.uv.y};
}
glm::dvec2 uv_of(const SorShape&, const UvQuery& q) {
    return {turn_fraction(q.local.x, q.local.z), q.hit.uv.y};
}

}  // namespace

double turn_fraction(double x, double z) {
    if (x * x + z * z <= 1e-10) return 0;
    double a = std::atan2(z, x);
    if (a < 0) a += kTwoPi;
    return a / kTwoPi;
}

glm::dvec2 surface_uv(const ShapeData& shape, const glm::dvec3& local, const glm::dvec3& world,
                      const ShapeHit& hit) {
    const UvQuery q{local, world, hit};
    const glm::dvec2 uv = std::visit([&](const auto& s) { return uv_of(s, q); }, shape);
    return std::isfinite(uv.x) && std::isfinite(uv.y) ? uv : glm::dvec2(0);
}

}  // namespace lumen::render

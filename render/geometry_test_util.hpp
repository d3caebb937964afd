// Helpers for the geometry tests: building objects, transforms and scenes in a line each.
#pragma once
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render/geometry.hpp"

namespace lumen::render::testing {

inline scene::Transform from_matrix(const glm::dmat4& m) { return {m, glm::inverse(m)}; }
inline scene::Transform translate(glm::dvec3 v) {
    return from_matrix(glm::translate(glm::dmat4(1.0), v));
}
inline scene::Transform scale(glm::dvec3 v) { return from_matrix(glm::scale(glm::dmat4(1.0), v)); }
inline scene::Transform rotate(double degrees, glm::dvec3 axis) {
    return from_matrix(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis));
}

inline std::shared_ptr<scene::Object> make(scene::Shape shape,
                                           scene::Transform xf = scene::Transform{}) {
    auto o = std::make_shared<scene::Object>();
    o->shape = std::move(shape);
    o->transform = xf;
    return o;
}

inline std::shared_ptr<scene::Object> csg(scene::CsgOp op, std::vector<scene::ObjectPtr> kids) {
    return make(scene::Csg{op, std::move(kids)});
}

// Geometry points into its scene, so test scenes live until the test program ends.
inline const scene::Scene& scene_of(std::vector<scene::ObjectPtr> objects) {
    static std::deque<scene::Scene> keep;
    keep.emplace_back().objects = std::move(objects);
    return keep.back();
}

inline Ray ray(glm::dvec3 origin, glm::dvec3 dir) { return {origin, glm::normalize(dir)}; }

// The nearest hit beyond POV's global 1e-4, if any.
inline std::optional<Hit> trace(const Geometry& g, const Ray& r, bool shadow = false,
                                double t_min = 1e-4) {
    Hit h;
    if (!g.intersect(r, t_min, 1e30, h, shadow ? Query::Shadow : Query::All)) return std::nullopt;
    return h;
}

inline scene::LayeredTexture some_texture() {
    return {std::make_shared<const scene::Texture>()};
}

}  // namespace lumen::render::testing

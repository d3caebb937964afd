// Affine transform kept with its inverse (POV composes transforms in the order written:
// p' = T_last(...T_first(p))).
#pragma once
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace lumen::scene {

struct Transform {
    glm::dmat4 m{1.0};    // local -> world
    glm::dmat4 inv{1.0};  // world -> local

    bool is_identity() const { return m == glm::dmat4(1.0); }
    // Applies `next` after this transform (this then next).
    Transform then(const Transform& next) const { return {next.m * m, inv * next.inv}; }
    glm::dvec3 point(const glm::dvec3& p) const { return glm::dvec3(m * glm::dvec4(p, 1.0)); }
    glm::dvec3 vector(const glm::dvec3& v) const { return glm::dvec3(m * glm::dvec4(v, 0.0)); }
    glm::dvec3 inv_point(const glm::dvec3& p) const { return glm::dvec3(inv * glm::dvec4(p, 1.0)); }
    glm::dvec3 inv_vector(const glm::dvec3& v) const { return glm::dvec3(inv * glm::dvec4(v, 0.0)); }
    // Normals go through the inverse transpose.
    glm::dvec3 normal(const glm::dvec3& n) const {
        return glm::dvec3(glm::transpose(inv) * glm::dvec4(n, 0.0));
    }
};

}  // namespace lumen::scene

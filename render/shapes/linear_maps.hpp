// Kinds of linear map a shape's bake() checks: a transform bakes into a shape only when the
// shape stays the same kind in world space.
#pragma once
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "scene/transform.hpp"

namespace lumen::render {

inline glm::dmat3 linear_part(const scene::Transform& xf) { return glm::dmat3(xf.m); }

// Uniform scale factor if the linear part is a rotation (or mirror) times a scale, else 0.
inline double similarity_scale(const glm::dmat3& m) {
    double s2 = glm::dot(m[0], m[0]);
    double tol = 1e-12 * s2;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(glm::dot(m[i], m[i]) - s2) > tol) return 0;
        for (int j = i + 1; j < 3; ++j)
            if (std::abs(glm::dot(m[i], m[j])) > tol) return 0;
    }
    return std::sqrt(s2);
}

inline double similarity_scale(const scene::Transform& xf) {
    return similarity_scale(linear_part(xf));
}

inline bool is_axis_scaling(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (c != r && m[c][r] != 0) return false;
    return true;
}

}  // namespace lumen::render

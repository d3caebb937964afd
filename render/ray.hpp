// A ray with a unit direction, so every depth t is a true distance (POV normalises primary rays).
#pragma once
#include <glm/vec3.hpp>

namespace lumen::render {

struct Ray {
    glm::dvec3 origin{0};
    glm::dvec3 dir{0, 0, 1};  // unit length
    glm::dvec3 at(double t) const { return origin + t * dir; }
};

}  // namespace lumen::render

// Formulas of POV-Ray 3.7's leopard and quilted, checked against povray renders
// (tests/patterns/leopard_quilted.pov).
#include "render/patterns/periodic.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace lumen::render {

// Spots on a cubic lattice: ((sin x + sin y + sin z) / 3)².
double evaluate(const scene::pattern::Leopard&, const glm::dvec3& p) {
    const double s = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3;
    return s * s;
}

// Unit cubes with rounded edges: the offset from the cube's centre, shaped by a cubic whose
// middle control points are control0 and control1 and normalised so a corner gives 1.
double evaluate(const scene::pattern::Quilted& k, const glm::dvec3& p) {
    const glm::dvec3 v = p - glm::floor(p) - glm::dvec3(0.5);
    const double t = glm::length(v), u = 1 - t;
    const double shape =
        (t * t * t + 3 * t * u * u * k.control0 + 3 * t * t * u * k.control1) * 1.154700538;
    return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) * std::fabs(shape) / 3;
}

}  // namespace lumen::render

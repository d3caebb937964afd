#include "render/patterns/normal_forms.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

const double kHalfDiagonal = std::sqrt(3.0) / 2;

// The quilt's cross-section: a cubic Bezier curve from 0 to 1 with control points control0
// and control1 (POV-Ray's manual: 0 and 0 give a straight slope, 1 and 1 an S curve).
double quilt_profile(double t, double c0, double c1) {
    const double it = 1 - t;
    return t * t * t + 3 * t * t * it * c1 + 3 * t * it * it * c0;
}

}  // namespace

// Each unit cube is one quilt: the normal leans away from the cube's centre by the profile of
// the distance to it, over half the cube's diagonal (the factor measured against povray
// renders, exact to the pixel for any amount, controls and scale).
void add_form(const scene::pattern::Quilted& k, double amount, const glm::dvec3& p, glm::dvec3& n) {
    const glm::dvec3 d = p - glm::floor(p) - glm::dvec3(0.5);
    const double t = quilt_profile(glm::length(d), k.control0, k.control1);
    n += amount * (d * (t / kHalfDiagonal));
}

}  // namespace lumen::render

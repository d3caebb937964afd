// bump_map: the image's grey as a height field over the surface, as POV-Ray 3.7 perturbs it
// (matched pixel by pixel against povray renders: tests/images). The heights at the point and
// at the pixels one left-and-down and one right-and-down of it (rows grow downwards) span a
// triangle whose normal, set in a frame around the surface normal, is the new normal.
#include <cmath>

#include <glm/geometric.hpp>

#include "render/patterns/image_lookup.hpp"
#include "render/patterns/normal_forms.hpp"
#include "scene/image_map.hpp"

namespace lumen::render {

void apply_form(const pattern::BumpMap& k, const scene::Normal& normal, const glm::dvec3& p,
                glm::dvec3& n) {
    constexpr double kEpsilon = 1e-10;
    const auto at = image_position(k, p);
    if (!at) return;  // off the map: the normal is kept
    const double w = k.data->image.width, h = k.data->image.height;
    const double amount = normal.amount;
    const double h1 = amount * bump_height(k, *at);
    double x2 = at->x - 1, y2 = at->y + 1;
    if (x2 < 0) x2 += w;
    if (y2 >= h) y2 -= h;
    double x3 = x2 + 2;
    if (x3 >= w) x3 -= w;
    const double h2 = amount * bump_height(k, {x2, y2});
    const double h3 = amount * bump_height(k, {x3, y2});
    // The normal of the triangle (0, h1, 0), (-1, h2, 1), (1, h3, 1).
    const glm::dvec3 b = glm::normalize(glm::dvec3(h2 - h3, 2, 2 * h1 - h2 - h3));
    glm::dvec3 x = glm::cross(n, glm::dvec3(0, 1, 0)), y;
    const double len = glm::length(x);
    if (len < kEpsilon) {
        x = {1, 0, 0};
        y = std::fabs(n.y - 1) < kEpsilon ? glm::dvec3(0, 1, 0) : glm::dvec3(0, -1, 0);
    } else {
        x /= len;
        y = n;
    }
    const glm::dvec3 z = glm::normalize(glm::cross(x, y));
    n = b.x * x + b.y * y - b.z * z;
}

}  // namespace lumen::render

// RGBFT colour: POV colours have five channels (red, green, blue, filter, transmit).
#pragma once
#include <glm/vec3.hpp>

namespace lumen::scene {

struct Colour {
    double r = 0, g = 0, b = 0, f = 0, t = 0;

    glm::dvec3 rgb() const { return {r, g, b}; }
    static Colour from_rgb(const glm::dvec3& c) { return {c.x, c.y, c.z, 0, 0}; }
    bool operator==(const Colour&) const = default;
};

}  // namespace lumen::scene

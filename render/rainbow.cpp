#include "render/rainbow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/pattern.hpp"

namespace lumen::render {

double arc_strength(const scene::Rainbow::Arc& arc, const glm::dvec3& axis, const glm::dvec3& up,
                    const glm::dvec3& dir) {
    // The azimuths of `dir` and `up` around the axis (the builder refuses an up along it).
    const glm::dvec3 across = glm::normalize(up - glm::dot(up, axis) * axis);
    const glm::dvec3 v = dir - glm::dot(dir, axis) * axis;
    const double len = glm::length(v);
    const double cosine = len > 0 ? std::clamp(glm::dot(v, across) / len, -1.0, 1.0) : 1.0;
    const double azimuth = std::acos(cosine) * (180 / std::numbers::pi);
    const double end = arc.arc_angle / 2, full = arc.falloff_angle / 2;
    if (azimuth > end) return 0;
    if (azimuth <= full) return 1;
    // Probed: 1 - 3x^2 + 2x^3 over x = (azimuth - full) / (end - full), to 8-bit rounding at
    // arcs of 90-360 degrees with falloffs of 0-90.
    const double x = (azimuth - full) / (end - full);
    return 1 - x * x * (3 - 2 * x);
}

bool through_rainbow(const scene::Rainbow& r, const glm::dvec3& dir, double depth,
                     const glm::dvec3& behind, double u, glm::dvec3& seen, double& transmit) {
    const double len = glm::length(r.direction);
    if (!(len > 0) || !(r.width > 0) || r.colour_map.empty()) return false;
    const double cosine = std::clamp(glm::dot(dir, r.direction / len), -1.0, 1.0);
    const double theta = std::acos(cosine) * (180 / std::numbers::pi);
    // The position across the band, 0 at its inner edge; jitter moves it by up to ± jitter
    // before the band's ends are tested (probed: with jitter 0.5 a ray 0.16 inside the band's
    // edge took 0.29 of the map).
    double index = (theta - (r.angle - r.width / 2)) / r.width;
    if (r.jitter > 0) index += r.jitter * (2 * u - 1);
    if (!(index >= 0 && index <= 1)) return false;
    const double strength = r.arc ? arc_strength(*r.arc, r.direction / len, r.up, dir) : 1;
    if (!(strength > 0)) return false;
    const scene::Colour c = lookup_colour_map(r.colour_map, index);
    const glm::dvec3 rgb(c.r, c.g, c.b);
    // What shows through: the fog term, at least the colour's transmit. The filter tints it
    // by the part the fog term leaves (filter 0.5, transmit 0.2 over rgb 0.5, 0.6, 0.7 gave
    // 0.73201, 0.4112, 0.25521).
    // (At most 1: a negative distance would otherwise amplify what lies behind.)
    // Towards an arc's ends the band fades: its cover, 1 - k, shrinks by the arc's strength
    // (probed on tests/atmosphere/rainbow_arc.pov, whose map filters and transmits: 91 dB
    // against POV-Ray, where blending the faded band's result over what lies behind gave 49).
    const double k = 1 - strength * (1 - std::clamp(std::max(std::exp(-depth / r.distance), c.t),
                                                    0.0, 1.0));
    const double f = c.f * (1 - k);
    transmit = k;
    seen = behind * (k * ((1 - f) + f * rgb)) + (1 - k) * rgb;
    return true;
}

glm::dvec3 through_rainbows(const std::vector<scene::Rainbow>& rainbows, const glm::dvec3& dir,
                            double depth, const glm::dvec3& behind, const std::function<double()>& u,
                            double& transmit) {
    // Where bands overlap, POV-Ray averages what each band alone would make of the colour
    // (probed: two bands over the sky gave the mean of one band's colour and the sky's).
    glm::dvec3 sum(0);
    double transmits = 0;
    int n = 0;
    for (const scene::Rainbow& r : rainbows) {
        glm::dvec3 seen;
        double k;
        if (!through_rainbow(r, dir, depth, behind, r.jitter > 0 ? u() : 0.0, seen, k)) continue;
        sum += seen;
        transmits += k;
        ++n;
    }
    if (n == 0) return behind;
    transmit *= transmits / n;
    return sum / double(n);
}

}  // namespace lumen::render

// Non-noise pattern functions. Formulas follow the POV-Ray 3.7 reference manual; the block
// patterns' layouts (brick offsets, hexagon/square colour placement) were matched pixel by
// pixel against povray 3.7 renders.
#include "render/pattern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lumen::render {
namespace {

using scene::Colour;
using scene::PatternType;

constexpr double kEpsilon = 1e-10;

double checker(const glm::dvec3& p) {
    const long s = long(std::floor(p.x + kEpsilon)) + long(std::floor(p.y + kEpsilon)) +
                   long(std::floor(p.z + kEpsilon));
    return double(s & 1);
}

double gradient(const scene::Pattern& pat, const glm::dvec3& p) {
    double v = p.x * pat.gradient.x + p.y * pat.gradient.y + p.z * pat.gradient.z;
    if (v > 1) v = std::fmod(v, 1.0);
    return v;
}

double radial(const glm::dvec3& p) {
    // 0 at +x, 0.25 at -z, 0.5 at -x, 0.75 at +z (winding around +y).
    return std::atan2(-p.z, p.x) / (2 * std::numbers::pi);
}

double wrap_mod(double v, double m) { return v - std::floor(v / m) * m; }

// Mortar (0) surrounds each brick (1); odd rows shift x by half a brick, even rows shift z.
double brick(const scene::Pattern& pat, glm::dvec3 p) {
    const glm::dvec3 size = pat.brick_size;
    const double mortar = pat.mortar;
    p += glm::dvec3(kEpsilon);
    const double row = std::floor(p.y / size.y);
    if (std::fmod(row, 2.0) != 0)
        p.x += size.x / 2;
    else
        p.z += size.z / 2;
    const double xr = wrap_mod(p.x, size.x), yr = p.y - row * size.y, zr = wrap_mod(p.z, size.z);
    const bool in_mortar = xr >= size.x - mortar || yr >= size.y - mortar || zr >= size.z - mortar;
    return in_mortar ? 0.0 : 1.0;
}

// Hexagons of side 1 in the xz plane centred on a triangular lattice with basis
// a = (0, √3) and b = (1.5, √3/2); cell i·a + j·b gets colour (i − j) mod 3, which puts
// colour 0 at the origin, colour 1 in +z and colour 2 on either side.
double hexagon(const glm::dvec3& p) {
    const double s3 = std::sqrt(3.0);
    const double jf = p.x / 1.5;
    const double j0 = std::floor(jf);
    double best = 1e300;
    long bi = 0, bj = 0;
    for (long j = long(j0); j <= long(j0) + 1; ++j) {
        const double i0 = std::floor((p.z - j * s3 / 2) / s3);
        for (long i = long(i0); i <= long(i0) + 1; ++i) {
            const double cx = 1.5 * j, cz = i * s3 + j * s3 / 2;
            const double d = (p.x - cx) * (p.x - cx) + (p.z - cz) * (p.z - cz);
            if (d < best) best = d, bi = i, bj = j;
        }
    }
    return double(((bi - bj) % 3 + 3) % 3);
}

// Unit squares in the xz plane; the four colours tile a 2x2 block.
double square(const glm::dvec3& p) {
    const long a = long(std::floor(p.x)) & 1, b = long(std::floor(p.z)) & 1;
    return double(2 * (1 - b) + (a ^ b));
}

long mod3(double v) { return ((long(v) % 3) + 3) % 3; }

// Equilateral triangles of side 1 in the xz plane, in bands of height √3/2 whose upward
// triangles alternate between half-integer and integer centres; six colours meet at every
// vertex. Layout matched pixel by pixel against povray 3.7.
double triangular(const glm::dvec3& p) {
    const double h = std::sqrt(3.0) / 2;
    const double band = std::floor(p.z / h);
    const double v = p.z / h - band;  // 0 at the band's bottom edge
    const double half_width = (1 - v) / 2;  // of the upward triangle at this height
    const double fl = std::floor(p.x), nearest = std::floor(p.x + 0.5);
    static constexpr int even_up[3] = {2, 4, 0}, even_down[3] = {1, 5, 3};
    static constexpr int odd_up[3] = {4, 0, 2}, odd_down[3] = {3, 1, 5};
    if (std::fmod(std::fabs(band), 2.0) == 0) {
        if (std::fabs(p.x - (fl + 0.5)) < half_width) return even_up[mod3(fl)];
        return even_down[mod3(nearest)];
    }
    if (std::fabs(p.x - nearest) < half_width) return odd_up[mod3(nearest)];
    return odd_down[mod3(fl)];
}

double raw_value(const scene::Pattern& pat, const glm::dvec3& p) {
    switch (pat.type) {
        case PatternType::Checker: return checker(p);
        case PatternType::Gradient: return gradient(pat, p);
        case PatternType::Planar: return 1.0 - std::min(1.0, std::fabs(p.y));
        case PatternType::Radial: return radial(p);
        case PatternType::Onion: return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        case PatternType::Spherical: return 1.0 - std::min(1.0, glm::length(p));
        case PatternType::Cylindrical: return 1.0 - std::min(1.0, std::sqrt(p.x * p.x + p.z * p.z));
        case PatternType::Boxed:
            return 1.0 - std::min(1.0, std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
        case PatternType::Brick: return brick(pat, p);
        case PatternType::Hexagon: return hexagon(p);
        case PatternType::Square: return square(p);
        case PatternType::Triangular: return triangular(p);
        default: return 0.0;  // Plain, noise-based and unsupported patterns
    }
}

double apply_wave(const scene::Pattern& pat, double v) {
    using scene::WaveType;
    switch (pat.wave) {
        case WaveType::Ramp: return v;
        case WaveType::Sine: return (1 + std::sin(2 * std::numbers::pi * v)) / 2;
        case WaveType::Triangle: return v < 0.5 ? 2 * v : 2 - 2 * v;
        case WaveType::Scallop: return std::fabs(std::sin(std::numbers::pi * v));
        case WaveType::Cubic: return v * v * (3 - 2 * v);
        case WaveType::Poly: return std::pow(v, pat.wave_exponent);
    }
    return v;
}


}  // namespace

bool is_discrete(scene::PatternType type) {
    return type == PatternType::Checker || type == PatternType::Brick ||
           type == PatternType::Hexagon || type == PatternType::Square ||
           type == PatternType::Triangular;
}

double pattern_value(const scene::Pattern& pattern, const glm::dvec3& world_point) {
    const glm::dvec3 p = pattern.transform.is_identity() ? world_point
                                                         : pattern.transform.inv_point(world_point);
    double v = raw_value(pattern, p);
    if (is_discrete(pattern.type)) return v;
    v = std::fmod(v * pattern.frequency + pattern.phase, 1.00001);
    if (v < 0) v -= std::floor(v);
    return apply_wave(pattern, v);
}

const scene::ColourMap& default_colour_map(scene::PatternType type) {
    auto c = [](double v, double r, double g, double b) {
        return scene::ColourMapEntry{v, Colour{r, g, b, 0, 0}};
    };
    static const scene::ColourMap grey_ramp{c(0, 0, 0, 0), c(1, 1, 1, 1)};
    static const scene::ColourMap checker_map{c(0, 0, 0, 1), c(1, 0, 1, 0)};
    static const scene::ColourMap brick_map{c(0, 0.5, 0.5, 0.5), c(1, 0.6, 0.15, 0.15)};
    static const scene::ColourMap hexagon_map{c(0, 0, 0, 1), c(1, 0, 1, 0), c(2, 1, 0, 0)};
    static const scene::ColourMap square_map{c(0, 0, 0, 1), c(1, 0, 1, 0), c(2, 1, 0, 0),
                                             c(3, 1, 1, 0)};
    static const scene::ColourMap triangular_map{c(0, 0, 0, 1), c(1, 0, 1, 0), c(2, 1, 0, 0),
                                                 c(3, 1, 0, 1), c(4, 0, 1, 1), c(5, 1, 1, 0)};
    // Measured from povray renders: cyan -> yellow -> magenta -> cyan.
    static const scene::ColourMap radial_map{c(0, 0, 1, 1), c(0.333, 1, 1, 0), c(0.666, 1, 0, 1),
                                             c(1, 0, 1, 1)};
    switch (type) {
        case PatternType::Checker: return checker_map;
        case PatternType::Brick: return brick_map;
        case PatternType::Hexagon: return hexagon_map;
        case PatternType::Square: return square_map;
        case PatternType::Triangular: return triangular_map;
        case PatternType::Radial: return radial_map;
        default: return grey_ramp;
    }
}

scene::Colour lookup_colour_map(const scene::ColourMap& map, double v) {
    const BlendWeights b = blend_weights(map, v);
    if (map.empty()) return {};
    const Colour& lo = map[b.lower].colour;
    if (b.upper_weight == 0) return lo;
    const Colour& hi = map[b.upper].colour;
    const double w = b.upper_weight;
    return {lo.r + w * (hi.r - lo.r), lo.g + w * (hi.g - lo.g), lo.b + w * (hi.b - lo.b),
            lo.f + w * (hi.f - lo.f), lo.t + w * (hi.t - lo.t)};
}

}  // namespace lumen::render

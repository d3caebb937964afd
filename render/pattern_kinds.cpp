// Non-noise pattern functions. Formulas follow the POV-Ray 3.7 reference manual; the block
// patterns' layouts (brick offsets, hexagon/square colour placement) were matched pixel by
// pixel against povray 3.7 renders.
#include "render/pattern_kinds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

double wrap_mod(double v, double m) { return v - std::floor(v / m) * m; }

long mod3(double v) { return ((long(v) % 3) + 3) % 3; }

}  // namespace

namespace pattern = scene::pattern;

// Not a pattern: a plain pigment or texture uses its own colour and never asks.
double evaluate(const pattern::Plain&, const glm::dvec3&) { return 0.0; }

double evaluate(const pattern::Checker&, const glm::dvec3& p) {
    const long s = long(std::floor(p.x + kEpsilon)) + long(std::floor(p.y + kEpsilon)) +
                   long(std::floor(p.z + kEpsilon));
    return double(s & 1);
}

double evaluate(const pattern::Gradient& k, const glm::dvec3& p) {
    double v = p.x * k.direction.x + p.y * k.direction.y + p.z * k.direction.z;
    if (v > 1) v = std::fmod(v, 1.0);
    return v;
}

double evaluate(const pattern::Planar&, const glm::dvec3& p) {
    return 1.0 - std::min(1.0, std::fabs(p.y));
}

// 0 at +x, 0.25 at -z, 0.5 at -x, 0.75 at +z (winding around +y), as POV computes it: in
// [0.25, 1.25), so the frequency's wrap at 1.00001 falls where POV's does, and 0.25 within
// 0.001 of the axis.
double evaluate(const pattern::Radial&, const glm::dvec3& p) {
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    return 0.25 + (std::atan2(p.x, p.z) + std::numbers::pi) / (2 * std::numbers::pi);
}

// Wrapped here, before the frequency's wrap at 1.00001 (beyond a radius of 1 the two differ).
double evaluate(const pattern::Onion&, const glm::dvec3& p) {
    return std::fmod(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0);
}

double evaluate(const pattern::Spherical&, const glm::dvec3& p) {
    return 1.0 - std::min(1.0, glm::length(p));
}

double evaluate(const pattern::Cylindrical&, const glm::dvec3& p) {
    return 1.0 - std::min(1.0, std::sqrt(p.x * p.x + p.z * p.z));
}

double evaluate(const pattern::Boxed&, const glm::dvec3& p) {
    return 1.0 - std::min(1.0, std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
}

// Mortar (0) surrounds each brick (1); odd rows shift x by half a brick, even rows shift z.
double evaluate(const pattern::Brick& k, const glm::dvec3& point) {
    const glm::dvec3 size = k.size;
    const double mortar = k.mortar;
    glm::dvec3 p = point + glm::dvec3(kEpsilon);
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
double evaluate(const pattern::Hexagon&, const glm::dvec3& p) {
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

// Unit squares in the xz plane; the four values tile a 2x2 block (even x: 0 at even z, 1 at
// odd z; odd x: 3, then 2), as povray's list form shows them.
double evaluate(const pattern::Square&, const glm::dvec3& p) {
    const long a = long(std::floor(p.x)) & 1, b = long(std::floor(p.z)) & 1;
    return double(a ? 3 - b : b);
}

// Equilateral triangles of side 1 in the xz plane, in bands of height √3/2 whose upward
// triangles alternate between half-integer and integer centres; six colours meet at every
// vertex. Layout and values (povray's list form) matched pixel by pixel against povray 3.7.
double evaluate(const pattern::Triangular&, const glm::dvec3& p) {
    const double h = std::sqrt(3.0) / 2;
    const double band = std::floor(p.z / h);
    const double v = p.z / h - band;  // 0 at the band's bottom edge
    const double half_width = (1 - v) / 2;  // of the upward triangle at this height
    const double fl = std::floor(p.x), nearest = std::floor(p.x + 0.5);
    static constexpr int even_up[3] = {0, 4, 2}, even_down[3] = {1, 3, 5};
    static constexpr int odd_up[3] = {4, 2, 0}, odd_down[3] = {5, 1, 3};
    if (std::fmod(std::fabs(band), 2.0) == 0) {
        if (std::fabs(p.x - (fl + 0.5)) < half_width) return even_up[mod3(fl)];
        return even_down[mod3(nearest)];
    }
    if (std::fabs(p.x - nearest) < half_width) return odd_up[mod3(nearest)];
    return odd_down[mod3(fl)];
}

}  // namespace lumen::render

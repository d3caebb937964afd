#include "render/patterns/warps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "noise/noise.hpp"

namespace lumen::render {
namespace {

using Shape = scene::warp::Mapping::Shape;

constexpr double kEpsilon = 1e-10;
constexpr double kTwoPi = 2 * std::numbers::pi;

// The angle of (a, b) around the origin in [0, 1): 0 along +a, a quarter along +b.
double turn(double a, double b) {
    double t = std::atan2(b, a);
    if (t < 0) t += kTwoPi;
    return t / kTwoPi;
}

// The mapping warps build their result about the z axis; `orientation` turns that axis
// (measured: orientation x gives (c, b, -a), y gives (a, -c, b)).
glm::dvec3 orient(const glm::dvec3& o, const glm::dvec3& v) {
    if (o == glm::dvec3(0, 0, 1)) return v;
    const double a = v.x, b = v.y, c = v.z;
    return {o.x * c + o.y * a + o.z * a, o.x * b - o.y * c + o.z * b, -o.x * a + o.y * b + o.z * c};
}

// dist_exp scales the angular coordinates by distance^e; 0 (the default) leaves them.
double spread(const scene::warp::Mapping& w, double dist) {
    return w.dist_exp != 0 ? std::pow(dist, w.dist_exp) : 1.0;
}

// Measured: dist_exp scales the angle around the axis, not the height along it.
glm::dvec3 cylindrical(const scene::warp::Mapping& w, const glm::dvec3& p) {
    const double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0) return p;
    return orient(w.orientation, {turn(p.x, p.z) * spread(w, len), p.y, len});
}

glm::dvec3 spherical(const scene::warp::Mapping& w, const glm::dvec3& p) {
    const double len = glm::length(p);
    if (len == 0) return p;
    const glm::dvec3 n = p / len;
    const double f = spread(w, len);
    return orient(w.orientation,
                  {turn(n.x, n.z) * f, (0.5 + std::asin(n.y) / std::numbers::pi) * f, len});
}

glm::dvec3 toroidal(const scene::warp::Mapping& w, const glm::dvec3& p) {
    const double r = std::sqrt(p.x * p.x + p.z * p.z) - w.major_radius;
    const double len = std::sqrt(r * r + p.y * p.y);
    if (len == 0) return p;  // on the core circle: no direction around the tube
    double phi = std::acos(-r / len);
    if (p.y > 0) phi = kTwoPi - phi;
    const double f = spread(w, len);
    return orient(w.orientation, {turn(p.x, p.z) * f, phi / kTwoPi * f, len});
}

// The six faces of a cube unfolded into a cross in [0,1]², chosen by the dominant axis
// (ties go to the first of +x, +y, +z, -x, -y, -z); the depth is that coordinate's size.
glm::dvec3 cubic(const glm::dvec3& p) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (ax == 0 && ay == 0 && az == 0) return p;
    if (p.x >= 0 && p.x >= ay && p.x >= az) {
        const double m = p.x;
        return {0.75 - (p.z / m + 1) / 8, 1.0 / 3 + (p.y / m + 1) / 6, m};
    }
    if (p.y >= 0 && p.y >= ax && p.y >= az) {
        const double m = p.y;
        return {0.25 + (p.x / m + 1) / 8, 1 - (p.z / m + 1) / 6, m};
    }
    if (p.z >= 0 && p.z >= ax && p.z >= ay) {
        const double m = p.z;
        return {0.25 + (p.x / m + 1) / 8, 1.0 / 3 + (p.y / m + 1) / 6, m};
    }
    if (p.x < 0 && -p.x >= ay && -p.x >= az) {
        const double m = -p.x;
        return {(p.z / m + 1) / 8, 1.0 / 3 + (p.y / m + 1) / 6, m};
    }
    if (p.y < 0 && -p.y >= ax && -p.y >= az) {
        const double m = -p.y;
        return {0.25 + (p.x / m + 1) / 8, (p.z / m + 1) / 6, m};
    }
    const double m = -p.z;
    return {1 - (p.x / m + 1) / 8, 1.0 / 3 + (p.y / m + 1) / 6, m};
}

}  // namespace

// The axis is cut into blocks of the repeat's width; every block shows the first one,
// moved by `offset` per block, and odd blocks mirrored across the flipped axes. POV-Ray
// keeps the block number in single precision, so far blocks land where its blocks land.
glm::dvec3 warp_point(const scene::warp::Repeat& w, const glm::dvec3& point) {
    glm::dvec3 p = point;
    const int a = w.direction.x != 0 ? 0 : w.direction.y != 0 ? 1 : 2;
    const double width = w.direction[a];
    const double block = double(float(std::floor(p[a] / width)));
    p[a] -= block * width;
    if (std::fmod(block, 2.0) != 0) {  // odd (and no int overflow far out)
        for (int i = 0; i < 3; ++i)
            if (w.flip[i] != 0) p[i] = -p[i];
        if (w.flip[a] != 0) p[a] += width;
    }
    return p + block * w.offset;
}

// Points within `radius` of the centre (of their cell's centre, repeated) are pushed away
// from it by up to their distance, strongest near the centre: ((R - L) / R)^falloff ·
// strength, capped at 1; `inverse` pulls them in instead. A repeated hole's turbulence moves
// each cell's centre by a random fraction of it, drawn from the cell's hash.
glm::dvec3 warp_point(const scene::warp::BlackHole& w, const glm::dvec3& p) {
    if (w.type != 0) return p;
    glm::dvec3 centre = w.centre;
    int cell[3] = {0, 0, 0};
    bool repeated = false;
    for (int a = 0; a < 3; ++a) {
        if (w.repeat[a] < kEpsilon) continue;
        const double k = std::floor(p[a] / w.repeat[a]);
        centre[a] += k * w.repeat[a];
        cell[a] = int(std::fmod(k, 4096.0));  // the hash takes it mod 4096 anyway
        repeated = true;
    }
    if (repeated && w.turbulence != glm::dvec3(0)) {
        const int h = noise::hash3d(cell[0], cell[1], cell[2]);
        for (int a = 0; a < 3; ++a) centre[a] += noise::pattern_rand(h + a) * w.turbulence[a];
    }
    const glm::dvec3 d = p - centre;
    const double len = glm::length(d);
    if (len >= w.radius) return p;
    const double f = std::min(std::pow((w.radius - len) / w.radius, w.falloff) * w.strength, 1.0);
    return w.inverse ? p - f * d : p + f * d;
}

glm::dvec3 warp_point(const scene::warp::Mapping& w, const glm::dvec3& p) {
    switch (w.shape) {
        case Shape::Cylindrical: return cylindrical(w, p);
        case Shape::Spherical: return spherical(w, p);
        case Shape::Toroidal: return toroidal(w, p);
        case Shape::Planar: return orient(w.orientation, {p.x, p.y, w.offset});
        case Shape::Cubic: return cubic(p);
    }
    return p;
}

}  // namespace lumen::render

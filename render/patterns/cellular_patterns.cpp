// The cell patterns: cells (one random value per unit cube) and crackle (Worley's cellular
// pattern over one feature point per unit cube). Both draw from POV's PatternRands through the
// lattice hash, so the cells and feature points are the same in every scene.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/patterns/noise_kinds.hpp"

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

// floor(v) as a lattice coordinate; only its value mod 4096 matters, so far-away (and
// non-finite) coordinates just need a defined conversion.
int cell_of(double v) {
    const double f = std::floor(v);
    if (!(std::fabs(f) < 1e18)) return 0;
    return int(std::int64_t(f) & 4095);
}

// The cube offsets crackle searches: every neighbour within 1, and those 2 away along one
// axis only (81 in all), x outermost.
struct CubeOffsets {
    int d[81][3];
    constexpr CubeOffsets() : d{} {
        int n = 0;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((x == 2 || x == -2) + (y == 2 || y == -2) + (z == 2 || z == -2) <= 1) {
                        d[n][0] = x, d[n][1] = y, d[n][2] = z;
                        ++n;
                    }
    }
};
constexpr CubeOffsets kCubeOffsets;

glm::dvec3 feature_point(int a, int b, int c) {
    const int q = noise::hash3d(a, b, c);
    return {a + noise::pattern_rand(q), b + noise::pattern_rand(q + 1),
            c + noise::pattern_rand(q + 2)};
}

double distance(const glm::dvec3& p, const glm::dvec3& f, double metric) {
    const double dx = f.x - p.x, dy = f.y - p.y, dz = f.z - p.z;
    if (metric == 2) return dx * dx + dy * dy + dz * dz;
    if (metric == 1) return std::fabs(dx) + std::fabs(dy) + std::fabs(dz);
    return std::pow(std::fabs(dx), metric) + std::pow(std::fabs(dy), metric) +
           std::pow(std::fabs(dz), metric);
}

// Distance back from the metric's own measure (squared for 2, none for 1).
double unmeasured(double d, double metric) {
    if (metric == 2) return std::sqrt(d);
    if (metric == 1) return d;
    return std::pow(d, 1 / metric);
}

}  // namespace

double evaluate(const pattern::Cells&, const glm::dvec3& p, const scene::Pattern&) {
    const int h = noise::hash3d(cell_of(p.x + kEpsilon), cell_of(p.y + kEpsilon),
                                cell_of(p.z + kEpsilon));
    return std::min(noise::pattern_rand(h), 1.0);
}

double evaluate(const pattern::Crackle& k, const glm::dvec3& p, const scene::Pattern& pat) {
    const double fx = std::floor(p.x - kEpsilon), fy = std::floor(p.y - kEpsilon),
                 fz = std::floor(p.z - kEpsilon);
    if (!(std::fabs(fx) < 1e9 && std::fabs(fy) < 1e9 && std::fabs(fz) < 1e9)) return 0;
    const int hx = int(fx), hy = int(fy), hz = int(fz);
    // The three nearest feature points: the first three sorted, the rest inserted in order.
    double d[3];
    glm::dvec3 nearest;
    glm::dvec3 first[3];
    for (int i = 0; i < 3; ++i) {
        first[i] = feature_point(hx + kCubeOffsets.d[i][0], hy + kCubeOffsets.d[i][1],
                                 hz + kCubeOffsets.d[i][2]);
        d[i] = distance(p, first[i], k.metric);
    }
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int a, int b) { return d[a] < d[b]; });
    const double sorted[3] = {d[order[0]], d[order[1]], d[order[2]]};
    d[0] = sorted[0], d[1] = sorted[1], d[2] = sorted[2];
    nearest = first[order[0]];
    for (int i = 3; i < 81; ++i) {
        const glm::dvec3 f = feature_point(hx + kCubeOffsets.d[i][0], hy + kCubeOffsets.d[i][1],
                                           hz + kCubeOffsets.d[i][2]);
        const double di = distance(p, f, k.metric);
        if (di < d[0]) {
            d[2] = d[1], d[1] = d[0], d[0] = di;
            nearest = f;
        } else if (di < d[1]) {
            d[2] = d[1], d[1] = di;
        } else if (di < d[2]) {
            d[2] = di;
        }
    }
    if (k.solid) return std::clamp(noise::noise(nearest, generator_of(pat)), 0.0, 1.0);
    if (k.offset != 0) {
        const double o = k.metric == 2 ? k.offset * k.offset
                         : k.metric == 1 ? k.offset
                                         : std::pow(k.offset, k.metric);
        for (double& di : d) di += o;
    }
    const double v = k.form.x * unmeasured(d[0], k.metric) + k.form.y * unmeasured(d[1], k.metric) +
                     k.form.z * unmeasured(d[2], k.metric);
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace lumen::render

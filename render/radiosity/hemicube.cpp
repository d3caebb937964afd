// Hemicube by ray casting through pixel centres (the same coverage test a z-buffer makes).
#include "render/radiosity/hemicube.hpp"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "render/radiosity/ray_cast.hpp"

namespace lumen::render::radiosity {

std::vector<double> hemicube_point(const glm::dvec3& x, const glm::dvec3& n,
                                   const std::vector<Patch>& patches,
                                   const HemicubeOptions& options) {
    std::vector<double> row(patches.size(), 0.0);
    const int res = std::max(2, options.resolution - options.resolution % 2);
    glm::dvec3 t0, b0;
    tangent_frame(n, t0, b0);
    const double c = std::cos(options.rotation), s = std::sin(options.rotation);
    const glm::dvec3 t = c * t0 + s * b0, b = -s * t0 + c * b0;
    const double pixel = 2.0 / res, dA = pixel * pixel;
    // Adds the delta form factor `df` to the nearest patch along the local direction d.
    auto shade = [&](const glm::dvec3& d, double df) {
        const glm::dvec3 dir = d.x * t + d.y * b + d.z * n;
        double best = INFINITY;
        size_t hit = patches.size();
        for (size_t j = 0; j < patches.size(); ++j) {
            if (int(j) == options.skip) continue;
            const double dist = intersect(patches[j], x, dir);
            if (dist > 0 && dist < best) best = dist, hit = j;
        }
        // Seen from behind, the nearest patch occludes but receives nothing.
        if (hit < patches.size() && glm::dot(patches[hit].normal, dir) < 0) row[hit] += df;
    };
    const double pi = std::numbers::pi;
    for (int i = 0; i < res; ++i)
        for (int j = 0; j < res; ++j) {  // top face z = 1
            const double u = -1 + (i + 0.5) * pixel, v = -1 + (j + 0.5) * pixel;
            const double q = u * u + v * v + 1;
            shade({u, v, 1}, dA / (pi * q * q));
        }
    for (int side = 0; side < 4; ++side)
        for (int i = 0; i < res; ++i)
            for (int k = 0; k < res / 2; ++k) {  // side faces at ±1 along t or b, z in (0, 1)
                const double u = -1 + (i + 0.5) * pixel, z = (k + 0.5) * pixel;
                const double q = u * u + z * z + 1;
                const double sign = side % 2 ? -1.0 : 1.0;
                const glm::dvec3 d = side < 2 ? glm::dvec3(sign, u, z) : glm::dvec3(u, sign, z);
                shade(d, dA * z / (pi * q * q));
            }
    return row;
}

std::vector<double> hemicube_row(const std::vector<Patch>& patches, size_t i, int resolution,
                                 double rotation) {
    return hemicube_point(patches[i].centroid, patches[i].normal, patches,
                          {resolution, rotation, int(i)});
}

}  // namespace lumen::render::radiosity

// Irradiance gradients of a stratified gather (Ward and Heckbert 1992, "Irradiance
// Gradients"): from the radiance and hit distance of each stratum of a cosine-weighted
// hemisphere (M strata in sin^2 theta by N in phi), how the gathered G changes as the point
// moves (translation) and as its normal turns (rotation). A cache record extrapolates with
// them, so records can lie further apart for the same error.
#pragma once
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace lumen::render::radiosity {

struct GatherStrata {
    int m = 0, n = 0;               // strata in sin^2 theta (index i) and in phi (index j)
    std::vector<glm::dvec3> L;      // radiance of stratum (i, j) at i * n + j
    std::vector<double> R;          // its hit distance (infinite for a miss)
};

struct IrradianceGradients {
    // Column c: the gradient of channel c of G (translation: per unit of distance; rotation:
    // G(n') ~ G + (n x n') . rotation[c]).
    glm::dmat3 translation{0.0}, rotation{0.0};
};

// The gradients in world space, for the gather about `normal` with tangents t, b (the frame
// its directions were drawn in: d = sin(theta) (cos(phi) t + sin(phi) b) + cos(theta) normal).
IrradianceGradients irradiance_gradients(const GatherStrata& s, const glm::dvec3& t,
                                         const glm::dvec3& b);

}  // namespace lumen::render::radiosity

// The hemicube (Cohen & Greenberg 1985), kept as the lecture's comparison baseline: a half
// cube over a point, each pixel sees the nearest patch through its centre and adds its
// precomputed delta form factor. All-or-nothing pixels alias.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "render/radiosity/patch.hpp"

namespace lumen::render::radiosity {

struct HemicubeOptions {
    int resolution = 64;    // top face resolution x resolution; side faces resolution x res/2
    double rotation = 0;    // radians about the normal (a random one per patch breaks aliasing)
    int skip = -1;          // patch index ignored (the patch the hemicube sits on)
};

// Form factors from the point x (unit normal n) to every patch, with occlusion among them.
std::vector<double> hemicube_point(const glm::dvec3& x, const glm::dvec3& n,
                                   const std::vector<Patch>& patches,
                                   const HemicubeOptions& options = {});

// Row F_i* from a hemicube at the centroid of patch i.
std::vector<double> hemicube_row(const std::vector<Patch>& patches, size_t i,
                                 int resolution = 64, double rotation = 0);

}  // namespace lumen::render::radiosity

// Participating media (POV-Ray 3.7's `media { }`): in an interior, or at scene level as the
// atmosphere. The renderer integrates them along every ray segment (render/media.hpp).
#pragma once
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/texture.hpp"

namespace lumen::scene {

struct Media {
    // The defaults of #version 3.5 on; before it method 1, intervals 10, samples 1,1.
    int method = 3;  // 1 random, 2 stratified, 3 adaptive
    int intervals = 1;
    int samples_min = 10, samples_max = 10;
    double confidence = 0.9, variance = 1.0 / 128, ratio = 0.9, jitter = 0;
    int aa_level = 3;
    double aa_threshold = 0.1;
    glm::dvec3 absorption{0}, emission{0}, scattering{0};
    int scattering_type = 1;  // 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein
    double eccentricity = 0;  // Henyey-Greenstein's g
    double extinction = 1;    // scattering's share of the extinction
    // The density at a point is the product of these pigments' colours (none: 1); the last
    // written is first, as POV-Ray keeps them.
    std::vector<PigmentPtr> densities;
    bool collect = true;  // photons
    SourceLoc loc;

    bool constant() const { return densities.empty(); }
};
using MediaPtr = std::shared_ptr<const Media>;

}  // namespace lumen::scene

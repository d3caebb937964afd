// Fog along a ray segment: what it lets through and the colour it adds. Camera, reflected and
// refracted rays get both; shadow rays of a light with `media_attenuation on` get the
// attenuation only, with the same transmit floor and filter tint (POV-Ray 3.7 renders match
// this for constant and ground fog).
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "noise/noise.hpp"
#include "render/ray.hpp"
#include "scene/scene.hpp"

namespace lumen::render {

struct FogEffect {
    glm::dvec3 attenuation{1};  // multiplies what lies behind the fog
    glm::dvec3 added{0};        // the fogs' own colours, added
    double transmit = 1;        // multiplies the alpha channel's transmit
};

// Every fog of the scene over the segment [0, depth] of `ray`; fog turbulence uses the scene's
// noise generator.
FogEffect fog_along(const std::vector<scene::Fog>& fogs, const Ray& ray, double depth,
                    noise::Generator generator);

}  // namespace lumen::render

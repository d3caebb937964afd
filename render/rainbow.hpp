// rainbow { } laid over what a ray sees, as POV-Ray 3.7 does it (probed with 16-bit linear
// renders): the band between angle ± width/2 around the rainbow's direction takes the colour
// map across it, and covers the scene like a fog of the rainbow's distance whose transmit is
// the colour's. Applied to camera, reflected and refracted rays after shading, before the
// atmosphere and fog.
#pragma once
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace lumen::render {

// How strongly a partial arc covers the band along unit `dir`: 1 within falloff_angle/2 of
// `up`'s azimuth around the unit `axis`, fading smoothly to 0 at arc_angle/2, 0 beyond.
double arc_strength(const scene::Rainbow::Arc& arc, const glm::dvec3& axis, const glm::dvec3& up,
                    const glm::dvec3& dir);

// `behind` seen through rainbow `r` along unit direction `dir` over `depth` (2e10 for the
// sky); `u` in [0, 1) places the jitter. False where the ray misses the band; else `seen` is
// the colour and `transmit` the part of what lies behind that shows through.
bool through_rainbow(const scene::Rainbow& r, const glm::dvec3& dir, double depth,
                     const glm::dvec3& behind, double u, glm::dvec3& seen, double& transmit);

// Every rainbow of the scene over `behind`; `u` draws the jitters. Multiplies `transmit` (the
// alpha channel's) by what shows through.
glm::dvec3 through_rainbows(const std::vector<scene::Rainbow>& rainbows, const glm::dvec3& dir,
                            double depth, const glm::dvec3& behind, const std::function<double()>& u,
                            double& transmit);

}  // namespace lumen::render

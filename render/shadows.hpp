// Shadow rays through transparent surfaces and interior fade, as POV-Ray 3.7 traces them.
#pragma once
#include <glm/vec3.hpp>

#include "render/interior_list.hpp"
#include "render/intersector.hpp"
#include "render/trace_state.hpp"

namespace lumen::render {

// Attenuation of light travelling `depth` inside `interior`. Eye rays apply it whenever a
// fade_distance is set; shadow rays only when fade_power > 0 as well.
glm::dvec3 interior_fade(const scene::Interior& interior, double depth, bool shadow_ray);

// True when light crossing this interior on a shadow ray keeps its colour: no fade that
// shadow rays apply and no fake caustics (null = the default interior).
bool clear_for_shadows(const scene::Interior* interior);

// The filter (per rgb channel, 1 = unshadowed) applied to light reaching `point` along unit
// direction `dir` from a light `distance` away. The ray starts with a copy of the eye ray's
// interior list and toggles it at every transparent surface, so a transparent solid filters
// once when entered and once when left. With `solid_length`, every object is walked (none
// skipped as clear) and it receives how much of the way lies inside solid (non-hollow)
// objects, where there is no fog. With `refracted` (the light's photon flags, where a photon
// map lights the point), a photon target that refracts the light's photons blocks it all:
// its caustic takes the place of the light it lets through (POV-Ray). `occluder`: the light's
// cache of the object that last blocked its shadow rays (Intersector::occluded).
glm::dvec3 shadow_filter(const Intersector& geometry, const glm::dvec3& point,
                         const glm::dvec3& dir, double distance, const InteriorList& interiors,
                         TraceCounters& counters, double* solid_length = nullptr,
                         const scene::LightPhotons* refracted = nullptr,
                         Occluder* occluder = nullptr);

}  // namespace lumen::render

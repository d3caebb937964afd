// Participating media along a ray segment, as POV-Ray 3.7 integrates them: the segment cut
// into intervals (more where lights reach it), each sampled by method 3 (adaptive: sub-steps
// refined where the emission changes), 2 (stratified) or 1 (random); absorption, emission and
// scattering summed over the media, densities multiplied, light scattered towards the eye by
// each media's phase function from every light that reaches the sample unshadowed.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "render/interior_list.hpp"
#include "render/ray.hpp"
#include "render/shading.hpp"
#include "render/trace_state.hpp"
#include "scene/media.hpp"

namespace lumen::render {

struct MediaEffect {
    glm::dvec3 added{0};          // light emitted and scattered towards the ray's origin
    glm::dvec3 transmittance{1};  // what is left of the light from behind the segment
};

// Rays that escape cross media over this depth (POV-Ray's BOUND_HUGE): any absorption blacks
// out the sky, any emission saturates it.
inline constexpr double kMediaEscapeDepth = 2e10;

// The media's effect on the segment from ray.origin to `depth` along ray.dir. `lit`: the
// lights scatter into it (eye and secondary rays); shadow rays only lose light. `interiors`:
// the interiors the segment lies in, for the shadow rays of the scattered light.
MediaEffect integrate_media(const std::vector<const scene::Media*>& media, const Ray& ray,
                            double depth, bool lit, const LightingEnv& env,
                            const InteriorList& interiors, ThreadState& state);

// The media of the interiors a ray is in, in list order (POV-Ray's segment list), into `out`.
void media_in(const InteriorList& interiors, std::vector<const scene::Media*>& out);

// Whether the atmosphere dims this light on its way to a point (`media_attenuation on`).
bool atmosphere_dims(const LightSource& light, const LightingEnv& env);

// What is left of light crossing the media over the segment (shadow rays: extinction only,
// without jitter). `lead`, where given, is the media the segment takes its sampling from in
// place of lead_media's choice: a shadow ray leaving a container samples the stretch as that
// container's first media says, whatever else it is in (render/shadows.cpp).
glm::dvec3 media_transmittance(const std::vector<const scene::Media*>& media, const Ray& ray,
                               double depth, const scene::Media* lead = nullptr);

// POV-Ray's phase functions (no 1/4 pi): the share of light arriving along `to_light` that
// scatters along `view`, alpha = to_light . view.
double phase(const scene::Media& m, double alpha);
// The phase of several media in one segment: their mean (POV-Ray).
double mean_phase(const std::vector<const scene::Media*>& media, double alpha);

// The media a segment of several takes its sampling from: the first with the most intervals.
const scene::Media& lead_media(const std::vector<const scene::Media*>& media);

}  // namespace lumen::render

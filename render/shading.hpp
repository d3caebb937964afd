// The finish model (POV-Ray 3.7's rules): ambient, emission, diffuse, brilliance,
// phong, specular, metallic, and the reflectivity of a surface.
#pragma once
#include <vector>

#include <glm/vec3.hpp>

#include "noise/noise.hpp"
#include "render/interior_list.hpp"
#include "render/intersector.hpp"
#include "render/lights.hpp"
#include "render/photons/photon_map.hpp"
#include "render/trace_state.hpp"
#include "scene/scene.hpp"
#include "scene/texture.hpp"

namespace lumen::render {

// Everything the lights need to know about one texture layer at a hit point.
struct SurfaceSample {
    glm::dvec3 point{0};
    glm::dvec3 view{0, 0, 1};    // unit direction of the incoming ray
    glm::dvec3 normal{0, 1, 0};  // shading normal, facing the incoming ray
    glm::dvec3 raw_normal{0, 1, 0};  // the surface's own normal, facing the incoming ray
    const scene::Object* object = nullptr;  // the primitive shaded (its own shadow, see .cpp)
    glm::dvec3 colour{0};        // pigment rgb
    double opacity = 1;          // 1 − f − t (or the legacy formula)
    const scene::Finish* finish = nullptr;
    bool double_illuminate = false;
    double film_thickness = 0;   // irid: the film's thickness here (irid_thickness)
    bool collects_photons = true;  // the object's photons { collect }
    uint32_t light_group = 0;   // Hit::light_group and global_lights
    bool global_lights = true;
};

// Scene-wide lighting state shared by all threads (read-only while rendering).
struct LightingEnv {
    const std::vector<LightSource>* lights = nullptr;
    const Intersector* geometry = nullptr;
    glm::dvec3 ambient_light{1};
    glm::dvec3 irid_wavelength{0.70, 0.52, 0.48};  // global_settings irid_wavelength
    const std::vector<scene::Fog>* fogs = nullptr;  // dims lights with media_attenuation
    const std::vector<const scene::Media*>* atmosphere = nullptr;  // likewise
    // global_settings noise_generator: fog and irid turbulence.
    noise::Generator noise_generator = noise::Generator::RangeCorrected;
    bool ambient_off = false;  // radiosity with #version >= 3.7 drops ambient
    int quality = 9;
    // Set when a surface photon map exists: refracting photon targets then shadow black.
    bool photon_map = false;
    // Media photons (null: none), gathered at every sample of lit media.
    const PhotonMap* media_photons = nullptr;
    GatherSettings media_gather;
};

// POV's metallic factor per channel: 1 + m·(1 − Fm)·(rgb − 1), with the Fresnel-like Fm of the
// angle whose cosine is `cos_angle`.
glm::dvec3 metallic_factor(double metallic, double cos_angle, const glm::dvec3& rgb);

// Thin-film interference (finish irid, POV's film model): the factor by which a light's colour
// is multiplied before diffuse and highlights, 1 + amount·cos(2π·thickness·(|cosL| + |cosV|)/λ)
// per channel, where cosL and cosV are the cosines of the light and view directions with
// the normal and λ the channel's irid_wavelength.
glm::dvec3 irid_factor(const scene::Finish& finish, double thickness,
                       const glm::dvec3& wavelength, double cos_light, double cos_view);
// The film's thickness at world point p: irid turbulence t varies it by POV's turbulence T
// (5 octaves, omega 0.5, lambda 2) to thickness·(1 + t·(2T − 1)).
double irid_thickness(const scene::Finish& finish, const glm::dvec3& p,
                      noise::Generator generator);

// Ambient + emission + every light's diffuse and highlights (with shadows).
glm::dvec3 local_light(const SurfaceSample& s, const LightingEnv& env,
                       const InteriorList& interiors, ThreadState& state);

// The light a layer receives from the photons gathered at its point (POV-Ray's estimate: each
// photon shaded as a light from where it came, its colour over the disc πr², and divided by
// the cosine with the surface's own normal, kept within [0.1, 1]).
glm::dvec3 photon_light(const SurfaceSample& s, const GatheredPhotons& photons);

// Reflectivity of a layer: per-channel colour Rf and the factor by which the ray
// weight is multiplied. `relative_ior` (n2/n1) is only used by fresnel.
struct Reflectivity {
    glm::dvec3 colour{0};
    double weight = 0;
    bool any() const { return colour.x != 0 || colour.y != 0 || colour.z != 0; }
};
Reflectivity reflectivity(const scene::Finish& finish, double cos_incidence, double relative_ior,
                          const glm::dvec3& pigment);

// Mirror direction of `dir` about the shading normal, kept above the raw surface.
glm::dvec3 reflect_direction(const glm::dvec3& dir, const glm::dvec3& shading_normal,
                             const glm::dvec3& raw_normal);

}  // namespace lumen::render

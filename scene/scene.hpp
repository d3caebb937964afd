// The evaluated scene: what the interpreter hands to the renderer. Plain data only.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/media.hpp"
#include "scene/object.hpp"
#include "scene/photons.hpp"

namespace lumen::scene {

struct RadiositySettings {
    int count = 35, count_pool = 1600;
    double error_bound = 1.8;
    int recursion_limit = 2;
    int nearest_count = 5;
    double pretrace_start = 0.08, pretrace_end = 0.04;
    double low_error_factor = 0.5, gray_threshold = 0.0;
    double minimum_reuse = 0.015, maximum_reuse = 0.2;
    double brightness = 1.0, adc_bailout = 0.01;
    bool always_sample = false, normal = false, media = false;
    double max_sample = -1;
    SourceLoc loc;
};

struct GlobalSettings {
    std::optional<double> assumed_gamma;
    int max_trace_level = 5;
    double adc_bailout = 1.0 / 255.0;
    glm::dvec3 ambient_light{1, 1, 1};
    glm::dvec3 irid_wavelength{0.70, 0.52, 0.48};
    int noise_generator = 2;
    int number_of_waves = 10;
    std::optional<RadiositySettings> radiosity;
    std::optional<PhotonSettings> photons;  // a photons { } block: the photon pass runs
    std::vector<Unsupported> unsupported;  // photons, subsurface, ...
};

struct SkySphere {
    std::vector<PigmentPtr> pigments;  // bottom first; the last is the top layer
    Transform transform;
    double emission = 1.0;
    SourceLoc loc;
};

struct Fog {
    int type = 1;                      // 1 constant, 2 ground fog
    double distance = 0;
    Colour colour;
    TurbulenceParams turbulence;       // amount 0 = none
    double turb_depth = 0.5;
    double offset = 0, alt = 0;
    glm::dvec3 up{0, 1, 0};
    Transform transform;
    std::optional<Unsupported> unsupported;
    SourceLoc loc;
};

// rainbow { }: a fog-like ring of colour around `direction` (the way the light travels).
// Between rainbow angles angle ± width/2 the colour map is looked up at the position across the
// band, and the colour is laid over the ray's like a fog of this distance (POV-Ray 3.7, probed).
struct Rainbow {
    glm::dvec3 direction{0, 0, 1};
    double angle = 0, width = 0;  // degrees
    // POV-Ray's default leaves objects within millions of units untouched and the sky covered
    // (probed: between 5e6 and 1e9).
    double distance = 1e8;
    double jitter = 0;  // the band position moves by up to ± jitter
    glm::dvec3 up{0, 1, 0};
    ColourMap colour_map;
    // A partial arc, where arc_angle is given: the band spans the azimuths (around the
    // direction) within arc_angle/2 of `up`'s, at full strength within falloff_angle/2 (which
    // defaults to arc_angle), fading out to the arc's ends beyond. Degrees, 0 to 360.
    struct Arc {
        double arc_angle = 360, falloff_angle = 360;
    };
    std::optional<Arc> arc;
    SourceLoc loc;
};

struct Scene {
    double language_version = 3.62;    // #version in effect at the end of parsing
    bool version_given = false;        // a #version directive (or Version=) was seen
    Camera camera;
    std::vector<Light> lights;
    uint32_t light_groups = 0;  // light_group blocks placed: Light::group runs 1..this
    std::vector<ObjectPtr> objects;
    GlobalSettings globals;
    Colour background{0, 0, 0, 0, 0};
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;
    std::vector<std::shared_ptr<const Media>> atmosphere;  // scene-level media, in order
    // Every unsupported feature that reached the scene, in source order (lumen --check).
    std::vector<Unsupported> unsupported;
};

}  // namespace lumen::scene

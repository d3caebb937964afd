// Photon mapping settings (POV-Ray 3.7): the global photons { } block, an object's and a
// light's photons { } blocks. Plain data; the renderer's photon pass reads them.
#pragma once
#include <string>

#include "base/source.hpp"

namespace lumen::scene {

// refraction / reflection in an object's or a light's block: not given, on or off. An "on"
// on one side and an "off" on the other cancel (render/photons/photon_flags.hpp).
enum class PhotonToggle : unsigned char { Unset, On, Off };

struct PhotonSettings {
    double spacing = 1.0;
    int count = 0;  // > 0: spacing estimated from it
    int gather_min = 20, gather_max = 100;
    int media_steps = 0;  // media photons per segment (0: none)
    double media_factor = 1.0;
    double jitter = 0.4;
    int max_trace_level = -1;    // -1: the scene's
    double adc_bailout = -1;     // < 0: the scene's
    double autostop = 0.5;
    double expand_percent = 0.2;
    int expand_min = 35;
    // Gather radius and its multiplier for surfaces, then media; radius <= 0: automatic.
    double radius = 0, radius_mult = 1, media_radius = 0, media_radius_mult = 1;
    std::string save_file, load_file;  // render/photons/photon_file.hpp
    SourceLoc loc, file_loc, media_loc;  // the block; save_file or load_file; media
};

struct ObjectPhotons {
    bool target = false;
    double target_mult = 1.0;  // spacing multiplier of a target
    PhotonToggle refraction = PhotonToggle::Unset, reflection = PhotonToggle::Unset;
    bool collect = true;
    bool pass_through = false;
};

struct LightPhotons {
    PhotonToggle refraction = PhotonToggle::Unset, reflection = PhotonToggle::Unset;
    bool area_light = false;
};

}  // namespace lumen::scene

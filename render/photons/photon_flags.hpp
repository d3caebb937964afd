// POV-Ray's rules for the photon flags of objects and lights.
#pragma once
#include "scene/photons.hpp"

namespace lumen::render {

// Whether photons are refracted (or reflected) where the object says `object` and the light
// `light`: one of them on and neither off (an "on" and an "off" cancel).
inline bool photon_follows(scene::PhotonToggle object, scene::PhotonToggle light) {
    using T = scene::PhotonToggle;
    return (object == T::On || light == T::On) && object != T::Off && light != T::Off;
}

// Whether an object (its photons block after CSG inheritance, null: none) collects photons.
inline bool collects_photons(const scene::ObjectPhotons* p) { return !p || p->collect; }

// A photon target that refracts this light's photons: with a photon map, its shadow on a
// collecting surface is black (the caustic takes the place of the filtered light).
inline bool refracts_for(const scene::ObjectPhotons* p, const scene::LightPhotons& light) {
    return p && p->target && photon_follows(p->refraction, light.refraction);
}

}  // namespace lumen::render

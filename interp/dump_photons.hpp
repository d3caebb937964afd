// photons { } blocks as JSON, for the scene dump (interp/dump_scene.cpp).
#pragma once
#include "interp/dump_json.hpp"
#include "scene/photons.hpp"

namespace lumen::interp::dump {

Json object_photons(const scene::ObjectPhotons& p);
Json global_photons(const scene::PhotonSettings& p);
Json light_photons(const scene::LightPhotons& p);

}  // namespace lumen::interp::dump

// Deterministic JSON dump of an evaluated scene, for golden tests (tests/sdl/*.json) and
// `lumen --dump`. Only values that differ from the scene structs' defaults are printed.
#pragma once
#include <string>

#include "scene/scene.hpp"

namespace lumen::interp {

// Pretty-printed (2-space indent), keys in a fixed order, numbers as %.10g with -0 printed
// as 0. Objects, lights and the camera carry "loc": "file:line:col" (file name without
// directories); unsupported features are listed as "feature (file:line:col)".
std::string dump_scene_json(const scene::Scene& scene);

}  // namespace lumen::interp

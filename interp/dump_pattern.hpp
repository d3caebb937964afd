// Patterns and colour maps as JSON, for the scene dump (interp/dump_scene.cpp).
#pragma once
#include "interp/dump_json.hpp"
#include "scene/pattern.hpp"

namespace lumen::interp::dump {

Json pattern(const scene::Pattern& p);
Json colour_map(const scene::ColourMap& m);

}  // namespace lumen::interp::dump

// fog and rainbow as JSON, for the scene dump (interp/dump_scene.cpp).
#pragma once
#include "interp/dump_json.hpp"
#include "scene/scene.hpp"

namespace lumen::interp::dump {

Json fog(const scene::Fog& f);
Json rainbow(const scene::Rainbow& r);

}  // namespace lumen::interp::dump

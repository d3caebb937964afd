// The warps of a pattern's steps other than turbulence (scene/pattern_steps.hpp): each maps a
// point on its way from world space into pattern space. render/pattern.cpp applies them in the
// steps' order; the formulas were matched against povray 3.7 renders (tests/patterns/warp_*).
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern_steps.hpp"

namespace lumen::render {

glm::dvec3 warp_point(const scene::warp::Repeat& w, const glm::dvec3& p);
glm::dvec3 warp_point(const scene::warp::BlackHole& w, const glm::dvec3& p);
glm::dvec3 warp_point(const scene::warp::Mapping& w, const glm::dvec3& p);

}  // namespace lumen::render

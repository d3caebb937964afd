// pavement: unit cells grouped into tiles (scene/pavement_layouts.hpp); 0 inside a tile,
// rising to 1 at its walls, shaped near corners by exterior, interior and form.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

double evaluate(const scene::pattern::Pavement& k, const glm::dvec3& p);

}  // namespace lumen::render

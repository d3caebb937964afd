// Patterns whose value comes from another scene element: function (a compiled function),
// pigment_pattern (a pigment's grey),
// density_file (a df3 voxel grid), object (inside an object or not), and average, whose entries the owning pigment or texture
// evaluates itself.
#pragma once
#include <glm/vec3.hpp>

#include "scene/pattern.hpp"

namespace lumen::render {

// Never asked for a value: render/pigment.cpp and the texture code weigh the map's entries.
double evaluate(const scene::pattern::Average&, const glm::dvec3& p);
double evaluate(const scene::pattern::PigmentPattern& k, const glm::dvec3& p);
double evaluate(const scene::pattern::DensityFile& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Object& k, const glm::dvec3& p);
double evaluate(const scene::pattern::Function& k, const glm::dvec3& p,
                const scene::Pattern& pattern);

}  // namespace lumen::render

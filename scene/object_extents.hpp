// min_extent / max_extent: the bounding box POV-Ray 3.7 stores for an object when it is
// parsed, with its rules (loose boxes for tilted cylinders, a transformed box's corners,
// CSG and clipped_by boxes) and its single-precision storage.
#pragma once
#include <glm/vec3.hpp>

#include "scene/object.hpp"

namespace lumen::scene {

struct Extents {
    glm::dvec3 min, max;
};

// Throws LumenError for a shape lumen does not model (the object's unsupported feature).
Extents object_extents(const scene::Object& object);

}  // namespace lumen::scene

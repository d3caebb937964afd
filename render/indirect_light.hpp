// The tracer's hook for indirect diffuse light (radiosity): where POV would add ambient, the
// tracer adds diffuse × pigment × incident(hit). Implemented in render/radiosity.
#pragma once
#include <glm/vec3.hpp>

#include "render/hit.hpp"
#include "render/trace_state.hpp"

namespace lumen::render {

class IndirectLight {
public:
    virtual ~IndirectLight() = default;
    // Incident indirect light at the hit on the side that `normal` (unit, facing the
    // incoming ray) points to, with brightness and gray_threshold applied. Called from every
    // render thread at once.
    virtual glm::dvec3 incident(const Hit& hit, const glm::dvec3& normal,
                                ThreadState& state) const = 0;
};

}  // namespace lumen::render

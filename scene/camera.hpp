// The camera after POV's fix-ups (angle, look_at, orthographic scaling, transforms), so the
// renderer only maps pixels to rays (POV-Ray 3.7's rules).
#pragma once
#include <optional>
#include <glm/vec3.hpp>

#include "scene/unsupported.hpp"

namespace lumen::scene {

enum class CameraType { Perspective, Orthographic, Other };

struct Camera {
    CameraType type = CameraType::Perspective;
    glm::dvec3 location{0, 0, 0};
    glm::dvec3 direction{0, 0, 1};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 right{1.33, 0, 0};
    std::optional<Unsupported> unsupported;  // e.g. fisheye, focal blur
    SourceLoc loc;
};

}  // namespace lumen::scene

// Light sources (POV-Ray 3.7's rules). Positions are in world space (transforms applied).
#pragma once
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/object.hpp"

namespace lumen::scene {

enum class LightType { Point, Spot, Cylinder };

struct AreaLight {
    glm::dvec3 axis1{0}, axis2{0};
    int size1 = 1, size2 = 1;
    int adaptive = 100;
    bool jitter = false, circular = false, orient = false;
};

struct Light {
    glm::dvec3 position{0};
    glm::dvec3 colour{1, 1, 1};
    LightType type = LightType::Point;
    bool parallel = false;
    glm::dvec3 point_at{0, 0, 1};
    double radius = 30, falloff = 45, tightness = 0;  // degrees (spot); cylinder: units
    bool shadowless = false;
    double fade_distance = 0, fade_power = 0;
    std::optional<AreaLight> area;
    bool area_illumination = false;
    bool media_interaction = true, media_attenuation = false;
    ObjectPtr looks_like;          // already translated to the light, flagged no_shadow
    ObjectPtr projected_through;
    LightPhotons photons;
    // The light_group it belongs to (Csg::light_group): it lights that group's members only.
    // 0: a light of the whole scene.
    uint32_t group = 0;
    std::vector<Unsupported> unsupported;
    SourceLoc loc;
};

}  // namespace lumen::scene

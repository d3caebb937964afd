// Light sources prepared once per render (POV-Ray 3.7's rules): direction, distance and
// attenuation (spotlight cone, cylinder, fade) at a surface point, and area-light grids.
#pragma once
#include <optional>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "render/geometry.hpp"
#include "scene/light.hpp"

namespace lumen::render {

struct LightSource {
    const scene::Light* light = nullptr;
    glm::dvec3 position{0}, colour{1};
    glm::dvec3 axis{0, 0, 1};  // norm(point_at − position): spot/cylinder/parallel
    bool spot = false, cylinder = false, parallel = false, shadowless = false;
    double cos_radius = 1, cos_falloff = 1, tightness = 0;
    double radius = 0, falloff = 0;  // cylinder lights: in units
    double fade_distance = 0, fade_power = 0;
    // Area light: n1 × n2 grid around `position` (axis1 along u, axis2 along v).
    bool area = false, jitter = false, circular = false, orient = false;
    int n1 = 1, n2 = 1, adaptive = 100;
    glm::dvec3 axis1{0}, axis2{0};
    // projected_through: light only passes along rays that cross this object (null = none).
    std::shared_ptr<const Geometry> projection;
    uint32_t group = 0;  // scene::Light::group: 0 lights everything (within LightScope)
};

// Whether `light` lights a surface in light_group `group` (0: none) that the scene's lights
// reach where `global_lights` (POV-Ray 3.7, probed: a group's lights light only its members,
// not those of a light_group inside it; the scene's lights light a group's members only with
// `global_lights on`, off by default).
inline bool lights_surface(const LightSource& light, uint32_t group, bool global_lights) {
    return light.group == 0 ? group == 0 || global_lights : light.group == group;
}

// Direction and distance to the light and its attenuated colour at one surface point.
struct LightSample {
    glm::dvec3 dir{0};     // unit, from the point towards the light
    double distance = 0;   // shadow ray length
    glm::dvec3 colour{0};  // light colour after cone/cylinder and fade attenuation
};

std::vector<LightSource> prepare_lights(const std::vector<scene::Light>& lights);

// The spotlight cone's or the cylinder's attenuation towards `point` (1 for other lights).
double beam_factor(const LightSource& light, const glm::dvec3& point);
// fade_distance / fade_power attenuation `distance` from the light (1 without fade_power).
double light_fade(const LightSource& light, double distance);

// Returns false when the point gets no light at all (outside a cone).
bool illuminate(const LightSource& light, const glm::dvec3& point, LightSample& out);

// How far from `point` along unit `dir` (towards the light, `distance` away) shadows are
// tested: all the way without a projected_through object; with one, nothing (no light) where
// the segment misses it, else up to its nearest crossing. POV-Ray tests no further (measured:
// an object between the projected one and the light, or the projected object itself placed in
// the scene, casts no shadow).
std::optional<double> projected_reach(const LightSource& light, const glm::dvec3& point,
                                      const glm::dvec3& dir, double distance);
inline std::optional<double> projection_reach(const LightSource& light, const glm::dvec3& point,
                                              const glm::dvec3& dir, double distance) {
    if (!light.projection) return distance;  // the common case, on every shadow ray
    return projected_reach(light, point, dir, distance);
}

// An area light's axes as seen from one point: its own, or with `orient` rebuilt
// perpendicular to `to_light` (unit, point -> light centre). The same for every sample of
// the point's grid, so made once per point.
struct AreaAxes {
    glm::dvec3 axis1, axis2;
};
AreaAxes area_axes(const LightSource& light, const glm::dvec3& to_light);

// World position of area-light grid sample (u, v), given as fractional grid indices so jitter
// can move it.
glm::dvec3 area_sample_position(const LightSource& light, const AreaAxes& axes, double u,
                                double v);
inline glm::dvec3 area_sample_position(const LightSource& light, double u, double v,
                                       const glm::dvec3& to_light) {
    return area_sample_position(light, area_axes(light, to_light), u, v);
}

}  // namespace lumen::render

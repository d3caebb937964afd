#include "render/lights.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

constexpr double kEpsilon = 1e-10;

double to_radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// pow for the exponents scenes mostly give (tightness 1, fade_power 2) without the call, with
// the same result: lights are evaluated at every radiosity gather's hit.
double light_pow(double x, double y) {
    if (y == 1) return x;
    if (y == 2) return x * x;
    return std::pow(x, y);
}

// Hermite ramp between lo and hi (POV's cone edge).
double smooth_step(double lo, double hi, double x) {
    if (x < lo) return 0;
    if (x >= hi) return 1;
    const double u = (x - lo) / (hi - lo);
    return u * u * (3 - 2 * u);
}

// Spotlight cone; cos_theta is the angle between the axis and light -> point.
double spot_attenuation(const LightSource& l, double cos_theta) {
    if (cos_theta <= 0) return 0;
    double att = l.tightness != 0 ? light_pow(cos_theta, l.tightness) : 1.0;
    if (cos_theta < l.cos_radius) att *= smooth_step(l.cos_falloff, l.cos_radius, cos_theta);
    return att;
}

// Cylinder light: full inside `radius` of the axis, fading out to `falloff`.
double cylinder_attenuation(const LightSource& l, const glm::dvec3& point) {
    const glm::dvec3 d = point - l.position;
    const double along = glm::dot(d, l.axis);
    if (along <= 0) return 0;
    const double k = glm::length(d - along * l.axis);
    if (k >= l.falloff) return 0;
    double att = 1;
    if (l.tightness != 0) att = light_pow(std::max(0.0, 1 - k / l.falloff), l.tightness);
    if (k > l.radius) att *= smooth_step(0, 1, (l.falloff - k) / (l.falloff - l.radius));
    return att;
}

}  // namespace

std::vector<LightSource> prepare_lights(const std::vector<scene::Light>& lights) {
    std::vector<LightSource> out;
    out.reserve(lights.size());
    for (const scene::Light& s : lights) {
        LightSource l;
        l.light = &s;
        l.position = s.position;
        l.colour = s.colour;
        const glm::dvec3 axis = s.point_at - s.position;
        if (glm::length(axis) > kEpsilon) l.axis = glm::normalize(axis);
        l.spot = s.type == scene::LightType::Spot;
        l.cylinder = s.type == scene::LightType::Cylinder;
        l.parallel = s.parallel || l.cylinder;
        l.shadowless = s.shadowless;
        l.group = s.group;
        if (l.spot) {
            l.cos_radius = std::cos(to_radians(s.radius));
            l.cos_falloff = std::cos(to_radians(s.falloff));
            l.tightness = s.tightness;
        } else if (l.cylinder) {
            l.radius = s.radius;
            l.falloff = std::max(s.falloff, s.radius + kEpsilon);
            l.tightness = s.tightness;
        }
        l.fade_distance = s.fade_distance;
        l.fade_power = s.fade_power;
        if (s.area && (s.area->size1 > 1 || s.area->size2 > 1)) {
            l.area = true;
            l.n1 = std::max(1, s.area->size1);
            l.n2 = std::max(1, s.area->size2);
            l.axis1 = s.area->axis1;
            l.axis2 = s.area->axis2;
            l.adaptive = s.area->adaptive;
            l.jitter = s.area->jitter;
            l.orient = s.area->orient;
            l.circular = s.area->circular || l.orient;
        }
        if (s.projected_through) {
            scene::Scene only;
            only.objects.push_back(s.projected_through);
            l.projection = std::make_shared<const Geometry>(only);
        }
        out.push_back(l);
    }
    return out;
}

double beam_factor(const LightSource& l, const glm::dvec3& point) {
    if (l.spot) {
        const glm::dvec3 d = point - l.position;
        const double len = glm::length(d);
        return len > 0 ? spot_attenuation(l, glm::dot(d, l.axis) / len) : 0.0;
    }
    return l.cylinder ? cylinder_attenuation(l, point) : 1.0;
}

double light_fade(const LightSource& l, double distance) {
    if (!(l.fade_power > 0) || !(std::fabs(l.fade_distance) > kEpsilon)) return 1;
    return 2 / (1 + light_pow(distance / l.fade_distance, l.fade_power));
}

bool illuminate(const LightSource& l, const glm::dvec3& point, LightSample& out) {
    if (l.parallel) {
        // Every ray uses the fixed direction; the shadow length is measured along it.
        out.dir = -l.axis;
        out.distance = glm::dot(l.position - point, out.dir);
    } else {
        const glm::dvec3 d = l.position - point;
        out.distance = glm::length(d);
        out.dir = out.distance > 0 ? d / out.distance : glm::dvec3(0, 0, 1);
    }
    double att = 1;
    if (l.spot)
        att = spot_attenuation(l, -glm::dot(out.dir, l.axis));
    else if (l.cylinder)
        att = cylinder_attenuation(l, point);
    if (att == 0) return false;
    att *= light_fade(l, out.distance);
    out.colour = l.colour * att;
    return std::fabs(out.colour.x) >= kEpsilon || std::fabs(out.colour.y) >= kEpsilon ||
           std::fabs(out.colour.z) >= kEpsilon;
}

std::optional<double> projected_reach(const LightSource& l, const glm::dvec3& point,
                                      const glm::dvec3& dir, double distance) {
    // Only the segment between the point and the light counts (an object beyond the light
    // projects nothing), with the shadow rays' tolerance at both ends.
    constexpr double kTolerance = 1e-3;
    if (distance <= 2 * kTolerance) return std::nullopt;
    Hit hit;
    if (!l.projection->intersect(Ray{point, dir}, kTolerance, distance - kTolerance, hit))
        return std::nullopt;
    return hit.t;
}

AreaAxes area_axes(const LightSource& l, const glm::dvec3& to_light) {
    if (!l.orient) return {l.axis1, l.axis2};
    // Rebuilt perpendicular to the light ray, keeping |axis1|.
    const double len = glm::length(l.axis1);
    glm::dvec3 helper = std::fabs(to_light.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 axis1 = glm::normalize(glm::cross(to_light, helper)) * len;
    return {axis1, glm::normalize(glm::cross(to_light, axis1)) * len};
}

glm::dvec3 area_sample_position(const LightSource& l, const AreaAxes& axes, double u,
                                double v) {
    double a = l.n1 > 1 ? u / (l.n1 - 1) - 0.5 : 0.0;
    double b = l.n2 > 1 ? v / (l.n2 - 1) - 0.5 : 0.0;
    if (l.circular && l.n1 > 1 && l.n2 > 1) {
        // Map the square onto a disc (the small offset keeps the centre defined).
        a += 0.001;
        b += 0.001;
        const double s = std::max(std::fabs(a), std::fabs(b)) / std::sqrt(a * a + b * b);
        a *= s;
        b *= s;
    }
    return l.position + a * axes.axis1 + b * axes.axis2;
}

}  // namespace lumen::render

#include "render/fog.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace lumen::render {
namespace {

// Fog density integrated along a ray segment of length `depth`: constant fog has density 1;
// ground fog has density 1 below fog_offset and 1/(1 + ((y − offset)/alt)²) above it, y
// measured along the fog's up vector. (The manual says 1/(1 + (y − offset)/alt)²; povray 3.7
// renders match the form used here exactly.)
double fog_width(const scene::Fog& fog, const Ray& ray, double depth) {
    if (fog.type != 2) return depth;
    const glm::dvec3 up = glm::length(fog.up) > 0 ? glm::normalize(fog.up) : glm::dvec3(0, 1, 0);
    const double off = fog.offset, alt = fog.alt > 0 ? fog.alt : 1e-10;
    auto density = [&](double y) {
        if (y <= off) return 1.0;
        const double u = (y - off) / alt;
        return 1 / (1 + u * u);
    };
    auto integral = [&](double y) {  // antiderivative of the density
        return y <= off ? y : off + alt * std::atan((y - off) / alt);
    };
    const double y1 = glm::dot(ray.origin, up);
    const double dy = glm::dot(ray.dir, up);
    if (std::fabs(dy) < 1e-10) return depth * density(y1);
    return (integral(y1 + dy * depth) - integral(y1)) / dy;
}

// Fog turbulence thins the fog by the turbulence at the segment's midpoint (scaled
// component-wise by the amount), less so the longer the segment: the width is multiplied by
// 1 - e^(-depth/distance)·min(1, turb_depth·turbulence). Fitted to povray 3.7 renders of
// constant and ground fog to 2e-5 (16-bit linear output), with several amounts, turb_depths,
// distances, octaves/omega/lambda and generators; the fog's transform does not move it.
double turbulence_factor(const scene::Fog& fog, const Ray& ray, double depth,
                         noise::Generator generator) {
    const glm::dvec3 p = (ray.origin + ray.dir * (depth * 0.5)) * fog.turbulence.amount;
    const double t = noise::turbulence(p, fog.turbulence, generator);
    return 1 - std::exp(-depth / fog.distance) * std::min(1.0, fog.turb_depth * t);
}

}  // namespace

FogEffect fog_along(const std::vector<scene::Fog>& fogs, const Ray& ray, double depth,
                    noise::Generator generator) {
    // Every fog attenuates what is behind it and adds its own colour; the added colours are
    // summed without attenuating each other.
    FogEffect e;
    for (const scene::Fog& fog : fogs) {
        if (std::fabs(fog.distance) <= 1e-10) continue;  // a zero distance means no fog
        const glm::dvec3 fc(fog.colour.r, fog.colour.g, fog.colour.b);
        // The fog's transmit is the least amount of the scene that shows through.
        double width = fog_width(fog, ray, depth);
        if (fog.turbulence.amount != glm::dvec3(0))
            width *= turbulence_factor(fog, ray, depth, generator);
        const double k = std::max(std::exp(-width / fog.distance), fog.colour.t);
        // Filter tints the light that passes; it does not change the colour the fog adds.
        const double f = fog.colour.f;
        e.attenuation *= k * ((1 - f) + f * fc);
        e.transmit *= k;
        e.added += (1 - k) * fc;
    }
    return e;
}

}  // namespace lumen::render

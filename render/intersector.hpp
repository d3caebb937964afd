// What the tracer needs from the geometry: the nearest hit along a ray. In production this is
// render::Geometry (adapted in render.cpp); tests plug in tiny analytic scenes.
#pragma once
#include "render/hit.hpp"
#include "render/ray.hpp"

namespace lumen::render {

class Intersector {
public:
    virtual ~Intersector() = default;
    // Nearest hit with t_min < t < t_max; `shadow` skips no_shadow objects.
    virtual bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit,
                           bool shadow) const = 0;
};

}  // namespace lumen::render

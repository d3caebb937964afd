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
    // Every surface a shadow ray crosses with t_min < t < t_max, nearest first, handed to
    // `visit` until it returns false; returns how many, or -1 (before any) where the geometry
    // cannot list them in one pass (callers then step with intersect()).
    // shadow_listing() says when listing pays: from the start where most objects let light
    // through, after a first surface that does otherwise.
    enum class Listing { Never, AfterFirstSurface, FromStart };
    virtual Listing shadow_listing() const { return Listing::Never; }
    using HitVisitor = bool (*)(void* context, const Hit& hit);
    virtual int visit_shadow_hits(const Ray&, double /*t_min*/, double /*t_max*/,
                                  HitVisitor, void* /*context*/) const {
        return -1;
    }
};

}  // namespace lumen::render

// What the tracer needs from the geometry: the nearest hit along a ray. In production this is
// render::Geometry; tests plug in tiny analytic scenes.
#pragma once
#include <cstdint>

#include "render/hit.hpp"
#include "render/ray.hpp"

namespace lumen::render {

// A shadow ray ignores surfaces closer than this to where it starts or last crossed one
// (POV's SHADOW_TOLERANCE).
constexpr double kShadowTolerance = 1e-3;

// Which objects a query sees.
enum class Query : uint8_t {
    All,              // every object (no_image / no_reflection are the tracer's business)
    Shadow,           // objects that cast shadows: no_shadow ones are skipped
    ShadowSkipClear,  // those, less the clear ones (see has_clear_objects)
};

// The object that last blocked a shadow ray towards one light, which the next ray towards it
// tests first: nearby shadow rays (an area light's grid, neighbouring pixels) are mostly
// blocked by the same object, and one object test spares the walk through the rest. POV-Ray
// keeps the same cache per light. Only a hint: occluded() answers the same whatever it holds.
struct Occluder {
    uint32_t root = UINT32_MAX;  // the geometry's own numbering; UINT32_MAX: none yet
};

class Intersector {
public:
    virtual ~Intersector() = default;
    // Nearest hit with t_min < t < t_max among the objects `query` sees.
    virtual bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit,
                           Query query) const = 0;
    // Every surface a shadow ray crosses with t_min < t < t_max, nearest first, handed to
    // `visit` until it returns false; returns how many, or -1 (before any) where the geometry
    // cannot list them in one pass (callers then step with intersect()).
    // shadow_listing() says when listing pays: from the start where most objects let light
    // through, after a first surface that does otherwise.
    enum class Listing { Never, AfterFirstSurface, FromStart };
    virtual Listing shadow_listing(Query) const { return Listing::Never; }
    using HitVisitor = bool (*)(void* context, const Hit& hit);
    virtual int visit_shadow_hits(const Ray&, double /*t_min*/, double /*t_max*/, Query,
                                  HitVisitor, void* /*context*/) const {
        return -1;
    }
    // Clear objects let light through unchanged (every surface filters by exactly 1, no
    // caustics, no fade on shadow rays), so a shadow ray may skip them (Query::ShadowSkipClear)
    // where POV's stepping would pass one within its tolerance before another surface (that
    // surface would then be stepped over): near_clear_object(p) is true wherever a clear
    // object's surface may lie within twice kShadowTolerance of p.
    virtual bool has_clear_objects() const { return false; }
    virtual bool near_clear_object(const glm::dvec3& /*p*/) const { return false; }
    // Every surface `query` sees stops all light (no texture layer lets any through): a
    // shadow ray is then blocked exactly when occluded() finds some surface, the nearest or
    // not, and needs no walk from surface to surface.
    virtual bool opaque_only(Query) const { return false; }
    // Whether some surface `query` sees lies at t_min < t < t_max (not necessarily the nearest).
    // `last`, where given, is tested first and then names the object found.
    virtual bool occluded(const Ray& ray, double t_min, double t_max, Query query,
                          Occluder* /*last*/ = nullptr) const {
        Hit hit;
        return intersect(ray, t_min, t_max, hit, query);
    }
};

}  // namespace lumen::render

// All the scene's objects behind one intersection interface (shapes, CSG, bounding, BVH).
#pragma once
#include <memory>
#include <vector>

#include "base/diagnostics.hpp"
#include "render/interior_list.hpp"
#include "render/intersector.hpp"
#include "scene/scene.hpp"

namespace lumen::render {

// A top-level object as the geometry compiled it (unions flattened into their members), in
// scene order: the source object, its object -> world transform and what it inherited from
// the unions around it. The radiosity mesher meshes these, so it sees what the tracer sees.
struct PlacedObject {
    const scene::Object* object = nullptr;
    scene::Transform to_world;
    const scene::LayeredTexture* texture = nullptr;  // after inheritance; null = default
    bool csg = false;           // a merge, intersection or difference (meshed as a whole or not)
    bool no_radiosity = false;  // own or inherited
    bool clipped = false;       // own or inherited clipped_by
};

class Geometry final : public Intersector {
public:
    // Builds the acceleration structure. Throws LumenError (with the object's location) for a
    // shape the renderer cannot intersect.
    explicit Geometry(const std::vector<scene::ObjectPtr>& objects);
    // The scene's objects (not the lights' looks_like objects: RenderFrame adds those).
    explicit Geometry(const scene::Scene& scene) : Geometry(scene.objects) {}
    ~Geometry() override;
    Geometry(const Geometry&) = delete;
    Geometry& operator=(const Geometry&) = delete;

    // Nearest hit with t_min < t < t_max (POV ignores hits closer than 1e-4 for every ray:
    // callers pass that as t_min) among the objects `query` sees; Query::All still hits
    // objects flagged no_image (the tracer decides per ray kind).
    // Thread-safe (const, no shared mutable state), as is everything below.
    bool intersect(const Ray& ray, double t_min, double t_max, Hit& hit,
                   Query query = Query::All) const override;

    // Every surface a shadow ray crosses with t_min < t < t_max, nearest first (equal t: scene
    // order), handed to `visit` until it returns false. Returns how many were handed over, or
    // -1, before any, where the scene cannot list them in one pass: objects `query` sees other
    // than plain spheres, planes and boxes (CSG, transformed, clipped or bounded ones), or
    // more than kMaxListedHits hits. Callers then step from hit to hit with intersect().
    static constexpr int kMaxListedHits = 32;
    int visit_shadow_hits(const Ray& ray, double t_min, double t_max, Query query,
                          HitVisitor visit, void* context) const override;
    // Never where the objects `query` sees cannot be listed; from the start where at least
    // half of them may let light through (filter or transmit somewhere).
    Listing shadow_listing(Query query) const override;

    bool has_clear_objects() const override;
    bool opaque_only(Query query) const override;
    bool occluded(const Ray& ray, double t_min, double t_max, Query query,
                  Occluder* last = nullptr) const override;
    bool near_clear_object(const glm::dvec3& p) const override;

    // True if world point p is inside `object` (used for media/fog decisions and tests).
    static bool inside(const scene::Object& object, const glm::dvec3& p);

    size_t primitive_count() const;
    const std::vector<PlacedObject>& placed_objects() const;
    // What the shapes report once a render is done (an isosurface's max_gradient, as POV-Ray
    // warns), located at their objects.
    std::vector<Diagnostic> shape_warnings() const;
    // The primitives of every opaque closed object that `eye` is outside of (shapes with an
    // inside, and CSG made only of such): a ray that meets one of their surfaces from behind
    // started inside solid matter, where nothing can see.
    std::vector<const scene::Object*> solid_primitives(const glm::dvec3& eye) const;
    // Whether world point p is inside placed_objects()[i].
    bool inside_placed(size_t i, const glm::dvec3& p) const;
    // The interiors of every object around p, in scene order: where a ray starting at p is
    // (POV-Ray tests every object for the camera, and for a light shooting photons).
    InteriorList interiors_around(const glm::dvec3& p) const;
    // Whether no ray can see into placed_objects()[i] from outside it: no layer of its texture
    // lets light through, and camera and reflection rays do not pass it by (no_image,
    // no_reflection).
    bool placed_is_opaque(size_t i) const;
    // Whether nothing seen from `eye` lies inside placed_objects()[i]: it is opaque and `eye`
    // is outside it.
    bool hides_inside(size_t i, const glm::dvec3& eye) const {
        return placed_is_opaque(i) && !inside_placed(i, eye);
    }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lumen::render

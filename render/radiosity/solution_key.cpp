#include "render/radiosity/solution_key.hpp"

#include "render/radiosity/scene_solution.hpp"
#include "render/radiosity/solution_io.hpp"
#include "scene/content_hash.hpp"

namespace lumen::render::radiosity {

namespace {

void add_light(scene::ContentHash& h, const scene::Light& l) {
    h.add(l.position), h.add(l.colour), h.add(l.type), h.add(l.parallel), h.add(l.point_at);
    h.add(l.radius), h.add(l.falloff), h.add(l.tightness), h.add(l.shadowless);
    h.add(l.fade_distance), h.add(l.fade_power), h.add(l.area_illumination);
    h.add(bool(l.area));
    if (const auto& a = l.area) {
        h.add(a->axis1), h.add(a->axis2), h.add(a->size1), h.add(a->size2), h.add(a->adaptive);
        h.add(a->jitter), h.add(a->circular), h.add(a->orient);
    }
    h.add(l.looks_like), h.add(l.projected_through);
}

}  // namespace

uint64_t solution_key(const RenderFrame& frame, const SceneMesh& mesh,
                      const RadiosityOptions& options) {
    const scene::Scene& scene = frame.scene();
    scene::ContentHash h;
    // How it is solved. Gather rays, the cache error, subdivision and the display mode only
    // change how the solution is shown.
    h.add(options.method), h.add(effective_bounces(scene, options)), h.add(options.form_factors);
    h.add(options.ff_rays), h.add(options.hemicube_res), h.add(options.tolerance);
    h.add(kSolutionFileVersion);  // what a stored solution holds
    h.add(bool(scene.globals.radiosity));
    if (const auto& r = scene.globals.radiosity) h.add(r->brightness), h.add(r->recursion_limit);
    h.add(scene.globals.ambient_light), h.add(scene.globals.assumed_gamma);
    // The patches: where they are and, through each vertex's reflectance, emission and
    // brilliance, the finishes and pigments that matter to them.
    h.add(mesh.patch_size);
    for (const MeshVertex& v : mesh.vertices) {
        h.add(v.position), h.add(v.normal), h.add(v.rho), h.add(v.emission);
        h.add(v.brilliance), h.add(v.area), h.add(v.sealed);
    }
    for (const MeshElement& e : mesh.elements) h.add(e.v);
    // What lights them directly and what the sky adds.
    for (const scene::Light& l : scene.lights) add_light(h, l);
    h.add(scene.background);
    h.add(bool(scene.sky_sphere));
    if (const auto& s = scene.sky_sphere) h.add(s->pigments), h.add(s->transform), h.add(s->emission);
    // Everything that casts shadows on them or hides one patch from another: every object's
    // shape, placement, flags and pigments (filter and transmit let light through).
    h.add(scene.objects);
    return h.value();
}

}  // namespace lumen::render::radiosity

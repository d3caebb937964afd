#include "render/radiosity/display.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/radiosity/surface_light.hpp"


namespace lumen::render::radiosity {

namespace {

// The element a surface hit lies on: a short probe along the normal through the hit point.
// An element turned more than 45 degrees from the surface there is not the hit's (the far
// side of a thin tube, found near a silhouette): -1, and the point gathers for itself.
long element_at(const SceneMesh& mesh, const Hit& hit, const glm::dvec3& normal,
                glm::dvec3& bary) {
    const double d = 1e-4 * mesh.patch_size;
    const long e = mesh.find(hit.point + d * normal, -normal, d, d + 1e-9, hit.object, bary);
    if (e >= 0 && std::fabs(glm::dot(mesh.elements[size_t(e)].normal, normal)) < 0.7) return -1;
    return e;
}

// The receivers' G where a hit lies on an element; a point gather elsewhere.
class Preview final : public IndirectLight {
public:
    Preview(const SceneMesh& mesh, const ReceiverMesh& receivers, const PointGather* points,
            const DisplaySettings& s)
        : mesh_(mesh), receivers_(receivers), points_(points), s_(s) {}
    glm::dvec3 incident(const Hit& hit, const glm::dvec3& normal, ThreadState& state) const override {
        glm::dvec3 bary;
        const long e = element_at(mesh_, hit, normal, bary);
        if (e < 0) return points_ ? apply_knobs(s_, points_->incident(hit.point, normal, state))
                                  : glm::dvec3(0);
        const MeshElement& el = mesh_.elements[size_t(e)];
        const uint32_t side = seen_side(el, hit.normal, normal);
        // A seen point on a sealed side is on another facet than this one (the far side of a
        // coarsely faceted tube), and one whose corners were not gathered (seen only in a
        // reflection or by an anti-aliasing sample, with no form factors to stand in): it
        // gathers for itself.
        if (points_) {
            bool own = !receivers_.covers(e, side);
            for (uint32_t v : el.v) own = own || (mesh_.vertices[v].sealed >> side & 1);
            if (own) return apply_knobs(s_, points_->incident(hit.point, normal, state));
        }
        return apply_knobs(s_, receivers_.value(e, bary, side));
    }

private:
    const SceneMesh& mesh_;
    const ReceiverMesh& receivers_;
    const PointGather* points_;
    DisplaySettings s_;
};

// The per-pixel final gather everywhere.
class Gather final : public IndirectLight, public GatherStats {
public:
    Gather(const PointGather& points, const DisplaySettings& s) : points_(points), s_(s) {}
    glm::dvec3 incident(const Hit& hit, const glm::dvec3& normal, ThreadState& state) const override {
        return apply_knobs(s_, points_.incident(hit.point, normal, state));
    }
    size_t cache_points() const override { return points_.cache_points(); }
    double gather_seconds() const override { return points_.gather_seconds(); }

private:
    const PointGather& points_;
    DisplaySettings s_;
};

}  // namespace

DisplaySettings display_settings(const scene::Scene& scene, const RadiosityOptions& options) {
    const scene::RadiositySettings r = scene.globals.radiosity.value_or(scene::RadiositySettings{});
    DisplaySettings s;
    s.brightness = r.brightness;
    s.gray_threshold = std::clamp(r.gray_threshold, 0.0, 1.0);
    // At least 7 x 7 strata: POV's default count 35 gives 45, which rounds to 49 (a floor of 64
    // cost radiosity2.pov 14% more time for 0.0057 -> 0.0055 against its bar of 0.0070).
    s.gather_rays = options.gather_rays ? *options.gather_rays : std::max(49, r.count * 13 / 10);
    // POV's error_bound is not Ward's a: a tenth of it gives about POV's cache density
    // (cornell.pov's 0.5 -> 0.05: 20600 records at 300x300; 0.5 itself gave 519, MAE 0.010).
    s.cache_error = options.cache_error ? *options.cache_error : std::max(0.01, r.error_bound / 10);
    // The preview's point gathers shoot at least 256 rays each (point_gather_settings), so a
    // coarser cache serves them: radiosity_37.pov's error 0.0079 -> 0.0085 (POV's own 0.0104) at
    // 0.05 -> 0.1, its time 1.36 -> 0.82 s; radiosity2.pov's (0.02) 0.0059 either way.
    s.point_cache_error =
        options.cache_error ? *options.cache_error : std::max(0.2, r.error_bound / 10);
    s.min_reuse = r.minimum_reuse;
    s.max_reuse = std::max(r.maximum_reuse, r.minimum_reuse);
    s.camera = scene.camera.location;
    return s;
}

glm::dvec3 apply_knobs(const DisplaySettings& s, const glm::dvec3& G) {
    glm::dvec3 g = G;
    if (s.gray_threshold > 0) {
        const double grey = 0.297 * g.x + 0.589 * g.y + 0.114 * g.z;
        g = s.gray_threshold * glm::dvec3(grey) + (1 - s.gray_threshold) * g;
    }
    g *= s.brightness;
    return std::isfinite(g.x + g.y + g.z) ? g : glm::dvec3(0);
}

bool interpolate(const SceneMesh& mesh, const std::vector<glm::dvec3>& values, const Hit& hit,
                 const glm::dvec3& normal, glm::dvec3& out) {
    glm::dvec3 bary;
    const long e = element_at(mesh, hit, normal, bary);
    if (e < 0) return false;
    out = interpolate_sides(mesh, values, e, bary,
                            seen_side(mesh.elements[size_t(e)], hit.normal, normal));
    return true;
}

std::unique_ptr<IndirectLight> make_preview(const SceneMesh& mesh, const ReceiverMesh& receivers,
                                            const PointGather* points,
                                            const DisplaySettings& settings) {
    return std::make_unique<Preview>(mesh, receivers, points, settings);
}

std::unique_ptr<IndirectLight> make_gather(const PointGather& points,
                                           const DisplaySettings& settings) {
    return std::make_unique<Gather>(points, settings);
}

PointGatherSettings point_gather_settings(const scene::Scene& scene, const DisplaySettings& s,
                                          int bounces, bool everywhere) {
    PointGatherSettings p;
    // As the fallback of the preview, these gathers are seen directly, one per cache record,
    // with no smoothing after them: fewer rays show as noise (radiosity_37.pov's walls at
    // count 50), and with more rays a coarser cache serves.
    p.rays = everywhere ? s.gather_rays : std::max(256, s.gather_rays);
    p.bounces = std::max(1, bounces);
    p.cache = {everywhere ? s.cache_error : s.point_cache_error, s.min_reuse, s.max_reuse,
               s.camera};
    p.ambient_emission = ambient_emission(scene);
    return p;
}

}  // namespace lumen::render::radiosity

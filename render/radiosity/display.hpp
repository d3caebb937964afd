// Showing the radiosity solution: the tracer asks for the incident
// indirect light G at each diffuse hit.
// - preview: G interpolated from the element's vertices (fast; shows the mesh).
//   Hits on surfaces without elements gather per point (point_gather.hpp).
// - gather: a final gather per point (cosine rays whose hits return the interpolated B of
//   the previous bounce, misses the background) through a Ward-style irradiance cache shared
//   by the render threads; this is POV's look without its bounce noise.
#pragma once
#include <memory>

#include "render/indirect_light.hpp"
#include "render/intersector.hpp"
#include "render/radiosity/point_gather.hpp"
#include "render/radiosity/receivers.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "scene/scene.hpp"

namespace lumen::render::radiosity {

struct DisplaySettings {
    double brightness = 1, gray_threshold = 0;
    int gather_rays = 256;
    double cache_error = 0.3;            // Ward's a: reuse radius relative to the harmonic mean
    double point_cache_error = 0.3;      // the same for the gathers of unmeshed surfaces
    double min_reuse = 0.015, max_reuse = 0.2;  // × distance to the camera (POV)
    glm::dvec3 camera{0};
};

// The settings from the scene's radiosity block and the options.
DisplaySettings display_settings(const scene::Scene& scene, const RadiosityOptions& options);

// brightness × (G desaturated by gray_threshold), never NaN.
glm::dvec3 apply_knobs(const DisplaySettings& s, const glm::dvec3& G);

// Interpolated G of the element under a hit on the side `normal` faces; false when the hit
// is on no element.
bool interpolate(const SceneMesh& mesh, const std::vector<glm::dvec3>& values, const Hit& hit,
                 const glm::dvec3& normal, glm::dvec3& out);

class GatherStats {
public:
    virtual ~GatherStats() = default;
    virtual size_t cache_points() const = 0;
    virtual double gather_seconds() const = 0;  // summed over threads
};

// The receivers' G, interpolated over the (split) element hit, and `points`' gather where a
// hit is on no element (none when null); both must outlive the result.
std::unique_ptr<IndirectLight> make_preview(const SceneMesh& mesh, const ReceiverMesh& receivers,
                                            const PointGather* points,
                                            const DisplaySettings& settings);

// `points`' gather at every hit; it must outlive the result.
std::unique_ptr<IndirectLight> make_gather(const PointGather& points,
                                           const DisplaySettings& settings);

// The point gathers of the display, `bounces` levels deep: the gather display's rays and
// cache when they serve `everywhere`, more rays and a coarser cache when they only stand in
// for the preview where a hit is on no element.
PointGatherSettings point_gather_settings(const scene::Scene& scene, const DisplaySettings& s,
                                          int bounces, bool everywhere);

}  // namespace lumen::render::radiosity

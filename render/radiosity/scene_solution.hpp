// The view-independent radiosity solution of a scene: per
// vertex side, the radiosity B leaving it after bounce k−1 and the incident indirect light G
// of bounce k, where k is the bounce count (POV's recursion_limit) or ∞ (converged).
//   B⁰ = E + ρ(H + G_env),  Gᵏ = F Bᵏ⁻¹ + G_env,  Bᵏ = E + ρ(H + Gᵏ)
// H is the direct light as POV's radiosity rays see it (area lights as point lights at
// their centre, spotlight falloff, fade, shadows), F the ray-cast vertex form factors.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "render/camera.hpp"
#include "render/frame.hpp"
#include "render/hit.hpp"
#include "render/intersector.hpp"
#include "render/radiosity/irradiance_gradients.hpp"
#include "render/radiosity/options.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "scene/scene.hpp"

namespace lumen::render::radiosity {

// What a radiosity ray sees where it lands, evaluated at the hit (point_gather.hpp): on a
// surface without elements (CSG other than unions, shapes the mesher cannot cut, pure
// emitters) always, and on every surface where evaluates_every_hit() (the gathers that follow
// a solve).
class SurfaceRadiance {
public:
    virtual ~SurfaceRadiance() = default;
    // The light leaving `hit` back along the ray (direction `dir`) of a gather at `level`
    // (1: the gathers the camera's hits and the final gather make). `element`: the scene
    // mesh element the hit lies on, at barycentric `bary`; -1 where it lies on none (or
    // where uses_element(level) said it need not be looked for).
    virtual glm::dvec3 leaving(const Hit& hit, const glm::dvec3& dir, int level, long element,
                               const glm::dvec3& bary) const = 0;
    // Whether a gather asks leaving() on meshed surfaces too, in place of interpolating the
    // solution's B over the element it lands on.
    virtual bool evaluates_every_hit() const { return false; }
    // Whether leaving() at `level` needs the element under the hit (finding it costs a probe).
    virtual bool uses_element(int level) const {
        (void)level;
        return true;
    }
    // Runs `work` with the caches of `worker` (kept from call to call) for the gathers
    // `leaving` makes on this thread: with each worker given a fixed share of the work, what
    // it computes does not depend on which thread reached a surface first.
    virtual void with_worker_caches(size_t worker, const std::function<void()>& work) const {
        (void)worker;
        work();
    }
};

// Sparse rows of vertex form factors: F[u][col] is the fraction of a cosine-weighted gather
// from vertex side u that lands on the basis function of `col`; `env` the background light
// that escaping rays bring back (already divided by the ray count).
struct VertexFormFactors {
    std::vector<uint32_t> start;  // row u is [start[u], start[u+1])
    std::vector<uint32_t> col;
    std::vector<float> weight;
    std::vector<glm::dvec3> env;

    size_t rows() const { return env.size(); }
    glm::dvec3 gather(size_t u, const std::vector<glm::dvec3>& B) const;
};

struct Solution {
    std::vector<glm::dvec3> B;  // per unknown: leaving radiosity (bounce k−1)
    std::vector<glm::dvec3> G;  // per unknown: incident indirect light (bounce k); empty
                                // without form factors (needs_form_factors)
    // Per unknown: the incident indirect light inside B, B = E + ρ(H + indirect) (bounce
    // k−1; zeros for one bounce). A gather that lands on an element adds it to the direct
    // light it evaluates at the hit.
    std::vector<glm::dvec3> indirect;
    int bounces = 0;            // k; 0 = converged
    uint64_t scene_key = 0;     // what the solution was computed for (save/load, animation)
};

struct SolveInfo {
    double form_factor_seconds = 0, solve_seconds = 0;
    int iterations = 0;
    int ff_rays = 0;                    // rays per vertex side of the ray-cast form factors
    std::string method;                 // "jacobi", "matrix", ...
    std::vector<std::string> warnings;  // stability reports
};

// What radiosity gathers see in an escaping direction: the sky_sphere over the background.
glm::dvec3 background_radiance(const scene::Scene& scene, const glm::dvec3& dir);

// Direct light per vertex side (the H above), from the frame's lights through its geometry.
std::vector<glm::dvec3> direct_light(const RenderFrame& frame, const SceneMesh& mesh, int threads);

// Vertex form factors by the options' method (scene_form_factors.cpp): `raycast`
// (ff_rays stratified cosine rays per vertex side), `analytic` (Lambert's point-to-polygon
// value with sampled visibility for emitters and the elements within two patch sizes, rays
// for the rest) or `hemicube` (hemicube_res, cast through the scene; the baseline).
// Rays landing on surfaces without elements add what `unmeshed` says they leave to `env`.
VertexFormFactors vertex_form_factors(const scene::Scene& scene, const SceneMesh& mesh,
                                      const Intersector& geometry,
                                      const RadiosityOptions& options, int threads,
                                      const SurfaceRadiance* unmeshed = nullptr);

// Which vertex sides the camera sees (one primary ray per pixel), rows on `threads` threads.
std::vector<char> visible_sides(const SceneMesh& mesh, const Intersector& geometry,
                                const CameraModel& camera, int width, int height, int threads);

// Where the gathers and light samples of a vertex side start: a hair inside the adjacent
// elements (off shared edges and corners).
inline glm::dvec3 gather_origin(const SceneMesh& mesh, const MeshVertex& v) {
    return v.position + v.inward * (1e-3 * mesh.patch_size);
}
// The true surface under point p of a flat element with front normal n: a curved shape's
// elements are chords, inside the surface away from their corners, and their normal is off
// the surface's. A probe along -n from `reach` above p to `reach` below it takes, of the hits
// on `object` whose normal is within 60 degrees of ±n, the one nearest p; p and n (kept on
// n's side) become that hit and `object`'s normal there. False, with p and n unchanged, when
// there is none.
bool onto_surface(const Intersector& geometry, const scene::Object* object, glm::dvec3& p,
                  glm::dvec3& n, double reach);

inline glm::dvec3 side_normal(const MeshVertex& v, size_t side) {
    return side ? -v.normal : v.normal;
}
inline bool needs_light(const MeshVertex& v) { return v.rho.x > 0 || v.rho.y > 0 || v.rho.z > 0; }
// The ray seed of unknown u's gathers (deterministic per vertex side).
inline uint64_t side_seed(size_t u) { return 0x9e3779b97f4a7c15ULL * (u + 1); }

struct GatherResult {
    glm::dvec3 G{0};
    double harmonic_distance = 0;  // of the rays that hit (infinite when none did)
    double inside = 0;  // share of the rays that started inside solid matter (left out)
    IrradianceGradients gradients;  // when asked for
};

// Incident light at a point: `rays` stratified cosine rays from `origin` about the unit
// `normal` (deterministic for `seed`); a hit returns B interpolated over the element it lands
// on, a miss the background, a surface without elements what `unmeshed` says it leaves
// (nothing when null) for a gather at `level`, and so does every surface where
// `unmeshed->evaluates_every_hit()`.
GatherResult gather_point(const scene::Scene& scene, const SceneMesh& mesh,
                          const Intersector& geometry, const std::vector<glm::dvec3>& B,
                          const glm::dvec3& origin, const glm::dvec3& normal, int rays,
                          uint64_t seed, const SurfaceRadiance* unmeshed = nullptr,
                          int level = 1, bool gradients = false);

// The whole solution of the frame: direct light, form factors and the solve the options ask
// for, all through the frame's geometry (the tracer's).
Solution solve_scene(const RenderFrame& frame, const SceneMesh& mesh,
                     const RadiosityOptions& options, int threads, SolveInfo& info);

// The bounce count in effect: the option, else the scene's recursion_limit.
int effective_bounces(const scene::Scene& scene, const RadiosityOptions& options);
// Form-factor rays per vertex side: Radiosity_FF_Rays, else 16; 4 where the solve stops at
// one bounce.
int effective_ff_rays(const scene::Scene& scene, const RadiosityOptions& options);
// Whether the solve computes form factors. A solve that stops at one bounce (POV's
// recursion_limit 1, Jacobi or auto) is B = E + ρH, and its G (F B) would only stand in for
// the vertex sides the display does not gather; unless the options name a form-factor method
// or ray count, it skips them, its solution has no G (empty), and the display gathers at
// every point it shows instead (patio-radio_37.pov: 1.1 of 3.0 s went to form factors).
bool needs_form_factors(const scene::Scene& scene, const RadiosityOptions& options);

// Runs fn(begin, end) over [0, n) on up to `threads` threads (in chunks).
void parallel_for(size_t n, int threads, const std::function<void(size_t, size_t)>& fn);
// The same with a fixed share per worker (chunks dealt round robin): fn(worker, begin, end),
// where the same chunks always reach the same worker for a given thread count.
void parallel_for_dealt(size_t n, int threads,
                        const std::function<void(size_t, size_t, size_t)>& fn);

}  // namespace lumen::render::radiosity

// Radiosity at any surface point, meshed or not. The patch solution covers what the mesher
// can cut; a point elsewhere (CSG other than unions, shapes without a mesher, pure emitters)
// gets its incident light from a gather of its own through an irradiance cache, and what a
// gather ray sees where it lands on such a surface is evaluated there, as POV-Ray evaluates
// every surface its radiosity rays hit: E + ρ (H + G), with G a gather one level deeper while
// the level is within the bounce count (POV's recursion_limit).
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/vec3.hpp>

#include "render/frame.hpp"
#include "render/radiosity/irradiance_cache.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "render/trace_state.hpp"

namespace lumen::render::radiosity {

struct PointGatherSettings {
    int rays = 256;            // rays of a level-1 gather; deeper levels shoot a quarter
    int bounces = 1;           // the deepest level that gathers
    CacheSettings cache;       // level 1's; deeper levels reuse twice as far
    glm::dvec3 ambient_emission{0};  // surface_light.hpp
    bool gradients = true;           // records extrapolate (irradiance_gradients.hpp)
};

class PointGather final : public SurfaceRadiance {
public:
    // `B` null: no solution yet (the solve's own gathers), so surfaces without elements
    // leave only E + ρH. With the solution's `indirect` (Solution::indirect), every hit is
    // evaluated where it lies, meshed or not: the direct light at the hit point itself (the
    // element's B blurs a shadow edge over its corners), the element's material (the
    // texture's where there is no element), plus the solution's indirect light interpolated
    // over the element. Everything passed must outlive the object.
    PointGather(const RenderFrame& frame, const SceneMesh& mesh, const std::vector<glm::dvec3>* B,
                const PointGatherSettings& settings,
                const std::vector<glm::dvec3>* indirect = nullptr);

    glm::dvec3 leaving(const Hit& hit, const glm::dvec3& dir, int level, long element,
                       const glm::dvec3& bary) const override;
    bool evaluates_every_hit() const override { return indirect_ != nullptr; }
    bool uses_element(int level) const override {
        return any_indirect_ || (B_ && level < s_.bounces);
    }
    void with_worker_caches(size_t worker, const std::function<void()>& work) const override;

    // Incident indirect light at surface point p on the side of unit normal n, for a gather
    // of `level` (1: a camera hit), through that level's cache. Needs B.
    glm::dvec3 incident(const glm::dvec3& p, const glm::dvec3& n, int level) const;
    // The same for a camera hit in a render block, through caches of that block's own
    // (kept in `state`, and used by the deeper levels of its gathers): the value does not
    // depend on the order in which threads render blocks, or on which blocks a partial
    // render leaves out (lumen farm's tiles are the whole render's pixels).
    glm::dvec3 incident(const glm::dvec3& p, const glm::dvec3& n, ThreadState& state) const;

    size_t cache_points() const;
    double gather_seconds() const { return gather_ns_.load() * 1e-9; }

private:
    const RenderFrame& frame_;
    const SceneMesh& mesh_;
    const std::vector<glm::dvec3>* B_;
    PointGatherSettings s_;
    const std::vector<glm::dvec3>* indirect_;
    bool any_indirect_ = false;  // not all zeros (one bounce)
    using Caches = std::vector<std::unique_ptr<IrradianceCache>>;  // per level, 1 first
    Caches make_caches() const;
    glm::dvec3 incident_in(const Caches& caches, const glm::dvec3& p, const glm::dvec3& n,
                           int level) const;

    Caches caches_;  // shared: gathers outside render blocks and workers
    mutable std::mutex workers_mutex_;
    mutable std::vector<std::unique_ptr<Caches>> worker_caches_;  // the receivers' workers
    mutable std::atomic<size_t> block_records_{0};
    mutable std::atomic<uint64_t> gather_ns_{0};
};

}  // namespace lumen::render::radiosity

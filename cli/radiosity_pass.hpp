// The radiosity pass of a frame: applies Radiosity=on/off to the scene, meshes it, computes
// (or loads, or reuses from the previous frame) the patch solution, and provides the
// tracer's indirect light. One solution serves every frame in which only the camera moved.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>

#include "render/frame.hpp"
#include "render/indirect_light.hpp"
#include "render/radiosity/display.hpp"
#include "render/radiosity/options.hpp"
#include "render/radiosity/receivers.hpp"
#include "render/radiosity/scene_mesh.hpp"
#include "render/radiosity/scene_solution.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

namespace lumen::cli {

// Radiosity=on gives a scene without a block POV's defaults; Radiosity=off drops the block.
void apply_radiosity_switch(scene::Scene& scene, const render::radiosity::RadiosityOptions& o);

class RadiosityPass {
public:
    // Prepares the indirect light for the frame, through its geometry and lights (the frame
    // must outlive the pass's use of the result: the next prepare() drops it). Returns null
    // when the scene has no radiosity. Reuses the previous solution when the scene key and
    // mesh match. `log` receives warnings and the +V line.
    const render::IndirectLight* prepare(const render::RenderFrame& frame,
                                         const render::radiosity::RadiosityOptions& options,
                                         const render::RenderOptions& render,
                                         std::vector<std::string>& log);
    // The same on a frame of its own for `scene` (which must outlive it), kept until the next
    // prepare().
    const render::IndirectLight* prepare(const scene::Scene& scene,
                                         const render::radiosity::RadiosityOptions& options,
                                         const render::RenderOptions& render,
                                         std::vector<std::string>& log);

    // The view-independent part of prepare() alone: meshes the scene and loads, reuses or
    // solves (and saves) its patch solution. Returns false when the scene has no radiosity.
    bool solve(const render::RenderFrame& frame,
               const render::radiosity::RadiosityOptions& options,
               const render::RenderOptions& render, std::vector<std::string>& log);
    // Where Radiosity_Store keeps the solution of scene key `key`.
    static std::string store_path(const std::string& folder, uint64_t key);

    // The +V line, once the frame is rendered (gather figures included).
    std::string summary() const;

    bool reused() const { return reused_; }
    const std::string& loaded_from() const { return loaded_from_; }
    // The preview's receiving elements (null with the gather display).
    const render::radiosity::ReceiverMesh* receivers() const { return receivers_.get(); }
    const render::radiosity::Solution* solution() const {
        return solution_ ? &*solution_ : nullptr;
    }

private:
    std::unique_ptr<render::RenderFrame> own_frame_;  // prepare(scene) only
    std::unique_ptr<render::radiosity::SceneMesh> mesh_;
    std::optional<render::radiosity::Solution> solution_;
    std::unique_ptr<render::radiosity::ReceiverMesh> receivers_;  // G shown in this view
    std::unique_ptr<render::radiosity::PointGather> points_;      // where no element is
    size_t gathered_ = 0;            // vertex sides gathered for this view
    double gather_seconds_ = 0;
    std::unique_ptr<render::IndirectLight> display_;
    render::radiosity::SolveInfo info_;
    render::radiosity::RadiosityOptions options_;
    bool reused_ = false;
    std::string loaded_from_;  // the file the solution came from, if it was loaded
    int bounces_ = 0;
};

}  // namespace lumen::cli

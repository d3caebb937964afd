// One frame's scene compiled for rendering, built once: the geometry (the scene's objects and
// the lights' looks_like objects), the prepared lights and the one check that the scene uses
// nothing lumen cannot draw. The pre-passes (radiosity now, photons later) and the tracer all
// work on it, so they see the same objects, flags and lights.
#pragma once
#include <memory>
#include <vector>

#include "render/geometry.hpp"
#include "render/lights.hpp"
#include "scene/scene.hpp"

namespace lumen::render {

// Throws LumenError at the first unsupported feature that reached the scene (its location).
void check_supported(const scene::Scene& scene);

class RenderFrame {
public:
    // `scene` must outlive the frame. Throws LumenError for unsupported features and shapes.
    explicit RenderFrame(const scene::Scene& scene);
    RenderFrame(const RenderFrame&) = delete;
    RenderFrame& operator=(const RenderFrame&) = delete;

    const scene::Scene& scene() const { return scene_; }
    const Geometry& geometry() const { return *geometry_; }
    const std::vector<LightSource>& lights() const { return lights_; }

private:
    const scene::Scene& scene_;
    std::unique_ptr<const Geometry> geometry_;
    std::vector<LightSource> lights_;
};

}  // namespace lumen::render

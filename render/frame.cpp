#include "render/frame.hpp"

#include "base/diagnostics.hpp"

namespace lumen::render {

void check_supported(const scene::Scene& scene) {
    if (scene.unsupported.empty()) return;
    const scene::Unsupported& u = scene.unsupported.front();
    throw LumenError(u.loc, "unsupported feature: " + u.feature);
}

namespace {

// A light's looks_like object is part of the geometry (the interpreter has already placed it
// at the light and made it no_shadow).
std::vector<scene::ObjectPtr> objects_of(const scene::Scene& scene) {
    std::vector<scene::ObjectPtr> all = scene.objects;
    for (const scene::Light& l : scene.lights)
        if (l.looks_like) all.push_back(l.looks_like);
    return all;
}

}  // namespace

RenderFrame::RenderFrame(const scene::Scene& scene) : scene_(scene) {
    check_supported(scene);
    geometry_ = std::make_unique<const Geometry>(objects_of(scene));
    lights_ = prepare_lights(scene.lights);
}

}  // namespace lumen::render

// The reuse key of a radiosity solution: a hash of everything the patch solution depends on
// and nothing it does not (the camera, finishes' highlights and reflection, the display
// options), so a solution is reused across views and frames exactly while it stays right.
#pragma once
#include <cstdint>

#include "render/frame.hpp"
#include "render/radiosity/options.hpp"
#include "render/radiosity/scene_mesh.hpp"

namespace lumen::render::radiosity {

uint64_t solution_key(const RenderFrame& frame, const SceneMesh& mesh,
                      const RadiosityOptions& options);

}  // namespace lumen::render::radiosity

// Public entry point of the renderer: scene::Scene -> linear float image.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "render/default_init.hpp"

#include "scene/scene.hpp"

namespace lumen::render {

class IndirectLight;  // render/indirect_light.hpp

struct RenderOptions {
    int width = 800, height = 600;
    bool antialias = false;
    double aa_threshold = 0.3;
    int aa_method = 1;        // +AM1 / +AM2
    int aa_depth = 3;         // +R
    bool jitter = true;       // +J / -J (only matters with +A)
    double jitter_amount = 1.0;
    double aa_gamma = 2.5;
    int threads = 0;          // 0 = all cores
    int block_size = 32;      // +BS
    int quality = 9;          // +Q
    bool alpha = false;       // +UA: the background is transparent (alpha channel)
    const IndirectLight* indirect = nullptr;  // radiosity (render/indirect_light.hpp)
    // Partial render, 0-based inclusive pixel ranges (full image when -1).
    int start_row = 0, end_row = -1, start_col = 0, end_col = -1;
};

// RGBFT per pixel in the scene's working colour space, unclipped (POV keeps floats until output).
struct Image {
    int width = 0, height = 0;
    // 5 floats per pixel: r g b f t, row-major from the top. Not zeroed on resize: the render
    // writes every pixel of its area (and zeroes the rest of a partial render itself).
    std::vector<float, DefaultInit<float>> pixels;
    float* at(int x, int y) { return &pixels[(size_t(y) * width + x) * 5]; }
    const float* at(int x, int y) const { return &pixels[(size_t(y) * width + x) * 5]; }
};

struct RenderStats {
    uint64_t primary_rays = 0, total_rays = 0, shadow_rays = 0;
    uint64_t photons_shot = 0, photons_stored = 0;  // the photon pass (POV's statistics)
    uint64_t media_photons_stored = 0;
    double seconds = 0;
};

// Progress callback: fraction done in [0,1]. Called from worker threads, serialised.
using Progress = std::function<void(double)>;

// Called by a worker thread as soon as a block's pixels [left, right] x [top, bottom]
// (inclusive) are final; calls for different blocks may run at the same time.
using BlockDone = std::function<void(const Image&, int left, int top, int right, int bottom)>;

// The pixels a render computes (+SR +ER +SC +EC), inclusive, 0-based.
struct PixelArea {
    int x0, y0, x1, y1;
};
PixelArea render_area(const RenderOptions& options);
// False for a partial render (+SR +ER +SC +EC that leave out part of the image).
bool covers_whole_image(const RenderOptions& options);

// The side of the render's blocks (+BS, within [4, the image's larger side]). Blocks lie on a
// grid of this size from the image's top-left corner: a partial render cut on that grid gives
// the same pixels as the whole render.
int effective_block_size(const RenderOptions& options);

class RenderFrame;  // render/frame.hpp

// Renders the frame's scene (its pre-passes, such as options.indirect, done on the same frame).
// Pixels outside a partial render's area are zero, unless `block_done` is given: a caller that
// takes the blocks as they finish gets those pixels unset.
Image render(const RenderFrame& frame, const RenderOptions& options, RenderStats* stats = nullptr,
             const Progress& progress = {}, const BlockDone& block_done = {});

// The same on a frame built for this render. Throws LumenError if the scene uses something
// the renderer cannot draw (with the location of the offending item).
Image render(const scene::Scene& scene, const RenderOptions& options, RenderStats* stats = nullptr,
             const Progress& progress = {}, const BlockDone& block_done = {});

}  // namespace lumen::render

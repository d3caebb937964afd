// render(): the image cut into blocks (+BS) rendered by a pool of std::threads.
#include "render/render.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "base/diagnostics.hpp"
#include "render/antialias.hpp"
#include "render/camera.hpp"
#include "render/frame.hpp"
#include "render/photons/photon_pass.hpp"
#include "render/tracer.hpp"

namespace lumen::render {
namespace {

struct Block {
    int left, top, right, bottom;
};

// Blocks of block_size pixels on a grid from the image's top-left corner, cut by the render
// area: anti-aliasing compares a pixel with its neighbours inside its block, so a partial
// render (a farm's tile, cut on this grid) gives each pixel the value the whole render does.
std::vector<Block> make_blocks(int x0, int y0, int x1, int y1, int size) {
    std::vector<Block> blocks;
    const auto next = [size](int v) { return (v / size + 1) * size; };
    for (int top = y0; top <= y1; top = next(top))
        for (int left = x0; left <= x1; left = next(left))
            blocks.push_back({left, top, std::min(x1, next(left) - 1), std::min(y1, next(top) - 1)});
    return blocks;
}

}  // namespace

PixelArea render_area(const RenderOptions& options) {
    return {std::clamp(options.start_col, 0, options.width - 1),
            std::clamp(options.start_row, 0, options.height - 1),
            options.end_col < 0 ? options.width - 1 : std::min(options.end_col, options.width - 1),
            options.end_row < 0 ? options.height - 1 : std::min(options.end_row, options.height - 1)};
}

bool covers_whole_image(const RenderOptions& options) {
    const PixelArea a = render_area(options);
    return a.x0 == 0 && a.y0 == 0 && a.x1 == options.width - 1 && a.y1 == options.height - 1;
}

int effective_block_size(const RenderOptions& options) {
    return std::clamp(options.block_size, 4, std::max({4, options.width, options.height}));
}

Image render(const scene::Scene& scene, const RenderOptions& options, RenderStats* stats,
             const Progress& progress, const BlockDone& block_done) {
    const auto started = std::chrono::steady_clock::now();
    const RenderFrame frame(scene);
    Image image = render(frame, options, stats, progress, block_done);
    // The frame's compile time counts, as it did before frames.
    if (stats) stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return image;
}

Image render(const RenderFrame& frame, const RenderOptions& options, RenderStats* stats,
             const Progress& progress, const BlockDone& block_done) {
    const auto started = std::chrono::steady_clock::now();
    const scene::Scene& scene = frame.scene();
    if (options.width <= 0 || options.height <= 0)
        throw LumenError({}, "image size must be positive");
    TraceOptions trace_options;
    trace_options.quality = options.quality;
    trace_options.alpha = options.alpha;
    trace_options.indirect = options.indirect;
    // The photon pass before the first pixel (POV-Ray shoots before it renders).
    const std::unique_ptr<PhotonPass> photons = shoot_photons(frame, options.threads);
    trace_options.photons = photons.get();
    const Tracer tracer(frame, trace_options);
    const CameraModel camera(scene.camera, options.width, options.height);
    const BlockRenderer blocks_renderer(tracer, camera, options,
                                        colour_compare_for(scene, options.aa_gamma));

    Image image;
    image.width = options.width;
    image.height = options.height;
    const PixelArea area = render_area(options);
    const auto [x0, y0, x1, y1] = area;
    // The blocks write every pixel of the render area, so only a partial render needs zeroes
    // (zeroing 9.6 MB at 800x600 first took its page faults on one thread), and only when the
    // caller reads the image rather than the blocks (a farm's 3840x2160 tile spent most of its
    // time zeroing 166 MB).
    if (covers_whole_image(options) || block_done)
        image.pixels.resize(size_t(image.width) * image.height * 5);
    else
        image.pixels.assign(size_t(image.width) * image.height * 5, 0.0f);
    if (x1 < x0 || y1 < y0) return image;

    const int block_size = effective_block_size(options);
    const std::vector<Block> blocks = make_blocks(x0, y0, x1, y1, block_size);

    unsigned threads = options.threads > 0 ? unsigned(options.threads)
                                           : std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(blocks.size()));

    std::atomic<size_t> next{0};
    std::mutex progress_mutex;
    size_t finished = 0;
    RenderStats total;
    std::exception_ptr failure;

    auto worker = [&](unsigned id) {
        ThreadState state;
        state.rng.seed(12345 + id);
        uint64_t primary = 0;
        try {
            for (size_t b = next++; b < blocks.size(); b = next++) {
                const Block& k = blocks[b];
                blocks_renderer.render(k.left, k.top, k.right, k.bottom, image, state, primary);
                if (block_done) block_done(image, k.left, k.top, k.right, k.bottom);
                std::lock_guard lock(progress_mutex);
                ++finished;
                if (progress) progress(double(finished) / blocks.size());
            }
        } catch (...) {
            std::lock_guard lock(progress_mutex);
            if (!failure) failure = std::current_exception();
            next = blocks.size();
        }
        std::lock_guard lock(progress_mutex);
        total.primary_rays += primary;
        total.total_rays += state.counters.rays;
        total.shadow_rays += state.counters.shadow_rays;
    };

    if (threads <= 1) {
        worker(0);
    } else {
        std::vector<std::thread> pool;
        for (unsigned i = 0; i < threads; ++i) pool.emplace_back(worker, i);
        for (std::thread& t : pool) t.join();
    }
    if (failure) std::rethrow_exception(failure);

    total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (photons) {
        total.photons_shot = photons->shot;
        total.photons_stored = photons->surface.size();
        total.media_photons_stored = photons->media.size();
    }
    if (stats) *stats = total;
    return image;
}

}  // namespace lumen::render

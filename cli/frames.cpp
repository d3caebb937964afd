#include "cli/frames.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace lumen::cli {
namespace {

// POV hands numbers to the scene through 32-bit floats; the derived identifiers are also
// printed with 6 significant digits on the way (clock_delta = 0.333333).
double through_float(double v) { return double(float(v)); }
double through_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(float(v)));
    return std::strtod(buf, nullptr);
}

}  // namespace

bool is_animation(const Options& o) { return o.final_frame > o.initial_frame; }

std::string extension_for(render::FileType type) {
    switch (type) {
        case render::FileType::PNG: return ".png";
        case render::FileType::EXR: return ".exr";
        case render::FileType::HDR: return ".hdr";
        case render::FileType::TIFF: return ".tif";
        case render::FileType::PPM: return ".ppm";
    }
    return ".png";
}

std::string output_path(const Options& o, int frame) {
    namespace fs = std::filesystem;
    fs::path p;
    if (o.output.empty() || o.output.back() == '/') {
        p = fs::path(o.output) / fs::path(o.input).stem();
        p += extension_for(o.image.type);
    } else {
        p = o.output;
        if (!p.has_extension()) p += extension_for(o.image.type);
    }
    if (!is_animation(o)) return p.string();
    const int digits = int(std::to_string(std::abs(o.final_frame)).size());
    char num[32];
    std::snprintf(num, sizeof num, "%0*d", digits, frame);
    fs::path numbered = p.parent_path() / p.stem();
    numbered += num;
    numbered += p.extension();
    return numbered.string();
}

std::vector<Frame> plan_frames(const Options& o) {
    interp::InterpOptions base = o.scene;
    base.image_width = o.render.width;
    base.image_height = o.render.height;
    base.initial_frame = o.initial_frame;
    base.final_frame = o.final_frame;
    base.initial_clock = through_text(o.initial_clock);
    base.final_clock = through_text(o.final_clock);

    std::vector<Frame> frames;
    if (!is_animation(o)) {
        Frame f;
        f.scene = base;
        f.scene.clock = through_float(o.clock);
        f.output = o.output_to_file ? output_path(o, 0) : std::string();
        frames.push_back(std::move(f));
        return frames;
    }
    // Cyclic animations leave out the last clock value, which would repeat the first frame.
    const int steps = o.final_frame - o.initial_frame + (o.cyclic ? 1 : 0);
    const double delta = (o.final_clock - o.initial_clock) / steps;
    const int first = std::max(o.initial_frame, o.subset_start.value_or(o.initial_frame));
    const int last = std::min(o.final_frame, o.subset_end.value_or(o.final_frame));
    for (int n = first; n <= last; ++n) {
        Frame f;
        f.number = n;
        f.scene = base;
        f.scene.clock_on = true;
        f.scene.frame_number = n;
        f.scene.clock_delta = through_text(delta);
        f.scene.clock = through_float(o.initial_clock +
                                      (n - o.initial_frame) * (o.final_clock - o.initial_clock) / steps);
        f.output = o.output_to_file ? output_path(o, n) : std::string();
        frames.push_back(std::move(f));
    }
    return frames;
}

}  // namespace lumen::cli

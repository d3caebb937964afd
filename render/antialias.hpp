// Rendering one block of pixels, with POV-Ray's anti-aliasing methods:
// none (one ray through each pixel centre), AM1 (non-recursive adaptive, block framed) and
// AM2 (recursive adaptive over pixel corners), with POV's jitter (render/jitter.hpp). Blocks are
// independent, so the image does not depend on the thread count or block order.
#pragma once
#include <vector>

#include <glm/vec4.hpp>

#include "render/camera.hpp"
#include "render/focal_blur.hpp"
#include "render/render.hpp"
#include "render/tracer.hpp"

namespace lumen::render {

// A sample: working-space rgb (unclipped) and transmit.
struct Sample {
    glm::dvec3 rgb{0};
    double t = 0;
};

// How colours are compared for anti-aliasing: through c^(1/aa_gamma) of linear values.
struct ColourCompare {
    double decode_gamma = 1.0;  // working -> linear power; 0 = sRGB curve (legacy scenes)
    double aa_gamma = 2.5;
    double difference(const Sample& a, const Sample& b) const;
    // The compared form of a sample (encoded rgb, t): encode each sample once, compare many times.
    glm::dvec4 encode(const Sample& s) const;
    static double difference(const glm::dvec4& a, const glm::dvec4& b);
};
ColourCompare colour_compare_for(const scene::Scene& scene, double aa_gamma);

class BlockRenderer {
public:
    BlockRenderer(const Tracer& tracer, const CameraModel& camera, const RenderOptions& options,
                  const ColourCompare& compare);

    // Renders pixels [left..right] × [top..bottom] (inclusive) into `image`.
    void render(int left, int top, int right, int bottom, Image& image, ThreadState& state,
                uint64_t& primary_rays) const;

private:
    Sample sample(double x, double y, ThreadState& state, uint64_t& primary_rays) const;
    Sample blurred_sample(double x, double y, ThreadState& state, uint64_t& primary_rays) const;
    void render_plain(int left, int top, int right, int bottom, Image& image, ThreadState& state,
                      uint64_t& primary_rays) const;
    void render_am1(int left, int top, int right, int bottom, Image& image, ThreadState& state,
                    uint64_t& primary_rays) const;
    void render_am2(int left, int top, int right, int bottom, Image& image, ThreadState& state,
                    uint64_t& primary_rays) const;
    Sample supersample(double px, double py, const Sample& centre, ThreadState& state,
                       uint64_t& primary_rays) const;

    const Tracer& tracer_;
    const CameraModel& camera_;
    std::optional<FocalBlur> focal_blur_;
    RenderOptions options_;
    ColourCompare compare_;
};

}  // namespace lumen::render

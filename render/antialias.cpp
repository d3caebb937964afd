#include "render/antialias.hpp"

#include <algorithm>
#include <cmath>

#include "base/stop_request.hpp"
#include "render/jitter.hpp"

namespace lumen::render {
namespace {

void put(Image& image, int x, int y, const Sample& s) {
    float* p = image.at(x, y);
    p[0] = float(s.rgb.x);
    p[1] = float(s.rgb.y);
    p[2] = float(s.rgb.z);
    p[3] = 0;
    p[4] = float(s.t);
}

double srgb_decode(double v) {
    return v < 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace

glm::dvec4 ColourCompare::encode(const Sample& s) const {
    auto e = [&](double v) {
        double lin = v;
        if (decode_gamma == 0)
            lin = srgb_decode(v);
        else if (decode_gamma != 1)
            lin = v > 0 ? std::pow(v, decode_gamma) : v;
        return lin > 0 ? std::pow(lin, 1.0 / aa_gamma) : 0.0;
    };
    return {e(s.rgb.x), e(s.rgb.y), e(s.rgb.z), s.t};
}

double ColourCompare::difference(const glm::dvec4& a, const glm::dvec4& b) {
    return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z) +
           std::fabs(a.w - b.w);
}

double ColourCompare::difference(const Sample& a, const Sample& b) const {
    return difference(encode(a), encode(b));
}

ColourCompare colour_compare_for(const scene::Scene& scene, double aa_gamma) {
    ColourCompare c;
    c.aa_gamma = aa_gamma > 0 ? aa_gamma : 2.5;
    if (scene.globals.assumed_gamma)
        c.decode_gamma = *scene.globals.assumed_gamma;
    else if (scene.language_version < 3.7)
        c.decode_gamma = 0;  // legacy: working gamma = display gamma (sRGB)
    return c;
}

BlockRenderer::BlockRenderer(const Tracer& tracer, const CameraModel& camera,
                             const RenderOptions& options, const ColourCompare& compare)
    : tracer_(tracer), camera_(camera), options_(options), compare_(compare) {
    if (camera.camera().blur && !camera.camera().mesh) focal_blur_.emplace(camera.camera());
}

// Focal blur: rays from the aperture in batches until the colour is settled (POV-Ray's
// rule); a ray the projection does not have counts as black, fully transparent.
Sample BlockRenderer::blurred_sample(double x, double y, ThreadState& state,
                                     uint64_t& primary_rays) const {
    const FocalBlur& blur = *focal_blur_;
    double s1[4] = {0, 0, 0, 0}, s2[4] = {0, 0, 0, 0};
    int n = 0;
    while (n < blur.max_samples()) {
        const std::optional<Ray> ray = blur.ray(camera_, x, y, n);
        double c[4] = {0, 0, 0, 1};
        if (ray) {
            ++primary_rays;
            const RayColour rc = tracer_.trace_primary(*ray, state);
            c[0] = rc.rgb.x, c[1] = rc.rgb.y, c[2] = rc.rgb.z, c[3] = rc.transmit;
        }
        for (int k = 0; k < 4; ++k) s1[k] += c[k], s2[k] += c[k] * c[k];
        const bool batch_end = blur.batch_ends(n);
        ++n;
        if (batch_end && blur.settled(n, s1, s2)) break;
    }
    return {glm::dvec3(s1[0], s1[1], s1[2]) / double(n), s1[3] / n};
}

Sample BlockRenderer::sample(double x, double y, ThreadState& state,
                             uint64_t& primary_rays) const {
    throw_if_stop_requested();  // SIGINT/SIGTERM: the render unwinds within a sample
    state.reseed(x, y);
    if (focal_blur_) return blurred_sample(x, y, state, primary_rays);
    const int rays = camera_.rays_per_sample();
    if (rays == 1) {
        ++primary_rays;
        const std::optional<Ray> ray = camera_.ray(x, y);
        if (!ray) return {glm::dvec3(0), 1.0};  // no ray: black, fully transparent (POV)
        const RayColour c = tracer_.trace_primary(*ray, state);
        return {c.rgb, c.transmit};
    }
    // A mesh camera's rays: their average over those shot.
    Sample sum{glm::dvec3(0), 0.0};
    int shot = 0;
    for (int k = 0; k < rays; ++k) {
        const std::optional<Ray> ray = camera_.ray(x, y, k);
        if (!ray) continue;
        ++primary_rays, ++shot;
        const RayColour c = tracer_.trace_primary(*ray, state);
        sum.rgb += c.rgb;
        sum.t += c.transmit;
    }
    if (shot == 0) return {glm::dvec3(0), 1.0};
    return {sum.rgb / double(shot), sum.t / shot};
}

void BlockRenderer::render(int left, int top, int right, int bottom, Image& image,
                           ThreadState& state, uint64_t& primary_rays) const {
    ++state.block;
    if (!options_.antialias)
        render_plain(left, top, right, bottom, image, state, primary_rays);
    else if (options_.aa_method == 2)
        render_am2(left, top, right, bottom, image, state, primary_rays);
    else
        render_am1(left, top, right, bottom, image, state, primary_rays);
}

void BlockRenderer::render_plain(int left, int top, int right, int bottom, Image& image,
                                 ThreadState& state, uint64_t& primary_rays) const {
    for (int y = top; y <= bottom; ++y)
        for (int x = left; x <= right; ++x) put(image, x, y, sample(x, y, state, primary_rays));
}

Sample BlockRenderer::supersample(double px, double py, const Sample& centre, ThreadState& state,
                                  uint64_t& primary_rays) const {
    const int n = std::clamp(options_.aa_depth, 1, 9);
    const double step = 1.0 / n;
    const double amount = options_.jitter ? options_.jitter_amount : 0.0;
    Sample sum = centre;
    for (int j = 0; j < n; ++j) {
        const double oy = -(0.5 - step / 2) + j * step;
        for (int i = 0; i < n; ++i) {
            const double ox = -(0.5 - step / 2) + i * step;
            double sx = px + ox, sy = py + oy;
            if (amount > 0) {
                double jx, jy;
                jitter2d(sx, sy, jx, jy);
                sx += jx * amount / n;
                sy += jy * amount / n;
            }
            const Sample s = sample(sx, sy, state, primary_rays);
            sum.rgb += s.rgb;
            sum.t += s.t;
        }
    }
    const double k = 1.0 / (n * n + 1);
    return {sum.rgb * k, sum.t * k};
}

// AM1: the block is framed by the row above and the column to its left, traced once and never
// supersampled; a pixel is supersampled when it differs from its left or top neighbour.
void BlockRenderer::render_am1(int left, int top, int right, int bottom, Image& image,
                               ThreadState& state, uint64_t& primary_rays) const {
    const int w = right - left + 2, h = bottom - top + 2;  // plus the frame
    std::vector<Sample> value(size_t(w) * h);
    std::vector<unsigned char> done(size_t(w) * h, 0);
    auto idx = [&](int x, int y) { return size_t(y - top + 1) * w + (x - left + 1); };
    const double thr = options_.aa_threshold;
    // Each value's compared form, kept in step with it (a pixel is compared twice or more).
    std::vector<glm::dvec4> coded(size_t(w) * h);
    auto set = [&](size_t i, const Sample& s) {
        value[i] = s;
        coded[i] = compare_.encode(s);
    };

    for (int x = left; x <= right; ++x) {
        set(idx(x, top - 1), sample(x, top - 1, state, primary_rays));
        done[idx(x, top - 1)] = 1;
    }
    for (int y = top; y <= bottom; ++y) {
        set(idx(left - 1, y), sample(left - 1, y, state, primary_rays));
        done[idx(left - 1, y)] = 1;
        for (int x = left; x <= right; ++x) {
            const Sample c = sample(x, y, state, primary_rays);
            set(idx(x, y), c);
            const glm::dvec4 cc = coded[idx(x, y)];
            const bool ld = ColourCompare::difference(coded[idx(x - 1, y)], cc) >= thr;
            const bool td = ColourCompare::difference(coded[idx(x, y - 1)], cc) >= thr;
            if (ld && !done[idx(x - 1, y)]) {
                set(idx(x - 1, y), supersample(x - 1, y, value[idx(x - 1, y)], state, primary_rays));
                done[idx(x - 1, y)] = 1;
            }
            if (td && !done[idx(x, y - 1)]) {
                set(idx(x, y - 1), supersample(x, y - 1, value[idx(x, y - 1)], state, primary_rays));
                done[idx(x, y - 1)] = 1;
            }
            if (ld || td) {
                set(idx(x, y), supersample(x, y, c, state, primary_rays));
                done[idx(x, y)] = 1;
            }
        }
    }
    for (int y = top; y <= bottom; ++y)
        for (int x = left; x <= right; ++x) put(image, x, y, value[idx(x, y)]);
}

// AM2: every pixel starts from its four corner rays and subdivides where they differ.
void BlockRenderer::render_am2(int left, int top, int right, int bottom, Image& image,
                               ThreadState& state, uint64_t& primary_rays) const {
    const int depth = std::clamp(options_.aa_depth, 1, 9);
    const int cells = 1 << (depth - 1);  // sub-grid cells per pixel side
    const int grid = cells + 1;
    const double amount = options_.jitter ? options_.jitter_amount : 0.0;
    const double jitter_scale = amount / ((1 << depth) + 1);
    const double thr = options_.aa_threshold;

    const int cw = right - left + 2;
    std::vector<Sample> corners(size_t(cw) * (bottom - top + 2));
    for (int y = top; y <= bottom + 1; ++y)
        for (int x = left; x <= right + 1; ++x)
            corners[size_t(y - top) * cw + (x - left)] =
                sample(x - 0.5, y - 0.5, state, primary_rays);

    std::vector<Sample> sub(size_t(grid) * grid);
    std::vector<unsigned char> have(size_t(grid) * grid);
    for (int y = top; y <= bottom; ++y) {
        for (int x = left; x <= right; ++x) {
            std::fill(have.begin(), have.end(), 0);
            auto corner = [&](int cx, int cy) { return corners[size_t(cy - top) * cw + (cx - left)]; };
            sub[0] = corner(x, y);
            sub[cells] = corner(x + 1, y);
            sub[size_t(cells) * grid] = corner(x, y + 1);
            sub[size_t(cells) * grid + cells] = corner(x + 1, y + 1);
            have[0] = have[cells] = have[size_t(cells) * grid] = have[size_t(cells) * grid + cells] = 1;
            auto at = [&](int gi, int gj) -> const Sample& {
                const size_t k = size_t(gj) * grid + gi;
                if (!have[k]) {
                    double sx = x - 0.5 + double(gi) / cells, sy = y - 0.5 + double(gj) / cells;
                    if (jitter_scale > 0) {
                        double jx, jy;
                        jitter2d(sx, sy, jx, jy);
                        sx += jx * jitter_scale;
                        sy += jy * jitter_scale;
                    }
                    sub[k] = sample(sx, sy, state, primary_rays);
                    have[k] = 1;
                }
                return sub[k];
            };
            // Cell [i0..i1]×[j0..j1] of the sub-grid, with `level` subdivisions left.
            auto subdivide = [&](auto&& self, int i0, int j0, int i1, int j1, int level) -> Sample {
                const Sample a = at(i0, j0), b = at(i1, j0), c = at(i0, j1), d = at(i1, j1);
                const bool split =
                    level > 0 && (compare_.difference(a, b) >= thr || compare_.difference(a, c) >= thr ||
                                  compare_.difference(a, d) >= thr || compare_.difference(b, c) >= thr ||
                                  compare_.difference(b, d) >= thr || compare_.difference(c, d) >= thr);
                if (!split)
                    return {(a.rgb + b.rgb + c.rgb + d.rgb) * 0.25, (a.t + b.t + c.t + d.t) * 0.25};
                const int im = (i0 + i1) / 2, jm = (j0 + j1) / 2;
                const Sample q[4] = {self(self, i0, j0, im, jm, level - 1),
                                     self(self, im, j0, i1, jm, level - 1),
                                     self(self, i0, jm, im, j1, level - 1),
                                     self(self, im, jm, i1, j1, level - 1)};
                return {(q[0].rgb + q[1].rgb + q[2].rgb + q[3].rgb) * 0.25,
                        (q[0].t + q[1].t + q[2].t + q[3].t) * 0.25};
            };
            put(image, x, y, subdivide(subdivide, 0, 0, cells, cells, depth - 1));
        }
    }
}

}  // namespace lumen::render

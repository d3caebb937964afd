#include "tests/differential/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace lumen::differential {
namespace {

struct Rgb8 {
    int width = 0, height = 0;
    std::vector<unsigned char> pixels;  // 3 per pixel
};

Rgb8 load_rgb8(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image " + path);
    const OIIO::ImageSpec& spec = in->spec();
    Rgb8 img{spec.width, spec.height, {}};
    std::vector<unsigned char> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data()))
        throw std::runtime_error("cannot decode image " + path);
    img.pixels.resize(size_t(spec.width) * spec.height * 3);
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c)
            img.pixels[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return img;
}

// Heat-map colour for a difference in levels: black, red, yellow, white.
void heat_colour(int diff, unsigned char* out) {
    const double t = std::min(1.0, diff / 64.0);
    out[0] = (unsigned char)std::lround(255 * std::min(1.0, t * 3));
    out[1] = (unsigned char)std::lround(255 * std::clamp(t * 3 - 1, 0.0, 1.0));
    out[2] = (unsigned char)std::lround(255 * std::clamp(t * 3 - 2, 0.0, 1.0));
    if (diff > 0 && out[0] < 60) out[0] = 60;  // keep single-level differences visible
}

void write_rgb8(const std::string& path, int w, int h, const std::vector<unsigned char>& px) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error("cannot write image " + path);
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, px.data()))
        throw std::runtime_error("cannot write image " + path);
    out->close();
}

int largest_channel(const Rgb8& img, int x, int y) {
    const unsigned char* p = &img.pixels[(size_t(y) * img.width + x) * 3];
    return std::max({p[0], p[1], p[2]});
}

int dark_where_lit(const Rgb8& reference, const Rgb8& candidate) {
    int count = 0;
    for (int y = 1; y + 1 < reference.height; ++y)
        for (int x = 1; x + 1 < reference.width; ++x) {
            if (largest_channel(candidate, x, y) > 4) continue;
            bool lit = true;
            for (int dy = -1; dy <= 1 && lit; ++dy)
                for (int dx = -1; dx <= 1 && lit; ++dx)
                    lit = largest_channel(reference, x + dx, y + dy) >= 32;
            count += lit;
        }
    return count;
}

}  // namespace

Comparison compare_images(const std::string& reference, const std::string& candidate,
                          const std::string& heat_map_path) {
    const Rgb8 a = load_rgb8(reference), b = load_rgb8(candidate);
    if (a.width != b.width || a.height != b.height)
        throw std::runtime_error("image sizes differ: " + std::to_string(a.width) + "x" +
                                 std::to_string(a.height) + " vs " + std::to_string(b.width) +
                                 "x" + std::to_string(b.height));
    Comparison c{a.width, a.height};
    std::vector<unsigned char> heat(a.pixels.size());
    double squared = 0, absolute = 0;
    size_t differing = 0;
    const size_t n = size_t(a.width) * a.height;
    for (size_t p = 0; p < n; ++p) {
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) {
            const int d = std::abs(int(a.pixels[p * 3 + ch]) - int(b.pixels[p * 3 + ch]));
            squared += double(d) * d;
            absolute += d;
            worst = std::max(worst, d);
        }
        c.max_error = std::max(c.max_error, worst);
        differing += worst > 0;
        heat_colour(worst, &heat[p * 3]);
    }
    const double mse = squared / double(n * 3);
    c.psnr = mse == 0 ? std::numeric_limits<double>::infinity()
                      : 10 * std::log10(255.0 * 255.0 / mse);
    c.differing_fraction = double(differing) / double(n);
    c.mean_error = absolute / 255.0 / double(n * 3);
    c.dark_where_lit = dark_where_lit(a, b);
    write_rgb8(heat_map_path, a.width, a.height, heat);
    return c;
}

}  // namespace lumen::differential

// Output encoding (povray-semantics.md §2), then the file through image_files.hpp.
#include "render/image_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parser/diagnostics.hpp"
#include "render/image_files.hpp"

namespace lumen::render {
namespace {

// How working-space values become file values.
struct Encoding {
    bool identity = false;      // legacy scene: bytes are the working values
    double decode_gamma = 1.0;  // working -> linear power (assumed_gamma)
    double file_gamma = -1.0;   // <= 0: sRGB curve
};

Encoding encoding_for(const scene::Scene& scene, const OutputOptions& options) {
    Encoding e;
    e.file_gamma = options.file_gamma;
    if (scene.globals.assumed_gamma) {
        e.decode_gamma = *scene.globals.assumed_gamma;
    } else if (scene.language_version < 3.7) {
        // No #version (3.62) and no assumed_gamma: gamma handling is off entirely.
        e.identity = true;
    }
    return e;
}

// POV evaluates these transfer curves in single precision; double differs by one level
// in rare pixels.
float srgb_encode(float v) {
    if (v <= 0.0031308f) return 12.92f * v;
    return 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float to_linear(float v, const Encoding& e) {
    if (e.identity || e.decode_gamma == 1.0) return v;
    return v > 0 ? std::pow(v, float(e.decode_gamma)) : v;
}

// Working value -> encoded file value in [0,1] (before quantisation), unclipped.
float encode(float v, const Encoding& e) {
    if (e.identity) return v;
    const float lin = to_linear(v, e);
    if (e.file_gamma <= 0) return srgb_encode(lin);
    if (e.file_gamma == 1.0) return lin;
    return lin > 0 ? std::pow(lin, float(1.0 / e.file_gamma)) : lin;
}

double quantise(float encoded, int maxval) {
    const double c = std::clamp(double(encoded), 0.0, 1.0);
    return std::floor(c * maxval + 0.5);
}

const char* extension(FileType type) {
    switch (type) {
        case FileType::PNG: return ".png";
        case FileType::EXR: return ".exr";
        case FileType::HDR: return ".hdr";
        case FileType::TIFF: return ".tif";
        case FileType::PPM: return ".ppm";
    }
    return ".png";
}

bool is_float_format(FileType type) { return type == FileType::EXR || type == FileType::HDR; }

// Float formats get linear light; integer formats the quantised levels 0..maxval.
EncodedImage prepare_pixels(const Image& image, const Encoding& e, const OutputOptions& o,
                            int channels, int maxval) {
    const bool floating = is_float_format(o.type);
    EncodedImage out;
    out.width = image.width;
    out.height = image.height;
    out.channels = channels;
    out.maxval = floating ? 0 : maxval;
    out.curve = e.identity ? EncodedImage::Curve::Unlabelled
                : e.file_gamma <= 0 ? EncodedImage::Curve::SRGB
                                    : EncodedImage::Curve::Power;
    out.file_gamma = e.file_gamma;
    out.values.resize(size_t(image.width) * image.height * channels);
    // Rows [y0, y1): the transfer curves cost a pow per channel, so bands run in parallel.
    auto encode_rows = [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const float* p = image.at(x, y);
                float* q = &out.values[(size_t(y) * image.width + x) * channels];
                const float alpha = std::clamp(1.0f - p[4], 0.0f, 1.0f);
                for (int c = 0; c < 3; ++c) {
                    float v = p[c];
                    // The buffer holds premultiplied colour; straight alpha files need it undone.
                    if (o.alpha && !floating && alpha > 0) v /= alpha;
                    if (floating)
                        q[c] = e.identity ? v : to_linear(v, e);
                    else
                        q[c] = float(quantise(encode(v, e), maxval));
                }
                if (channels == 4) q[3] = floating ? alpha : float(quantise(alpha, maxval));
            }
        }
    };
    const int bands = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    std::vector<std::thread> helpers;
    for (int b = 1; b < bands; ++b)
        helpers.emplace_back(encode_rows, image.height * b / bands, image.height * (b + 1) / bands);
    encode_rows(0, image.height / bands);
    for (std::thread& t : helpers) t.join();
    return out;
}

}  // namespace

int encode_8bit(double v, const scene::Scene& scene, const OutputOptions& options) {
    return int(quantise(encode(float(v), encoding_for(scene, options)), 255));
}

void write_image(const Image& image, const scene::Scene& scene, const OutputOptions& options,
                 const std::string& path) {
    namespace fs = std::filesystem;

    const Encoding e = encoding_for(scene, options);
    const int channels = options.alpha ? 4 : 3;
    const bool sixteen = !is_float_format(options.type) && options.bits > 8 &&
                         (options.type == FileType::PNG || options.type == FileType::TIFF ||
                          options.type == FileType::PPM);
    const EncodedImage pixels = prepare_pixels(image, e, options, channels, sixteen ? 65535 : 255);

    const fs::path target(path);
    fs::path tmp = target;
    tmp.replace_filename("." + target.filename().string() + ".lumen-tmp" + extension(options.type));

    try {
        switch (options.type) {
            case FileType::PNG: write_png(pixels, tmp.string()); break;
            case FileType::PPM: write_ppm(pixels, tmp.string()); break;
            case FileType::EXR: write_with_oiio(pixels, "openexr", tmp.string()); break;
            case FileType::HDR: write_with_oiio(pixels, "hdr", tmp.string()); break;
            case FileType::TIFF: write_with_oiio(pixels, "tiff", tmp.string()); break;
        }
    } catch (const std::runtime_error& failure) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw LumenError({}, "cannot write '" + path + "': " + failure.what());
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw LumenError({}, "cannot rename the image to '" + path + "': " + ec.message());
    }
}

}  // namespace lumen::render

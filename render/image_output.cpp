// Output encoding (POV-Ray 3.7's rules), then the file through image_files.hpp.
#include "render/image_output.hpp"

#include <algorithm>
#include <cmath>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "base/diagnostics.hpp"
#include "render/image_files.hpp"
#include "render/level_table.hpp"

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
float encode_value(float v, const Encoding& e) {
    if (e.identity) return v;
    const float lin = to_linear(v, e);
    if (e.file_gamma <= 0) return srgb_encode(lin);
    if (e.file_gamma == 1.0) return lin;
    return lin > 0 ? std::pow(lin, float(1.0 / e.file_gamma)) : lin;
}

// In single precision too, as POV: 0.9 * 255 rounds to 229.5 in float and so to level 230.
double quantise(float encoded, int maxval) {
    const float c = std::clamp(encoded, 0.0f, 1.0f);
    return std::floor(c * float(maxval) + 0.5f);
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

std::filesystem::path temporary_path(const std::string& path, FileType type) {
    const std::filesystem::path target(path);
    std::filesystem::path tmp = target;
    tmp.replace_filename("." + target.filename().string() + ".lumen-tmp" + extension(type));
    return tmp;
}

// Renames the written temporary file to `path`, or removes it when writing failed.
void finish_file(const std::filesystem::path& tmp, const std::string& path,
                 const std::string& failure) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!failure.empty()) {
        fs::remove(tmp, ec);
        throw LumenError({}, "cannot write '" + path + "': " + failure);
    }
    fs::rename(tmp, fs::path(path), ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw LumenError({}, "cannot rename the image to '" + path + "': " + ec.message());
    }
}

}  // namespace

int encode_8bit(double v, const scene::Scene& scene, const OutputOptions& options) {
    return int(quantise(encode_value(float(v), encoding_for(scene, options)), 255));
}

struct ImageEncoder::Impl {
    Encoding encoding;
    OutputOptions options;
    bool floating = false;
    std::optional<LevelTable> levels;  // 8-bit files: the level of a positive value
    EncodedImage out;  // float formats get linear light; integer ones levels 0..maxval
    int origin_x = 0, origin_y = 0;  // the rendered pixel at out's top-left (set_origin)

    // Streaming (stream_to): pixels encoded per row; the writer thread takes row y once
    // row_pixels[y] reaches the width (acquire pairs with the encoders' release).
    std::unique_ptr<std::atomic<int>[]> row_pixels;
    std::mutex mutex;
    std::condition_variable row_done;
    bool abandoned = false;  // under mutex
    std::thread writer;
    std::string failure;  // the writer's error, read after join
    std::filesystem::path tmp;

    const uint8_t* wait_for_row(int y, std::vector<uint8_t, DefaultInit<uint8_t>>& bytes) {
        std::unique_lock lock(mutex);
        row_done.wait(lock, [&] { return abandoned || row_pixels[y].load(std::memory_order_acquire) == out.width; });
        if (abandoned) throw std::runtime_error("abandoned");
        lock.unlock();
        png_sample_bytes(out, y, bytes.data());
        return bytes.data();
    }
    void stop_writer() {
        if (!writer.joinable()) return;
        {
            std::lock_guard lock(mutex);
            abandoned = true;
        }
        row_done.notify_all();
        writer.join();
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
    }
};

ImageEncoder::ImageEncoder(const scene::Scene& scene, const OutputOptions& options, int width,
                           int height)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.encoding = encoding_for(scene, options);
    m.options = options;
    m.floating = is_float_format(options.type);
    const bool sixteen = !m.floating && options.bits > 8 &&
                         (options.type == FileType::PNG || options.type == FileType::TIFF ||
                          options.type == FileType::PPM);
    EncodedImage& out = m.out;
    out.width = width;
    out.height = height;
    out.channels = options.alpha ? 4 : 3;
    out.maxval = m.floating ? 0 : sixteen ? 65535 : 255;
    out.curve = m.encoding.identity         ? EncodedImage::Curve::Unlabelled
                : m.encoding.file_gamma <= 0 ? EncodedImage::Curve::SRGB
                                             : EncodedImage::Curve::Power;
    out.file_gamma = m.encoding.file_gamma;
    out.values.resize(size_t(width) * height * out.channels);
    if (out.maxval == 255) {
        auto level = [e = m.encoding](float v) { return int(quantise(encode_value(v, e), 255)); };
        if (level(std::numeric_limits<float>::infinity()) == 255) m.levels.emplace(level);
    }
}

ImageEncoder::~ImageEncoder() { impl_->stop_writer(); }

void ImageEncoder::stream_to(const std::string& path) {
    Impl& m = *impl_;
    if (m.options.type != FileType::PNG || m.writer.joinable() || m.out.height <= 0) return;
    m.row_pixels = std::make_unique<std::atomic<int>[]>(size_t(m.out.height));
    m.tmp = temporary_path(path, m.options.type);
    m.writer = std::thread([&m] {
        std::vector<uint8_t, DefaultInit<uint8_t>> bytes(png_row_bytes(m.out));
        try {
            write_png_rows(m.out, [&](int y) { return m.wait_for_row(y, bytes); }, m.tmp.string());
        } catch (const std::exception& e) {
            m.failure = e.what();
        }
    });
}

void ImageEncoder::set_origin(int x, int y) {
    impl_->origin_x = x;
    impl_->origin_y = y;
}

void ImageEncoder::clear_outside(int left, int top, int right, int bottom) {
    EncodedImage& out = impl_->out;
    const size_t row = size_t(out.width) * out.channels, c = size_t(out.channels);
    float* v = out.values.data();
    for (int y = 0; y < out.height; ++y) {
        float* r = v + size_t(y) * row;
        if (y < top || y > bottom) {
            std::fill(r, r + row, 0.0f);
            continue;
        }
        std::fill(r, r + size_t(std::max(0, left)) * c, 0.0f);
        if (right + 1 < out.width) std::fill(r + size_t(right + 1) * c, r + row, 0.0f);
    }
}

void ImageEncoder::encode(const Image& image, int left, int top, int right, int bottom) {
    const Impl& m = *impl_;
    const Encoding& e = m.encoding;
    const int channels = m.out.channels, maxval = m.out.maxval;
    float* values = impl_->out.values.data();
    for (int y = top; y <= bottom; ++y) {
        for (int x = left; x <= right; ++x) {
            const float* p = image.at(x, y);
            float* q = values + (size_t(y - m.origin_y) * m.out.width + (x - m.origin_x)) * channels;
            const float alpha = std::clamp(1.0f - p[4], 0.0f, 1.0f);
            for (int c = 0; c < 3; ++c) {
                float v = p[c];
                // The buffer holds premultiplied colour; straight alpha files need it undone.
                if (m.options.alpha && !m.floating && alpha > 0) v /= alpha;
                if (m.floating)
                    q[c] = e.identity ? v : to_linear(v, e);
                else if (m.levels && v > 0)
                    q[c] = float((*m.levels)(v));
                else
                    q[c] = float(quantise(encode_value(v, e), maxval));
            }
            if (channels == 4) q[3] = m.floating ? alpha : float(quantise(alpha, maxval));
        }
    }
    if (!impl_->row_pixels) return;
    bool any_complete = false;
    for (int y = top; y <= bottom; ++y) {
        const int n = right - left + 1;
        any_complete |= impl_->row_pixels[y - m.origin_y].fetch_add(n, std::memory_order_acq_rel) + n ==
                        m.out.width;
    }
    if (any_complete) {
        { std::lock_guard lock(impl_->mutex); }  // the writer is waiting or will see the count
        impl_->row_done.notify_all();
    }
}

void ImageEncoder::write(const std::string& path) {
    Impl& m = *impl_;
    if (!m.writer.joinable()) {
        write_encoded(m.out, m.options.type, path);
        return;
    }
    m.writer.join();  // every row is encoded by now
    finish_file(m.tmp, path, m.failure);
}

void write_encoded(const EncodedImage& image, FileType type, const std::string& path) {
    const std::filesystem::path tmp = temporary_path(path, type);
    std::string failure;
    try {
        switch (type) {
            case FileType::PNG: write_png(image, tmp.string()); break;
            case FileType::PPM: write_ppm(image, tmp.string()); break;
            case FileType::EXR: write_with_oiio(image, "openexr", tmp.string()); break;
            case FileType::HDR: write_with_oiio(image, "hdr", tmp.string()); break;
            case FileType::TIFF: write_with_oiio(image, "tiff", tmp.string()); break;
        }
    } catch (const std::runtime_error& e) {
        failure = e.what();
    }
    finish_file(tmp, path, failure);
}

void write_image(const Image& image, const scene::Scene& scene, const OutputOptions& options,
                 const std::string& path) {
    ImageEncoder encoder(scene, options, image.width, image.height);
    // Bands on all cores: the transfer curves cost a pow per channel.
    const int bands = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    const int w = image.width, h = image.height;
    std::vector<std::thread> helpers;
    for (int b = 1; b < bands; ++b)
        if (h * b / bands < h * (b + 1) / bands)
            helpers.emplace_back([&, b] {
                encoder.encode(image, 0, h * b / bands, w - 1, h * (b + 1) / bands - 1);
            });
    if (h / bands > 0) encoder.encode(image, 0, 0, w - 1, h / bands - 1);
    for (std::thread& t : helpers) t.join();
    encoder.write(path);
}

}  // namespace lumen::render

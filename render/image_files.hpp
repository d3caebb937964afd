// Image files from encoded pixels: PNG (libpng) and PPM written here, OpenEXR, Radiance HDR
// and TIFF through OpenImageIO, loaded only when one of those is asked for (oiio_module.cpp):
// OIIO pulls in some 260 shared libraries whose start-up would dominate a small render.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/default_init.hpp"

namespace lumen::render {

// Pixels as they go into the file, row-major from the top, `channels` (3 or 4) per pixel.
struct EncodedImage {
    int width = 0, height = 0, channels = 3;
    int maxval = 255;  // integer files: 255 or 65535, values hold levels 0..maxval; 0: float
    std::vector<float, DefaultInit<float>> values;  // every value is written by the encoder
    // How integer levels encode light, for the file's colour metadata.
    enum class Curve { Unlabelled, SRGB, Power } curve = Curve::SRGB;
    double file_gamma = 1.0;  // Curve::Power: levels = linear^(1/file_gamma)
};

// Each writes `path` completely or throws std::runtime_error with the reason (a partial file
// may remain: the caller writes to a temporary name and renames it).
void write_png(const EncodedImage& image, const std::string& path);
// PNG rows as they become available: `rows(y)` returns row y's sample bytes (big-endian for
// 16 bits), valid until the next call, waiting for them if it must; it throws to abandon the
// file. `header` gives the size and format (its values are not read).
using RowSource = std::function<const uint8_t*(int y)>;
void write_png_rows(const EncodedImage& header, const RowSource& rows, const std::string& path);
// Row y of `image` as PNG sample bytes, png_row_bytes(image) of them.
void png_sample_bytes(const EncodedImage& image, int y, uint8_t* out);
size_t png_row_bytes(const EncodedImage& image);
void write_ppm(const EncodedImage& image, const std::string& path);
// format: OpenImageIO's name ("openexr", "hdr", "tiff").
void write_with_oiio(const EncodedImage& image, const char* format, const std::string& path);

}  // namespace lumen::render

// Image files as POV-Ray's image contexts (height_field, image_map, bump_map, image_pattern,
// material_map) read them: the file's samples undecoded, with what the file says about its
// encoding, so each caller applies POV-Ray's value rules itself (image/pov_storage.hpp).
// PNG through libpng, JPEG through libjpeg, PPM/PGM, TGA and GIF here, the rest through
// OpenImageIO, loaded only when such a file is read (image/oiio_module.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace lumen::image {

// POV-Ray's image type keywords (`png "f"`); Pot is GIF data read as 16-bit heights.
enum class Format { Gif, Tga, Iff, Ppm, Pgm, Png, Jpeg, Tiff, Bmp, Exr, Hdr, Sys, Pot };

std::optional<Format> format_from_keyword(std::string_view word);
// From the name's extension, as POV-Ray matches it: all lower or all upper case.
std::optional<Format> format_from_extension(std::string_view path);
const char* format_keyword(Format f);

// What the file says about how its integer samples encode light.
struct FileGamma {
    enum class Kind { Unspecified, SRGB, Power } kind = Kind::Unspecified;
    double gamma = 1;  // Power: the file's gAMA value g (linear = v^(1/g))
};

struct ImageFile {
    int width = 0, height = 0;
    // Samples per pixel in `values` (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA); for a palette
    // image, the channels of its palette entries (3 or 4).
    int channels = 0;
    int bit_depth = 8;      // of one sample in the file (1..16); 32 for floating-point files
    bool floating = false;  // HDR, EXR: linear values, not levels
    // width * height * channels samples, row 0 = the top of the picture, each level / maxval
    // (PPM/PGM levels first brought to 8 or 16 bits as POV-Ray does); empty for a palette image.
    std::vector<float> values;
    std::vector<std::array<float, 4>> palette;  // RGBA, raw; empty when the file has none
    std::vector<uint8_t> indices;               // width * height palette indices
    FileGamma gamma;

    bool has_palette() const { return !palette.empty(); }
    bool has_alpha() const { return has_palette() ? channels == 4 : channels == 2 || channels == 4; }
    bool grey() const { return !has_palette() && channels <= 2; }
    size_t pixels() const { return size_t(width) * size_t(height); }
};

// Unreadable, corrupt or oversized files; the message says why (without the file's name).
struct ImageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The most pixels lumen reads from one image (a guard against absurd headers).
inline constexpr size_t kMaxImagePixels = size_t(1) << 24;  // 4096 x 4096
inline constexpr int kMaxImageSide = 1 << 16;

// Reads `path` as `format` or throws ImageError. Iff and Sys are refused.
ImageFile read_image(const std::string& path, Format format);

// One reader per file family (each throws ImageError).
ImageFile read_png(const std::string& path);
ImageFile read_pnm(const std::string& path);  // P2, P3, P5, P6
ImageFile read_tga(const std::string& path);
ImageFile read_gif(const std::string& path);  // palette entries and indices
ImageFile read_pot(const std::string& path);  // 16-bit grey heights
ImageFile read_jpeg(const std::string& path);  // grey and RGB; CMYK through OpenImageIO
ImageFile read_with_oiio(const std::string& path);  // TIFF, BMP, EXR, HDR, CMYK JPEG

// Throws ImageError unless width x height is a size lumen reads.
void check_image_size(long long width, long long height);

}  // namespace lumen::image

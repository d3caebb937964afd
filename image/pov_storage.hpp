// An image file as POV-Ray 3.7 holds it once read: samples decoded with the context's gamma
// rule, palettes kept as decoded entries plus indices, and 8-bit (and smaller) grey samples
// requantised the way POV-Ray stores them. Every image context (height_field, image_map,
// bump_map, image_pattern, material_map) starts from this.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "image/image_file.hpp"

namespace lumen::image {

// How stored levels become values: raw, v^gamma, or the sRGB curve; then, in a scene whose
// working gamma W is not 1 (assumed_gamma), encoded for it as v^(1/W).
struct Decode {
    enum class Kind { Raw, Power, SRGB } kind = Kind::Raw;
    double gamma = 1;
    double working_gamma = 1;
    float apply(float v) const;
};

// What the file's own sRGB or gAMA chunk says, if it says anything.
std::optional<Decode> file_decode(const ImageFile& file);

// The decoding image_map applies by default in a 3.7 scene (assumed_gamma 1): the file's
// sRGB chunk or gAMA for PNG, sRGB for chunk-less PNG, GIF, TGA, BMP and JPEG, none for
// PPM, PGM, TIFF, HDR and EXR. (Other contexts use raw values unless `gamma` is given.)
Decode default_decode(const ImageFile& file, Format format);

// POV-Ray's grey of a colour, in single precision as it computes it.
inline float pov_grey(float r, float g, float b) {
    return float(float(r * 0.297f) + float(g * 0.589f)) + float(b * 0.114f);
}

struct PovImage {
    int width = 0, height = 0;
    bool palette = false;  // colours holds the decoded entries, indices one per pixel
    bool grey = false;     // one grey value (r = g = b) per pixel
    bool alpha = false;
    bool high_precision = false;  // more than 8 bits a sample (16-bit, float files)
    std::vector<std::array<float, 4>> colours;  // RGBA per pixel (or per palette entry)
    std::vector<uint8_t> indices;
    const std::array<float, 4>& at(int column, int row) const {
        const size_t i = size_t(row) * size_t(width) + size_t(column);
        return colours[palette ? indices[i] : i];
    }
};

// Decodes `file` (read as `format`) with `decode` and stores it as POV-Ray does. A PNG grey
// sample of 8 bits or fewer becomes trunc(grey(d, d, d) * 255) / 255 (the float grey sum
// drops 84 of the 256 levels by one, and darks collapse once decoded); PGM and TGA grey keep
// the decoded float (measured: level 3 gives height 771 from PGM and TGA, 514 from PNG).
PovImage store_as_pov(const ImageFile& file, Format format, const Decode& decode);

}  // namespace lumen::image

// Encoding (gamma rules of povray-semantics.md §2) and writing image files (image_files.hpp).
#pragma once
#include <string>

#include "render/render.hpp"

namespace lumen::render {

enum class FileType { PNG, EXR, HDR, TIFF, PPM };

struct OutputOptions {
    FileType type = FileType::PNG;
    int bits = 8;               // integer formats: 8 or 16
    bool alpha = false;         // +UA
    // File_Gamma: <= 0 means sRGB (the default), otherwise a power law; 1.0 = linear.
    double file_gamma = -1.0;
};

// Writes `image` to `path` (through a temporary file renamed at the end, so a failed run never
// leaves a partial image). Applies the scene's gamma model. Throws LumenError on failure.
void write_image(const Image& image, const scene::Scene& scene, const OutputOptions& options,
                 const std::string& path);

// The 8-bit value POV-Ray would write for working-space value v in `scene` (for tests).
int encode_8bit(double v, const scene::Scene& scene, const OutputOptions& options);

}  // namespace lumen::render

// Encoding (POV-Ray 3.7's gamma rules) and writing image files (image_files.hpp).
#pragma once
#include <memory>
#include <string>

#include "render/image_files.hpp"
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

// Encodes an image into file values (the scene's gamma model) rectangle by rectangle, so that
// the render's workers can encode each block as it is finished and only the file write is
// left when the last one is done. Rectangles must not overlap between concurrent calls.
class ImageEncoder {
public:
    ImageEncoder(const scene::Scene& scene, const OutputOptions& options, int width, int height);
    ~ImageEncoder();
    ImageEncoder(const ImageEncoder&) = delete;
    ImageEncoder& operator=(const ImageEncoder&) = delete;

    // PNG: starts writing `path` on a thread of its own, each row as soon as all of it is
    // encoded, so the compression overlaps the render. Other formats wait for write().
    void stream_to(const std::string& path);
    // A cropped partial render: the encoder's (width x height) pixels are the rendered ones
    // from (x, y) on; encode() takes the rendered image's coordinates.
    void set_origin(int x, int y);
    // A partial render's margins: every sample outside [left, right] x [top, bottom]
    // (inclusive) written as 0, alpha too (nothing rendered there: what lumen merge reads).
    void clear_outside(int left, int top, int right, int bottom);
    // Encodes pixels [left, right] x [top, bottom] (inclusive) of `image`.
    void encode(const Image& image, int left, int top, int right, int bottom);
    // Writes every encoded pixel to `path` (through a temporary file renamed at the end, so a
    // failed run never leaves a partial image), or finishes the file stream_to began (then
    // `path` is the one given there). Throws LumenError on failure. A stream never finished
    // is abandoned and its file removed.
    void write(const std::string& path);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Encodes all of `image` (on all cores) and writes it, as ImageEncoder::write.
void write_image(const Image& image, const scene::Scene& scene, const OutputOptions& options,
                 const std::string& path);

// Writes encoded pixels as a `type` file, completely or not at all (a temporary file renamed
// at the end). Throws LumenError on failure.
void write_encoded(const EncodedImage& image, FileType type, const std::string& path);

// The 8-bit value POV-Ray would write for working-space value v in `scene` (for tests).
int encode_8bit(double v, const scene::Scene& scene, const OutputOptions& options);

}  // namespace lumen::render

// The formats lumen has no reader of its own for (TIFF, BMP, EXR, HDR, CMYK JPEG), through the
// OpenImageIO module. OIIO expands palettes, so BMP comes back as RGB(A) colours.
#include "image/image_file.hpp"
#include "image/oiio/lumen_oiio.h"
#include "image/oiio_module.hpp"

namespace lumen::image {

namespace {

float* allocate(void* context, size_t count) {
    try {
        auto* values = static_cast<std::vector<float>*>(context);
        values->resize(count);
        return values->data();
    } catch (...) {
        return nullptr;
    }
}

}  // namespace

ImageFile read_with_oiio(const std::string& path) {
    std::string why;
    auto read = reinterpret_cast<LumenOiioRead>(oiio_module_function(LUMEN_OIIO_READ_SYMBOL, why));
    if (!read) throw ImageError("the OpenImageIO reader is missing (" + why + ")");
    ImageFile img;
    LumenOiioPixels spec{};
    char error[512] = "";
    if (read(path.c_str(), kMaxImageSide, kMaxImagePixels, &spec, allocate, &img.values, error,
             sizeof error) != 0)
        throw ImageError(error[0] ? error : "unreadable image");
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.channels;
    img.floating = spec.floating != 0;
    img.bit_depth = img.floating ? 32 : spec.bits;
    if (img.values.size() != img.pixels() * size_t(img.channels))
        throw ImageError("the OpenImageIO reader returned no pixels");
    return img;
}

}  // namespace lumen::image

// write_with_oiio(): the OpenImageIO module's writer (image/oiio_module.hpp).
#include <stdexcept>
#include <vector>

#include "image/oiio/lumen_oiio.h"
#include "image/oiio_module.hpp"
#include "render/image_files.hpp"

namespace lumen::render {

void write_with_oiio(const EncodedImage& image, const char* format, const std::string& path) {
    std::string why;
    const auto write = reinterpret_cast<LumenOiioWrite>(
        image::oiio_module_function(LUMEN_OIIO_WRITE_SYMBOL, why));
    if (!write)
        throw std::runtime_error("the OpenImageIO writer is missing (" + why + ")");
    LumenOiioImage spec{};
    spec.format = format;
    spec.path = path.c_str();
    spec.width = image.width;
    spec.height = image.height;
    spec.channels = image.channels;
    const bool floating = image.maxval == 0;
    spec.stored = floating ? (std::string(format) == "hdr" ? LUMEN_OIIO_FLOAT : LUMEN_OIIO_HALF)
                           : (image.maxval > 255 ? LUMEN_OIIO_UINT16 : LUMEN_OIIO_UINT8);
    if (!floating) spec.colour_space = image.curve == EncodedImage::Curve::Unlabelled ? "" : "sRGB";
    spec.software = "lumen " LUMEN_VERSION;
    // OIIO takes integer files as floats in [0,1]: the exact levels divided by maxval.
    std::vector<float> scaled;
    if (!floating) {
        scaled.reserve(image.values.size());
        for (float v : image.values) scaled.push_back(float(double(v) / image.maxval));
    }
    spec.pixels = floating ? image.values.data() : scaled.data();
    char error[512] = "";
    if (write(&spec, error, sizeof error) != 0)
        throw std::runtime_error(error);
}

}  // namespace lumen::render

// liblumen_oiio.so: writes one image with OpenImageIO (see lumen_oiio.h). Kept out of the
// lumen executable so that OIIO's libraries load only when a render asks for these formats.
#include <cstdio>
#include <string>

#include <OpenImageIO/imageio.h>

#include "render/oiio/lumen_oiio.h"

namespace {

OIIO::TypeDesc type_of(int stored) {
    switch (stored) {
        case LUMEN_OIIO_UINT16: return OIIO::TypeDesc::UINT16;
        case LUMEN_OIIO_HALF: return OIIO::TypeDesc::HALF;
        case LUMEN_OIIO_FLOAT: return OIIO::TypeDesc::FLOAT;
        default: return OIIO::TypeDesc::UINT8;
    }
}

int fail(const std::string& message, char* error, size_t error_size) {
    if (error_size) std::snprintf(error, error_size, "%s", message.c_str());
    return 1;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int lumen_oiio_write_v1(
    const LumenOiioImage* image, char* error, size_t error_size) {
    try {
        OIIO::ImageSpec spec(image->width, image->height, image->channels, type_of(image->stored));
        if (image->colour_space) {
            spec.attribute("oiio:ColorSpace", image->colour_space);
            spec.attribute("oiio:Gamma", 2.2f);
        }
        spec.attribute("Software", image->software);
        auto out = OIIO::ImageOutput::create(image->format);
        if (!out) return fail("no OpenImageIO writer for " + std::string(image->format), error, error_size);
        if (!out->open(image->path, spec)) return fail(out->geterror(), error, error_size);
        const bool ok = out->write_image(OIIO::TypeDesc::FLOAT, image->pixels);
        const std::string message = ok ? "" : out->geterror();
        out->close();
        return ok ? 0 : fail(message, error, error_size);
    } catch (const std::exception& e) {
        return fail(e.what(), error, error_size);
    }
}

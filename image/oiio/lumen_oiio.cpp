// liblumen_oiio.so: writes or reads one image with OpenImageIO (see lumen_oiio.h). Kept out of
// the lumen executable so that OIIO's libraries load only when a render asks for these formats.
#include <cstdio>
#include <string>

#include <OpenImageIO/imageio.h>

#include "image/oiio/lumen_oiio.h"

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

extern "C" __attribute__((visibility("default"))) int lumen_oiio_read_v1(
    const char* path, int max_side, size_t max_pixels, LumenOiioPixels* out, LumenOiioAlloc alloc,
    void* context, char* error, size_t error_size) {
    try {
        auto in = OIIO::ImageInput::open(path);
        if (!in) return fail(OIIO::geterror(), error, error_size);
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
            return fail("the image has no pixels", error, error_size);
        if (spec.width > max_side || spec.height > max_side ||
            size_t(spec.width) * size_t(spec.height) > max_pixels)
            return fail("the image is too large (" + std::to_string(spec.width) + " x " +
                            std::to_string(spec.height) + " pixels)",
                        error, error_size);
        const int channels = spec.nchannels > 4 ? 4 : spec.nchannels;
        out->width = spec.width;
        out->height = spec.height;
        out->channels = channels;
        const OIIO::TypeDesc f = spec.format;
        out->floating = f.is_floating_point() ? 1 : 0;
        const int bits = spec.get_int_attribute("oiio:BitsPerSample", int(f.size() * 8));
        out->bits = out->floating ? 32 : bits;
        float* pixels = alloc(context, size_t(spec.width) * size_t(spec.height) * size_t(channels));
        if (!pixels) return fail("out of memory", error, error_size);
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels))
            return fail(in->geterror(), error, error_size);
        in->close();
        return 0;
    } catch (const std::exception& e) {
        return fail(e.what(), error, error_size);
    }
}

// JPEG through libjpeg: greyscale and YCbCr/RGB files as 8-bit grey or RGB levels. The
// decoder's defaults (islow DCT, fancy upsampling) are OpenImageIO's too, so the samples are
// the ones the OpenImageIO module gave before (JpegReader.SamplesAreOpenImageIOs); CMYK files
// still go through that module, which converts them to RGB. Read here, a JPEG height field no
// longer loads OpenImageIO's 260 libraries (0.4 s a run).
#include <csetjmp>
#include <cstdio>
#include <memory>

#include <jpeglib.h>

#include "image/image_file.hpp"

namespace lumen::image {

namespace {

struct Decoder {
    jpeg_decompress_struct info{};
    jpeg_error_mgr manager{};
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX] = "libjpeg error";
    bool created = false;
    ~Decoder() {
        if (created) jpeg_destroy_decompress(&info);
    }
};

[[noreturn]] void error_exit(j_common_ptr common) {
    auto* d = static_cast<Decoder*>(common->client_data);
    (*common->err->format_message)(common, d->message);
    std::longjmp(d->jump, 1);
}
void no_message(j_common_ptr, int) {}

// The libjpeg calls, free of C++ objects with destructors (errors longjmp out of here):
// false on an error, with the message in the decoder.
bool start(Decoder& d, std::FILE* file) {
    d.info.err = jpeg_std_error(&d.manager);
    d.manager.error_exit = error_exit;
    d.manager.emit_message = no_message;
    d.info.client_data = &d;
    if (setjmp(d.jump)) return false;
    jpeg_create_decompress(&d.info);
    d.created = true;
    jpeg_stdio_src(&d.info, file);
    jpeg_read_header(&d.info, TRUE);
    return true;
}

bool decode(Decoder& d, unsigned char* pixels, size_t row_bytes) {
    if (setjmp(d.jump)) return false;
    jpeg_start_decompress(&d.info);
    while (d.info.output_scanline < d.info.output_height) {
        JSAMPROW row = pixels + size_t(d.info.output_scanline) * row_bytes;
        jpeg_read_scanlines(&d.info, &row, 1);
    }
    jpeg_finish_decompress(&d.info);
    return true;
}

}  // namespace

ImageFile read_jpeg(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) throw ImageError("cannot open the file");
    Decoder d;
    if (!start(d, file.get())) throw ImageError(d.message);
    const J_COLOR_SPACE space = d.info.jpeg_color_space;
    if (space != JCS_GRAYSCALE && space != JCS_YCbCr && space != JCS_RGB) {
        file.reset();
        return read_with_oiio(path);  // CMYK, YCCK: converted there
    }
    d.info.out_color_space = space == JCS_GRAYSCALE ? JCS_GRAYSCALE : JCS_RGB;
    check_image_size(d.info.image_width, d.info.image_height);
    ImageFile img;
    img.width = int(d.info.image_width);
    img.height = int(d.info.image_height);
    img.channels = space == JCS_GRAYSCALE ? 1 : 3;
    img.bit_depth = 8;
    std::vector<unsigned char> levels(img.pixels() * size_t(img.channels));
    if (!decode(d, levels.data(), size_t(img.width) * size_t(img.channels)))
        throw ImageError(d.message);
    img.values.resize(levels.size());
    // Scaled as OpenImageIO scales 8-bit samples (times 1/255, not over 255: a float's last
    // bit apart).
    for (size_t i = 0; i < levels.size(); ++i) img.values[i] = levels[i] * (1.0f / 255);
    return img;
}

}  // namespace lumen::image

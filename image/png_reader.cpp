// PNG through libpng: grey, grey + alpha, RGB, RGBA at 1..16 bits (sub-byte grey expanded to
// 8-bit levels), palette images as their entries (tRNS giving entry alpha) plus one index per
// pixel, and the sRGB / gAMA chunks (iCCP is ignored, as POV-Ray ignores it).
#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <memory>

#include <png.h>

#include "image/png_errors.hpp"

#include "image/image_file.hpp"

namespace lumen::image {

namespace {

using ErrorText = PngErrorText;

// What the header says, after the transformations asked for.
struct Header {
    png_uint_32 width = 0, height = 0;
    int bit_depth = 0, colour_type = 0, channels = 0;
    size_t row_bytes = 0;
    bool srgb = false, has_gamma = false;
    double gamma = 1;
    int palette_size = 0, trns_size = 0;
    png_color palette[256];
    png_byte trns[256];
};

struct Reader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ErrorText error;
    ~Reader() { png_destroy_read_struct(&png, &info, nullptr); }
};

// The libpng calls, free of C++ objects with destructors (libpng errors longjmp out of here).
bool read_header(Reader& r, std::FILE* file, Header& h) {
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.error, png_error_to_text,
                                   png_ignore_warning);
    if (!r.png) return false;
    r.info = png_create_info_struct(r.png);
    if (!r.info || setjmp(png_jmpbuf(r.png))) return false;
    png_init_io(r.png, file);
    png_set_user_limits(r.png, kMaxImageSide, kMaxImageSide);
    png_read_info(r.png, r.info);
    h.width = png_get_image_width(r.png, r.info);
    h.height = png_get_image_height(r.png, r.info);
    h.colour_type = png_get_color_type(r.png, r.info);
    h.bit_depth = png_get_bit_depth(r.png, r.info);
    int intent = 0;
    h.srgb = png_get_sRGB(r.png, r.info, &intent) != 0;
    h.has_gamma = png_get_gAMA(r.png, r.info, &h.gamma) != 0;
    if (h.colour_type == PNG_COLOR_TYPE_PALETTE) {
        png_colorp entries = nullptr;
        png_get_PLTE(r.png, r.info, &entries, &h.palette_size);
        for (int i = 0; i < h.palette_size && i < 256; ++i) h.palette[i] = entries[i];
        png_bytep alpha = nullptr;
        if (png_get_tRNS(r.png, r.info, &alpha, &h.trns_size, nullptr) && alpha)
            for (int i = 0; i < h.trns_size && i < 256; ++i) h.trns[i] = alpha[i];
        else
            h.trns_size = 0;
        png_set_packing(r.png);  // one index per byte
    } else if (h.bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(r.png);
    }
    png_set_interlace_handling(r.png);
    png_read_update_info(r.png, r.info);
    h.channels = png_get_channels(r.png, r.info);
    h.row_bytes = png_get_rowbytes(r.png, r.info);
    return true;
}

bool read_rows(Reader& r, png_bytep* rows) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_read_image(r.png, rows);
    png_read_end(r.png, nullptr);
    return true;
}

}  // namespace

ImageFile read_png(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) throw ImageError("cannot open the file");
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
        throw ImageError("not a PNG file");
    std::rewind(file.get());
    Reader r;
    auto header = std::make_unique<Header>();
    Header& h = *header;
    if (!read_header(r, file.get(), h)) throw ImageError(r.error.text);
    check_image_size(h.width, h.height);
    std::vector<png_byte> bytes(h.row_bytes * h.height);
    std::vector<png_bytep> rows(h.height);
    for (png_uint_32 y = 0; y < h.height; ++y) rows[y] = bytes.data() + y * h.row_bytes;
    if (!read_rows(r, rows.data())) throw ImageError(r.error.text);

    ImageFile img;
    img.width = int(h.width);
    img.height = int(h.height);
    img.bit_depth = h.bit_depth;
    if (h.srgb) img.gamma.kind = FileGamma::Kind::SRGB;
    else if (h.has_gamma && h.gamma > 0) img.gamma = {FileGamma::Kind::Power, h.gamma};
    if (h.colour_type == PNG_COLOR_TYPE_PALETTE) {
        img.channels = h.trns_size > 0 ? 4 : 3;
        for (int i = 0; i < h.palette_size; ++i)
            img.palette.push_back({h.palette[i].red / 255.0f, h.palette[i].green / 255.0f,
                                   h.palette[i].blue / 255.0f,
                                   i < h.trns_size ? h.trns[i] / 255.0f : 1.0f});
        img.indices.resize(img.pixels());
        for (size_t y = 0; y < h.height; ++y)
            std::copy_n(rows[y], h.width, img.indices.begin() + y * h.width);
        for (uint8_t& i : img.indices)
            if (i >= img.palette.size()) i = 0;  // an index past the palette: entry 0
        if (img.palette.empty()) throw ImageError("the palette image has no palette");
        return img;
    }
    img.channels = h.channels;
    const size_t n = img.pixels() * size_t(h.channels);
    img.values.resize(n);
    const bool sixteen = h.bit_depth == 16;
    for (size_t y = 0; y < h.height; ++y) {
        const png_byte* row = rows[y];
        float* out = img.values.data() + y * size_t(h.width) * h.channels;
        for (size_t i = 0; i < size_t(h.width) * h.channels; ++i)
            out[i] = sixteen ? float((row[2 * i] << 8) | row[2 * i + 1]) / 65535.0f
                             : float(row[i]) / 255.0f;
    }
    return img;
}

}  // namespace lumen::image

// Truevision TGA: colour-mapped (1), true-colour (2) and grey (3) images, uncompressed or RLE
// (9, 10, 11); 15/16-bit (5 bits a channel), 24 and 32-bit pixels; either origin.
#include "image/byte_reader.hpp"

namespace lumen::image {

namespace {

// One pixel or palette entry of `bits` bits as RGBA in [0, 1] (grey: r = g = b).
std::array<float, 4> read_colour(ByteReader& in, unsigned bits, bool grey) {
    if (grey) {
        const float v = in.u8() / 255.0f;
        const float a = bits == 16 ? in.u8() / 255.0f : 1.0f;
        return {v, v, v, a};
    }
    if (bits == 15 || bits == 16) {
        const unsigned p = in.u16();
        return {((p >> 10) & 31) / 31.0f, ((p >> 5) & 31) / 31.0f, (p & 31) / 31.0f, 1.0f};
    }
    const float b = in.u8() / 255.0f, g = in.u8() / 255.0f, r = in.u8() / 255.0f;
    const float a = bits == 32 ? in.u8() / 255.0f : 1.0f;
    return {r, g, b, a};
}

}  // namespace

ImageFile read_tga(const std::string& path) {
    ByteReader in(path, "TGA");
    if (in.size() < 18) throw ImageError("not a TGA file");
    const unsigned id_length = in.u8(), map_type = in.u8(), type = in.u8();
    const unsigned map_first = in.u16(), map_length = in.u16(), map_bits = in.u8();
    in.u16(), in.u16();  // origin
    const unsigned width = in.u16(), height = in.u16(), bits = in.u8(), descriptor = in.u8();
    const unsigned base = type & ~8u;
    const bool rle = (type & 8u) != 0;
    if (type > 11 || base < 1 || base > 3 || map_type > 1)
        throw ImageError("unsupported TGA image type " + std::to_string(type));
    const bool mapped = base == 1, grey = base == 3;
    if (mapped ? bits != 8 || map_type != 1 || map_length == 0 || map_length > 256
               : grey ? bits != 8 && bits != 16
                      : bits != 15 && bits != 16 && bits != 24 && bits != 32)
        throw ImageError("unsupported TGA pixel format (" + std::to_string(bits) + " bits)");
    check_image_size(width, height);
    in.skip(id_length);

    ImageFile img;
    img.width = int(width);
    img.height = int(height);
    img.bit_depth = 8;
    std::vector<std::array<float, 4>> palette;
    if (map_type == 1) {
        if (map_bits != 15 && map_bits != 16 && map_bits != 24 && map_bits != 32)
            throw ImageError("unsupported TGA colour map entries");
        for (unsigned i = 0; i < map_length; ++i) palette.push_back(read_colour(in, map_bits, false));
    }
    if (mapped) {
        img.palette.assign(map_first, {0, 0, 0, 1});
        img.palette.insert(img.palette.end(), palette.begin(), palette.end());
        if (img.palette.size() > 256) img.palette.resize(256);
        img.channels = map_bits == 32 ? 4 : 3;
        img.indices.resize(img.pixels());
    } else {
        img.channels = grey ? (bits == 16 ? 2 : 1) : (bits == 32 ? 4 : 3);
        img.values.resize(img.pixels() * size_t(img.channels));
    }
    const bool top_down = (descriptor & 0x20) != 0, right_to_left = (descriptor & 0x10) != 0;
    auto store = [&](size_t i, const std::array<float, 4>& c, unsigned index) {
        const size_t file_row = i / width, file_col = i % width;
        const size_t row = top_down ? file_row : height - 1 - file_row;
        const size_t col = right_to_left ? width - 1 - file_col : file_col;
        const size_t at = row * width + col;
        if (mapped) {
            img.indices[at] = uint8_t(index < img.palette.size() ? index : 0);
            return;
        }
        float* out = img.values.data() + at * img.channels;
        if (grey) {
            out[0] = c[0];
            if (img.channels == 2) out[1] = c[3];
        } else {
            for (int k = 0; k < img.channels; ++k) out[k] = c[size_t(k)];
        }
    };
    auto read_pixel = [&](unsigned& index) {
        if (mapped) {
            index = in.u8();
            return std::array<float, 4>{};
        }
        return read_colour(in, bits, grey);
    };
    const size_t n = img.pixels();
    for (size_t i = 0; i < n;) {
        unsigned count = 1;
        bool run = false;
        if (rle) {
            const unsigned packet = in.u8();
            count = (packet & 127) + 1;
            run = (packet & 128) != 0;
        }
        unsigned index = 0;
        std::array<float, 4> c{};
        for (unsigned k = 0; k < count && i < n; ++k, ++i) {
            if (!run || k == 0) c = read_pixel(index);
            store(i, c, index);
        }
    }
    return img;
}

}  // namespace lumen::image

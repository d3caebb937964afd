// GIF (87a and 89a): the first image of the file as palette entries and indices, as POV-Ray
// reads it (height fields take the index, image maps the entry), the transparent index of a
// graphic control extension an entry of alpha 0 (POV-Ray shows what lies behind it, probed
// with a 4 x 4 image_map), interlaced rows left in their stored order as POV-Ray leaves them;
// and POT, Fractint's
// continuous-potential files: a GIF twice as wide as the field, each row's left half the high
// bytes of 16-bit heights and its right half the low bytes.
#include "image/byte_reader.hpp"

namespace lumen::image {

namespace {

// The data sub-blocks that follow (each a length byte, 0 ending them), appended to `out`.
void sub_blocks(ByteReader& in, std::string& out) {
    for (unsigned n = in.u8(); n != 0; n = in.u8()) in.take(n, out);
}

std::vector<std::array<float, 4>> read_palette(ByteReader& in, unsigned size) {
    std::vector<std::array<float, 4>> p(size);
    for (auto& c : p) {
        const float r = in.u8() / 255.0f, g = in.u8() / 255.0f, b = in.u8() / 255.0f;
        c = {r, g, b, 1.0f};
    }
    return p;
}

// The LZW-coded indices of one image: `count` of them, codes starting at min_size + 1 bits.
std::vector<uint8_t> decode_lzw(const std::string& data, unsigned min_size, size_t count) {
    if (min_size < 2 || min_size > 8) throw ImageError("the GIF file's code size is invalid");
    const unsigned clear = 1u << min_size, end = clear + 1;
    // Each code's entry: its prefix code and last index; lengths for copying it out.
    std::vector<uint16_t> prefix(4096);
    std::vector<uint8_t> suffix(4096), first(4096);
    std::vector<uint16_t> length(4096);
    for (unsigned i = 0; i < clear; ++i) suffix[i] = first[i] = uint8_t(i), length[i] = 1;
    std::vector<uint8_t> out;
    out.reserve(count);
    unsigned size = min_size + 1, next = end + 1;
    int previous = -1;
    size_t bit = 0;
    const size_t bits = data.size() * 8;
    while (out.size() < count && bit + size <= bits) {
        unsigned code = 0;
        for (unsigned k = 0; k < size; ++k, ++bit)
            code |= unsigned((uint8_t(data[bit >> 3]) >> (bit & 7)) & 1) << k;
        if (code == clear) {
            size = min_size + 1, next = end + 1, previous = -1;
            continue;
        }
        if (code == end) break;
        if (code > next || (code == next && previous < 0))
            throw ImageError("the GIF file's image data are corrupt");
        // A code not yet in the table (code == next) is the previous entry plus its first index.
        const unsigned entry = code == next ? unsigned(previous) : code;
        const size_t start = out.size(), n = length[entry] + (code == next ? 1 : 0);
        out.resize(start + n);
        size_t i = start + length[entry];
        for (unsigned c = entry; ; c = prefix[c]) {
            out[--i] = suffix[c];
            if (length[c] == 1) break;
        }
        if (code == next) out.back() = first[previous];
        if (previous >= 0 && next < 4096) {
            prefix[next] = uint16_t(previous);
            suffix[next] = first[code == next ? unsigned(previous) : code];
            first[next] = first[previous];
            length[next] = uint16_t(length[previous] + 1);
            ++next;
            if (next == (1u << size) && size < 12) ++size;
        }
        previous = int(code);
    }
    if (out.size() < count) throw ImageError("the GIF file's image data are truncated");
    out.resize(count);
    return out;
}

}  // namespace

ImageFile read_gif(const std::string& path) {
    ByteReader in(path, "GIF");
    std::string magic;
    for (int i = 0; i < 6; ++i) magic += char(in.u8());
    if (magic != "GIF87a" && magic != "GIF89a") throw ImageError("not a GIF file");
    in.u16(), in.u16();  // the logical screen; the image's own size counts
    const unsigned flags = in.u8();
    in.u8(), in.u8();  // background, aspect
    ImageFile img;
    img.channels = 3;
    std::vector<std::array<float, 4>> global;
    if (flags & 0x80) global = read_palette(in, 2u << (flags & 7));
    int transparent = -1;
    for (;;) {
        const unsigned kind = in.u8();
        if (kind == 0x21) {  // an extension: its label, then its sub-blocks
            const unsigned label = in.u8();
            std::string block;
            sub_blocks(in, block);
            if (label == 0xF9 && block.size() >= 4)  // graphic control: flags, delay, index
                transparent = block[0] & 1 ? int(uint8_t(block[3])) : -1;
            continue;
        }
        if (kind != 0x2C) throw ImageError("the GIF file holds no image");
        in.u16(), in.u16();  // position on the screen
        const unsigned width = in.u16(), height = in.u16(), image_flags = in.u8();
        check_image_size(width, height);
        img.width = int(width), img.height = int(height);
        img.palette = image_flags & 0x80 ? read_palette(in, 2u << (image_flags & 7)) : global;
        if (img.palette.empty()) throw ImageError("the GIF file has no palette");
        const unsigned min_size = in.u8();
        std::string data;
        sub_blocks(in, data);
        // Interlaced rows stay in the order stored: POV-Ray 3.7 shows them so (an interlaced
        // image_map matched only without reordering them, tests/patterns/image_map.pov Kind 21).
        img.indices = decode_lzw(data, min_size, img.pixels());
        // Indices past a short palette (a damaged file) read as black.
        if (img.palette.size() < 256) img.palette.resize(256, {0, 0, 0, 1});
        if (transparent >= 0) {
            img.channels = 4;
            img.palette[size_t(transparent)][3] = 0;
        }
        return img;
    }
}

ImageFile read_pot(const std::string& path) {
    const ImageFile gif = read_gif(path);
    if (gif.width % 2 != 0) throw ImageError("a POT file's width must be even");
    ImageFile img;
    img.width = gif.width / 2, img.height = gif.height;
    img.channels = 1;
    img.bit_depth = 16;
    img.values.resize(img.pixels());
    for (size_t y = 0; y < size_t(img.height); ++y)
        for (size_t x = 0; x < size_t(img.width); ++x) {
            const size_t row = y * size_t(gif.width);
            const unsigned hi = gif.indices[row + x], lo = gif.indices[row + x + size_t(img.width)];
            img.values[y * size_t(img.width) + x] = float(hi * 256 + lo) / 65535.0f;
        }
    return img;
}

}  // namespace lumen::image

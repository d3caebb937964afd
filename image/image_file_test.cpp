// The image readers on files written here byte by byte (PNG with stored deflate blocks, PGM,
// PPM, TGA, BMP through OpenImageIO), POV-Ray's storage rules, and the errors.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_file.hpp"
#include "image/pov_storage.hpp"

namespace lumen::image {
namespace {

namespace fs = std::filesystem;
using Bytes = std::string;

fs::path temp_file(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / "lumen_image_tests";
    fs::create_directories(dir);
    return dir / name;
}

fs::path write(const std::string& name, const Bytes& bytes) {
    fs::path p = temp_file(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

void be32(Bytes& b, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b += char((v >> s) & 0xff);
}
void le16(Bytes& b, unsigned v) { b += char(v & 0xff), b += char(v >> 8); }
void le32(Bytes& b, uint32_t v) { le16(b, v & 0xffff), le16(b, v >> 16); }

uint32_t crc32(const Bytes& data) {
    uint32_t c = 0xffffffffu;
    for (unsigned char ch : data) {
        c ^= ch;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

Bytes chunk(const std::string& type, const Bytes& data) {
    Bytes out;
    be32(out, uint32_t(data.size()));
    out += type + data;
    be32(out, crc32(type + data));
    return out;
}

// zlib stream of one stored (uncompressed) deflate block.
Bytes zlib_stored(const Bytes& raw) {
    Bytes out = "\x78\x01";
    out += char(1);
    le16(out, unsigned(raw.size()));
    le16(out, unsigned(~raw.size() & 0xffff));
    out += raw;
    uint32_t a = 1, b = 0;
    for (unsigned char ch : raw) a = (a + ch) % 65521, b = (b + a) % 65521;
    be32(out, (b << 16) | a);
    return out;
}

// A PNG of `rows` (each row's sample bytes, filter byte added here) and extra chunks before
// the image data.
Bytes png(int w, int h, int depth, int colour_type, const std::vector<Bytes>& rows,
          const Bytes& extra = "") {
    Bytes ihdr;
    be32(ihdr, uint32_t(w));
    be32(ihdr, uint32_t(h));
    ihdr += char(depth), ihdr += char(colour_type), ihdr += Bytes(3, '\0');
    Bytes raw;
    for (const Bytes& r : rows) raw += '\0' + r;
    return "\x89PNG\r\n\x1a\n" + chunk("IHDR", ihdr) + extra + chunk("IDAT", zlib_stored(raw)) +
           chunk("IEND", "");
}

Bytes bytes(std::initializer_list<int> v) {
    Bytes b;
    for (int x : v) b += char(x);
    return b;
}

TEST(ImageFormat, FromKeywordAndExtension) {
    EXPECT_EQ(format_from_keyword("png"), Format::Png);
    EXPECT_EQ(format_from_keyword("jpeg"), Format::Jpeg);
    EXPECT_FALSE(format_from_keyword("jpg"));
    EXPECT_EQ(format_from_extension("dir.x/a.png"), Format::Png);
    EXPECT_EQ(format_from_extension("A.PNG"), Format::Png);
    EXPECT_FALSE(format_from_extension("a.Png"));  // POV-Ray takes all-lower or all-upper only
    EXPECT_EQ(format_from_extension("x.jpg"), Format::Jpeg);
    EXPECT_EQ(format_from_extension("x.tif"), Format::Tiff);
    EXPECT_FALSE(format_from_extension("dir.png/name"));
    EXPECT_FALSE(format_from_extension("x.xyz"));
}

TEST(PngReader, Grey8ValuesAndNoGamma) {
    const auto p = write("g8.png", png(4, 1, 8, 0, {bytes({0, 3, 128, 255})}));
    const ImageFile f = read_png(p);
    EXPECT_EQ(f.width, 4);
    EXPECT_EQ(f.height, 1);
    EXPECT_EQ(f.channels, 1);
    EXPECT_EQ(f.bit_depth, 8);
    EXPECT_TRUE(f.grey());
    EXPECT_EQ(f.gamma.kind, FileGamma::Kind::Unspecified);
    ASSERT_EQ(f.values.size(), 4u);
    EXPECT_FLOAT_EQ(f.values[1], 3 / 255.0f);
    EXPECT_FLOAT_EQ(f.values[3], 1.0f);
}

TEST(PngReader, SubByteGreyExpandsToEightBitLevels) {
    // 2-bit grey 0,1,2,3 packed in one byte: levels 0, 85, 170, 255.
    const auto p = write("g2.png", png(4, 1, 2, 0, {bytes({0x1b})}));
    const ImageFile f = read_png(p);
    ASSERT_EQ(f.values.size(), 4u);
    EXPECT_FLOAT_EQ(f.values[1], 85 / 255.0f);
    EXPECT_FLOAT_EQ(f.values[2], 170 / 255.0f);
}

TEST(PngReader, SixteenBitRgbAndGammaChunks) {
    Bytes gama;
    be32(gama, 45455);
    const auto p = write("rgb16.png", png(1, 2, 16, 2,
                                          {bytes({0xff, 0xff, 0x80, 0x00, 0x00, 0x01}),
                                           bytes({0, 0, 0, 0, 0x12, 0x34})},
                                          chunk("gAMA", gama)));
    const ImageFile f = read_png(p);
    EXPECT_EQ(f.channels, 3);
    EXPECT_EQ(f.bit_depth, 16);
    EXPECT_EQ(f.gamma.kind, FileGamma::Kind::Power);
    EXPECT_NEAR(f.gamma.gamma, 0.45455, 1e-9);
    EXPECT_FLOAT_EQ(f.values[1], 0x8000 / 65535.0f);
    EXPECT_FLOAT_EQ(f.values[2], 1 / 65535.0f);
    EXPECT_FLOAT_EQ(f.values[5], 0x1234 / 65535.0f);  // row 1 = the second row of the file
    const auto s = write("srgb.png", png(1, 1, 8, 0, {bytes({7})}, chunk("sRGB", bytes({0}))));
    EXPECT_EQ(read_png(s).gamma.kind, FileGamma::Kind::SRGB);
}

TEST(PngReader, PaletteKeepsEntriesIndicesAndTransparency) {
    const Bytes plte = bytes({255, 0, 0, 0, 255, 0, 0, 0, 255});
    const auto p = write("pal.png", png(3, 1, 8, 3, {bytes({2, 0, 1})},
                                        chunk("PLTE", plte) + chunk("tRNS", bytes({128}))));
    const ImageFile f = read_png(p);
    ASSERT_TRUE(f.has_palette());
    ASSERT_EQ(f.palette.size(), 3u);
    EXPECT_EQ(f.indices, (std::vector<uint8_t>{2, 0, 1}));
    EXPECT_FLOAT_EQ(f.palette[0][3], 128 / 255.0f);
    EXPECT_FLOAT_EQ(f.palette[1][3], 1.0f);
    EXPECT_FLOAT_EQ(f.palette[2][2], 1.0f);
    EXPECT_TRUE(f.has_alpha());
}

TEST(PngReader, CorruptAndMissingFilesAreErrors) {
    Bytes good = png(2, 2, 8, 0, {bytes({1, 2}), bytes({3, 4})});
    EXPECT_THROW(read_png(write("cut.png", good.substr(0, good.size() - 30))), ImageError);
    Bytes bad_crc = good;
    bad_crc[30] ^= 0x55;
    EXPECT_THROW(read_png(write("crc.png", bad_crc)), ImageError);
    EXPECT_THROW(read_png(write("not.png", "P5 1 1 255 x")), ImageError);
    EXPECT_THROW(read_png(temp_file("missing.png").string()), ImageError);
    EXPECT_THROW(read_png(write("huge.png", png(70000, 1, 8, 0, {}))), ImageError);
}

TEST(PnmReader, AsciiAndBinaryWithMaxval) {
    const ImageFile a = read_pnm(write("a.pgm", "P2\n# comment\n3 1\n15\n0 7 15\n"));
    EXPECT_EQ(a.channels, 1);
    EXPECT_EQ(a.bit_depth, 8);
    EXPECT_FLOAT_EQ(a.values[1], float(7 * 255 / 15) / 255.0f);  // brought to 8 bits first
    Bytes p6 = "P6 2 1 255\n";
    p6 += bytes({10, 20, 30, 255, 0, 128});
    const ImageFile b = read_pnm(write("b.ppm", p6));
    EXPECT_EQ(b.channels, 3);
    EXPECT_FLOAT_EQ(b.values[5], 128 / 255.0f);
    Bytes p5 = "P5 1 1 1000\n";
    p5 += bytes({0x01, 0xf4});  // 500 of 1000
    const ImageFile c = read_pnm(write("c.pgm", p5));
    EXPECT_EQ(c.bit_depth, 16);
    EXPECT_FLOAT_EQ(c.values[0], float(500 * 65535 / 1000) / 65535.0f);
}

TEST(PnmReader, BadFilesAreErrors) {
    EXPECT_THROW(read_pnm(write("t.ppm", "P6 4 4 255\nabc")), ImageError);    // truncated
    EXPECT_THROW(read_pnm(write("m.pgm", "P5 1 1 70000\n\1\1")), ImageError);  // maxval
    EXPECT_THROW(read_pnm(write("z.pgm", "P5 0 1 255\n")), ImageError);        // no pixels
    EXPECT_THROW(read_pnm(write("x.pgm", "P2 2 1 255\n1 x\n")), ImageError);   // not a number
    EXPECT_THROW(read_pnm(write("h.pgm", "P5 100000 100000 255\n")), ImageError);
    EXPECT_THROW(read_pnm(write("q.pgm", "Q5 1 1 255\n\1")), ImageError);
}

Bytes tga_header(int type, int width, int height, int bits, int descriptor, int map_length = 0,
                 int map_bits = 0) {
    Bytes h = bytes({0, map_length ? 1 : 0, type});
    le16(h, 0), le16(h, unsigned(map_length)), h += char(map_bits);
    le16(h, 0), le16(h, 0), le16(h, unsigned(width)), le16(h, unsigned(height));
    return h + bytes({bits, descriptor});
}

TEST(TgaReader, OriginsRleAndColourMaps) {
    // 24-bit, bottom-up: the file's first row is the picture's bottom row.
    const ImageFile up = read_tga(write("up.tga", tga_header(2, 1, 2, 24, 0) +
                                                      bytes({0, 0, 255, 255, 0, 0})));
    EXPECT_FLOAT_EQ(up.values[0], 0.0f);  // top pixel: blue (BGR 255, 0, 0)
    EXPECT_FLOAT_EQ(up.values[2], 1.0f);
    EXPECT_FLOAT_EQ(up.values[3], 1.0f);  // bottom pixel: red
    // RLE, top-down: a run of 3 then 1 raw pixel.
    const ImageFile rle = read_tga(write("rle.tga", tga_header(10, 4, 1, 24, 0x20) +
                                                        bytes({0x82, 10, 20, 30, 0x00, 1, 2, 3})));
    EXPECT_FLOAT_EQ(rle.values[6], 30 / 255.0f);  // third pixel's red (from the run)
    EXPECT_FLOAT_EQ(rle.values[9], 3 / 255.0f);  // the raw pixel, BGR 1, 2, 3
    EXPECT_FLOAT_EQ(rle.values[11], 1 / 255.0f);
    // Colour-mapped: two 24-bit entries, indices 1, 0.
    const ImageFile map = read_tga(write("map.tga", tga_header(1, 2, 1, 8, 0x20, 2, 24) +
                                                        bytes({0, 0, 255, 0, 255, 0, 1, 0})));
    ASSERT_TRUE(map.has_palette());
    EXPECT_EQ(map.indices, (std::vector<uint8_t>{1, 0}));
    EXPECT_FLOAT_EQ(map.palette[0][0], 1.0f);
    EXPECT_FLOAT_EQ(map.palette[1][1], 1.0f);
    // Grey, 8-bit.
    const ImageFile grey = read_tga(write("g.tga", tga_header(3, 2, 1, 8, 0x20) + bytes({9, 200})));
    EXPECT_TRUE(grey.grey());
    EXPECT_FLOAT_EQ(grey.values[1], 200 / 255.0f);
    EXPECT_THROW(read_tga(write("cut.tga", tga_header(2, 4, 4, 24, 0) + bytes({1, 2}))), ImageError);
    EXPECT_THROW(read_tga(write("bad.tga", tga_header(7, 1, 1, 24, 0) + bytes({1, 2, 3}))), ImageError);
}

TEST(OiioReader, ReadsBmpThroughTheModule) {
    Bytes bmp = "BM";
    le32(bmp, 14 + 40 + 8), le32(bmp, 0), le32(bmp, 14 + 40);
    le32(bmp, 40), le32(bmp, 1), le32(bmp, 2), le16(bmp, 1), le16(bmp, 24), le32(bmp, 0);
    le32(bmp, 8), le32(bmp, 2835), le32(bmp, 2835), le32(bmp, 0), le32(bmp, 0);
    bmp += bytes({255, 0, 0, 0, 0, 0, 255, 0});  // bottom row blue, top row red (BGR + pad)
    const ImageFile f = read_image(write("two.bmp", bmp), Format::Bmp);
    EXPECT_EQ(f.width, 1);
    EXPECT_EQ(f.height, 2);
    ASSERT_GE(f.channels, 3);
    EXPECT_FLOAT_EQ(f.values[0], 1.0f);  // top row red
    EXPECT_FLOAT_EQ(f.values[size_t(f.channels) + 2], 1.0f);
    EXPECT_THROW(read_image(write("bad.bmp", "BMxx"), Format::Bmp), ImageError);
    EXPECT_THROW(read_image("x.iff", Format::Iff), ImageError);
}

TEST(PovStorage, EightBitGreyIsRequantisedByTheFloatGreySum) {
    int dropped = 0;
    for (int k = 0; k < 256; ++k) {
        ImageFile f;
        f.width = f.height = 1;
        f.channels = 1;
        f.values = {k / 255.0f};
        const float v = store_as_pov(f, Format::Png, {}).colours[0][0];
        EXPECT_EQ(store_as_pov(f, Format::Pgm, {}).colours[0][0], f.values[0]);
        const int level = int(std::lround(v * 255));
        EXPECT_TRUE(level == k || level == k - 1) << k;
        dropped += level != k;
        if (k == 3 || k == 5 || k == 6 || k == 10) {
            EXPECT_EQ(level, k - 1) << k;
        }
        if (k == 4 || k == 255) {
            EXPECT_EQ(level, k) << k;
        }
    }
    EXPECT_EQ(dropped, 84);
    // Decoded with sRGB, level 10 collapses to 0; 16-bit grey keeps the decoded float.
    ImageFile f;
    f.width = f.height = 1;
    f.channels = 1;
    f.values = {10 / 255.0f};
    EXPECT_EQ(store_as_pov(f, Format::Png, {Decode::Kind::SRGB, 1}).colours[0][0], 0.0f);
    f.bit_depth = 16;
    EXPECT_GT(store_as_pov(f, Format::Png, {Decode::Kind::SRGB, 1}).colours[0][0], 0.0f);
}

TEST(PovStorage, DefaultDecodingFollowsTheFileAndFormat) {
    ImageFile f;
    EXPECT_EQ(default_decode(f, Format::Png).kind, Decode::Kind::SRGB);
    EXPECT_EQ(default_decode(f, Format::Ppm).kind, Decode::Kind::Raw);
    EXPECT_EQ(default_decode(f, Format::Tga).kind, Decode::Kind::SRGB);
    f.gamma = {FileGamma::Kind::Power, 0.5};
    const Decode d = default_decode(f, Format::Png);
    EXPECT_EQ(d.kind, Decode::Kind::Power);
    EXPECT_FLOAT_EQ(d.apply(0.5f), 0.25f);
}

}  // namespace
}  // namespace lumen::image

// The GIF and POT readers: GIFs written here code by code (plain and interlaced rows, clear
// codes, a local palette), Fractint's mtmand.pot from POV-Ray's includes checked against
// OpenImageIO's own GIF decoder, its 16-bit heights, and damaged files.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_file.hpp"

namespace lumen::image {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / "lumen_gif_tests";
    fs::create_directories(dir);
    return dir / name;
}

fs::path write(const std::string& name, const std::string& bytes) {
    fs::path p = temp_file(name);
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

void le16(std::string& b, unsigned v) { b += char(v & 0xff), b += char(v >> 8); }

// The image rows in the order a GIF stores them.
std::vector<int> stored_rows(int h, bool interlaced) {
    std::vector<int> rows;
    if (interlaced) {
        for (auto [start, step] : {std::pair{0, 8}, {4, 8}, {2, 4}, {1, 2}})
            for (int y = start; y < h; y += step) rows.push_back(y);
    } else {
        for (int y = 0; y < h; ++y) rows.push_back(y);
    }
    return rows;
}

// A GIF of 4-colour indices coded as literals with a clear code before every second one, so
// every code stays 3 bits wide; rows stored in the interlaced order when asked.
std::string make_gif(int w, int h, const std::vector<uint8_t>& indices, bool interlaced,
                     bool local_palette, bool transparent = false) {
    std::string b = "GIF89a";
    le16(b, unsigned(w)), le16(b, unsigned(h));
    b += char(local_palette ? 0x00 : 0x81), b += char(0), b += char(0);
    const std::string palette = std::string("\x00\x00\x00\xff\x00\x00\x00\xff\x00\x10\x20\x30", 12);
    if (!local_palette) b += palette;
    // A graphic control extension: index 1 transparent, or none.
    b += std::string(transparent ? "\x21\xf9\x04\x01\x00\x00\x01\x00" : "\x21\xf9\x04\x00\x00\x00\x00\x00", 8);
    b += char(0x2c);
    le16(b, 0), le16(b, 0), le16(b, unsigned(w)), le16(b, unsigned(h));
    b += char((local_palette ? 0x81 : 0) | (interlaced ? 0x40 : 0));
    if (local_palette) b += palette;
    b += char(2);  // minimum code size: clear 4, end 5
    std::vector<unsigned> codes;
    int n = 0;
    for (int y : stored_rows(h, interlaced))
        for (int x = 0; x < w; ++x) {
            if (n++ % 2 == 0) codes.push_back(4);
            codes.push_back(indices[size_t(y * w + x)]);
        }
    codes.push_back(5);
    std::string data;
    unsigned acc = 0, bits = 0;
    for (unsigned c : codes) {
        acc |= c << bits, bits += 3;
        while (bits >= 8) data += char(acc & 0xff), acc >>= 8, bits -= 8;
    }
    if (bits) data += char(acc);
    for (size_t i = 0; i < data.size(); i += 255) {
        const size_t len = std::min<size_t>(255, data.size() - i);
        b += char(len);
        b += data.substr(i, len);
    }
    b += char(0), b += char(0x3b);
    return b;
}

std::vector<uint8_t> pattern(int w, int h) {
    std::vector<uint8_t> v;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) v.push_back(uint8_t((x * 3 + y * 5 + x * y) % 4));
    return v;
}

// An interlaced file's rows stay in their stored order (0, 8, 16, 4, 12, 2, ...), as POV-Ray
// 3.7 shows them.
TEST(GifReader, PaletteAndIndicesPlainAndInterlaced) {
    const int w = 7, h = 19;
    const std::vector<uint8_t> image = pattern(w, h);
    for (bool interlaced : {false, true})
        for (bool local : {false, true}) {
            std::vector<uint8_t> want;
            for (int y : stored_rows(h, interlaced))
                want.insert(want.end(), image.begin() + y * w, image.begin() + (y + 1) * w);
            const ImageFile img =
                read_image(write("p.gif", make_gif(w, h, image, interlaced, local)).string(), Format::Gif);
            EXPECT_EQ(img.width, w);
            EXPECT_EQ(img.height, h);
            ASSERT_TRUE(img.has_palette());
            EXPECT_EQ(img.indices, want) << "interlaced " << interlaced << " local " << local;
            EXPECT_FLOAT_EQ(img.palette[1][0], 1.0f);
            EXPECT_FLOAT_EQ(img.palette[3][2], 0x30 / 255.0f);
            EXPECT_FLOAT_EQ(img.palette[3][3], 1.0f);
            EXPECT_EQ(img.channels, 3);
        }
}

// The transparent index of a graphic control extension: that entry's alpha is 0.
TEST(GifReader, TransparentIndexHasNoAlpha) {
    const ImageFile img = read_gif(write("a.gif", make_gif(4, 4, pattern(4, 4), false, false, true)).string());
    EXPECT_EQ(img.channels, 4);
    EXPECT_TRUE(img.has_alpha());
    EXPECT_FLOAT_EQ(img.palette[1][3], 0.0f);
    EXPECT_FLOAT_EQ(img.palette[0][3], 1.0f);
    EXPECT_FLOAT_EQ(img.palette[2][3], 1.0f);
}

TEST(GifReader, DamagedFilesAreErrors) {
    const std::string good = make_gif(5, 4, pattern(5, 4), false, false);
    EXPECT_THROW(read_gif(write("t.gif", good.substr(0, good.size() / 2)).string()), ImageError);
    EXPECT_THROW(read_gif(write("n.gif", "GIF88a" + good.substr(6)).string()), ImageError);
    std::string bad_size = good;
    bad_size[13 + 12 + 8 + 10] = char(11);  // minimum code size 11
    EXPECT_THROW(read_gif(write("c.gif", bad_size).string()), ImageError);
    EXPECT_THROW(read_gif(temp_file("missing.gif").string()), ImageError);
}

const char* kPot = "/usr/share/povray-3.7/include/mtmand.pot";

// Every pixel of Fractint's LZW stream (12-bit codes, a full table) as OpenImageIO decodes it.
TEST(GifReader, AgreesWithOpenImageIO) {
    if (!fs::exists(kPot)) GTEST_SKIP() << "povray-includes is not installed";
    const fs::path copy = temp_file("mtmand.gif");
    fs::copy_file(kPot, copy, fs::copy_options::overwrite_existing);
    const ImageFile ours = read_gif(copy.string()), theirs = read_with_oiio(copy.string());
    ASSERT_EQ(ours.width, 320);
    ASSERT_EQ(ours.height, 120);
    ASSERT_EQ(theirs.width, ours.width);
    ASSERT_EQ(theirs.height, ours.height);
    int differ = 0;
    for (size_t i = 0; i < ours.pixels(); ++i)
        for (int c = 0; c < 3; ++c)
            differ += std::abs(ours.palette[ours.indices[i]][size_t(c)] -
                               theirs.values[i * size_t(theirs.channels) + size_t(c)]) > 1e-6f;
    EXPECT_EQ(differ, 0);
}

// POT: the left half's indices are the high bytes of the heights, the right half's the low.
TEST(PotReader, SixteenBitHeightsFromBothHalves) {
    if (!fs::exists(kPot)) GTEST_SKIP() << "povray-includes is not installed";
    const ImageFile gif = read_gif(kPot), pot = read_image(kPot, Format::Pot);
    ASSERT_EQ(pot.width, 160);
    ASSERT_EQ(pot.height, 120);
    EXPECT_EQ(pot.channels, 1);
    EXPECT_EQ(pot.bit_depth, 16);
    EXPECT_FALSE(pot.has_palette());
    int distinct_low = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const unsigned hi = gif.indices[size_t(y * 320 + x)], lo = gif.indices[size_t(y * 320 + x + 160)];
            ASSERT_EQ(std::lround(pot.values[size_t(y * 160 + x)] * 65535.0), long(hi * 256 + lo));
            distinct_low += lo != 0;
        }
    EXPECT_GT(distinct_low, 1000);  // the low bytes carry detail
    EXPECT_THROW(read_pot(write("odd.gif", make_gif(5, 4, pattern(5, 4), false, false)).string()),
                 ImageError);
}

}  // namespace
}  // namespace lumen::image

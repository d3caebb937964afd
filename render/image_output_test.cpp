#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <thread>

#include <OpenImageIO/imageio.h>

#include "base/diagnostics.hpp"
#include "render/image_output.hpp"

namespace lumen::render {
namespace {

scene::Scene legacy() { return {}; }
scene::Scene v37() {
    scene::Scene s;
    s.language_version = 3.7;
    s.version_given = true;
    return s;
}

TEST(ImageOutput, GammaModels) {
    const OutputOptions o;
    // No #version: bytes are the values, quantised in float as POV does (0.7f·255 rounds to
    // 178.5 there: povray writes 179).
    EXPECT_EQ(encode_8bit(0.7, legacy(), o), 179);
    EXPECT_EQ(encode_8bit(0.7, v37(), o), 218);     // 3.7: sRGB encode of linear values
    scene::Scene g22 = v37();
    g22.globals.assumed_gamma = 2.2;
    EXPECT_EQ(encode_8bit(0.7, g22, o), 180);       // power law decode, then sRGB
    scene::Scene legacy_g1 = legacy();
    legacy_g1.globals.assumed_gamma = 1.0;          // a legacy scene with assumed_gamma
    EXPECT_EQ(encode_8bit(0.7, legacy_g1, o), 218);
    EXPECT_EQ(encode_8bit(0.21404114, v37(), o), 128);  // srgb 0.5 round trip
}

TEST(ImageOutput, ClipsAndRoundsHalfUp) {
    const OutputOptions o;
    EXPECT_EQ(encode_8bit(-1, legacy(), o), 0);
    EXPECT_EQ(encode_8bit(4.0, legacy(), o), 255);
    EXPECT_EQ(encode_8bit(0.5 / 255, legacy(), o), 1);  // floor(v·255 + 0.5)
    OutputOptions linear;
    linear.file_gamma = 1.0;
    EXPECT_EQ(encode_8bit(0.5, v37(), linear), 128);
}

Image gradient_image() {
    Image img;
    img.width = 4;
    img.height = 2;
    img.pixels.assign(4 * 2 * 5, 0.f);
    for (int x = 0; x < 4; ++x) {
        img.at(x, 0)[0] = float(x) / 3;
        img.at(x, 1)[1] = 2.0f;  // over-range: clipped only when written
    }
    return img;
}

TEST(ImageOutput, WritesPngAndPpmWithIdenticalPixels) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_test";
    std::filesystem::create_directories(dir);
    const Image img = gradient_image();
    for (FileType type : {FileType::PNG, FileType::PPM}) {
        OutputOptions o;
        o.type = type;
        const std::string path = (dir / (type == FileType::PNG ? "t.png" : "t.ppm")).string();
        write_image(img, legacy(), o, path);
        auto in = OIIO::ImageInput::open(path);
        ASSERT_TRUE(in) << path;
        std::vector<unsigned char> px(4 * 2 * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
        EXPECT_EQ(px[0], 0);
        EXPECT_EQ(px[3], 85);
        EXPECT_EQ(px[9], 255);
        EXPECT_EQ(px[12 + 1], 255);  // clipped
        EXPECT_EQ(px[12 + 0], 0);
    }
    // No temporary files are left behind.
    int files = 0;
    for (auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2);
    std::filesystem::remove_all(dir);
}

// 8-bit files look their levels up in a table: every value must still get encode_8bit's.
TEST(ImageOutput, EightBitFilesHoldTheLevelsOfEncode8bit) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_levels";
    std::filesystem::create_directories(dir);
    Image img;
    img.width = 256;
    img.height = 64;
    img.pixels.assign(size_t(img.width) * img.height * 5, 0.f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    for (float& v : img.pixels) v = u(rng);
    for (int x = 0; x < img.width; ++x) img.at(x, 0)[0] = float(x) / 255;  // every level
    scene::Scene g22 = v37();
    g22.globals.assumed_gamma = 2.2;
    int compared = 0;
    for (const scene::Scene& s : {legacy(), v37(), g22})
        for (double file_gamma : {-1.0, 2.2}) {
            OutputOptions o;
            o.file_gamma = file_gamma;
            const std::string path = (dir / "levels.png").string();
            write_image(img, s, o, path);
            auto in = OIIO::ImageInput::open(path);
            ASSERT_TRUE(in);
            std::vector<unsigned char> px(size_t(img.width) * img.height * 3);
            ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
            for (int y = 0; y < img.height; ++y)
                for (int x = 0; x < img.width; ++x)
                    for (int c = 0; c < 3; ++c, ++compared)
                        ASSERT_EQ(px[(size_t(y) * img.width + x) * 3 + c],
                                  encode_8bit(img.at(x, y)[c], s, o))
                            << x << "," << y << " gamma " << file_gamma;
        }
    EXPECT_EQ(compared, 6 * 256 * 64 * 3);
    std::filesystem::remove_all(dir);
}

TEST(ImageOutput, SixteenBitPngAndExr) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_test16";
    std::filesystem::create_directories(dir);
    const Image img = gradient_image();
    OutputOptions o;
    o.bits = 16;
    const std::string png = (dir / "t16.png").string();
    write_image(img, legacy(), o, png);
    auto in = OIIO::ImageInput::open(png);
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT16);
    std::vector<uint16_t> px(4 * 2 * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, px.data()));
    EXPECT_EQ(px[3], 21845);  // floor(1/3 · 65535 + 0.5)
    in->close();

    o.type = FileType::EXR;
    const std::string exr = (dir / "t.exr").string();
    write_image(img, v37(), o, exr);
    auto ein = OIIO::ImageInput::open(exr);
    ASSERT_TRUE(ein);
    std::vector<float> f(4 * 2 * 3);
    ASSERT_TRUE(ein->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, f.data()));
    EXPECT_NEAR(f[12 + 1], 2.0f, 1e-3);  // HDR keeps over-range values
    std::filesystem::remove_all(dir);
}

std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ImageOutput, SixteenBitPpmIsBigEndianWithMaxval65535) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_ppm16";
    std::filesystem::create_directories(dir);
    OutputOptions o;
    o.type = FileType::PPM;
    o.bits = 16;
    write_image(gradient_image(), legacy(), o, (dir / "t.ppm").string());
    const std::string b = file_bytes(dir / "t.ppm");
    const std::string header = "P6\n4 2\n65535\n";
    ASSERT_EQ(b.size(), header.size() + 4 * 2 * 3 * 2);
    EXPECT_EQ(b.substr(0, header.size()), header);
    const auto sample = [&](size_t i) {
        return unsigned(uint8_t(b[header.size() + 2 * i])) * 256 +
               uint8_t(b[header.size() + 2 * i + 1]);
    };
    EXPECT_EQ(sample(3), 21845u);  // pixel 1 red: floor(1/3 · 65535 + 0.5)
    EXPECT_EQ(sample(12 + 1), 65535u);
    std::filesystem::remove_all(dir);
}

TEST(ImageOutput, PngColourChunksFollowTheEncoding) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_chunks";
    std::filesystem::create_directories(dir);
    const auto chunks_of = [&](const scene::Scene& s, double file_gamma) {
        OutputOptions o;
        o.file_gamma = file_gamma;
        write_image(gradient_image(), s, o, (dir / "t.png").string());
        const std::string b = file_bytes(dir / "t.png");
        return std::string(b.find("sRGB") != std::string::npos ? "sRGB " : "") +
               (b.find("gAMA") != std::string::npos ? "gAMA" : "");
    };
    EXPECT_EQ(chunks_of(v37(), -1), "sRGB gAMA");  // sRGB curve (with the matching gAMA)
    EXPECT_EQ(chunks_of(v37(), 1.0), "gAMA");      // a power law
    EXPECT_EQ(chunks_of(legacy(), -1), "");        // legacy: the bytes are the working values
    std::filesystem::remove_all(dir);
}

TEST(ImageOutput, TiffThroughTheOiioModule) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_tiff";
    std::filesystem::create_directories(dir);
    OutputOptions o;
    o.type = FileType::TIFF;
    const std::string tif = (dir / "t.tif").string();
    write_image(gradient_image(), legacy(), o, tif);
    auto in = OIIO::ImageInput::open(tif);
    ASSERT_TRUE(in);
    std::vector<unsigned char> px(4 * 2 * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    EXPECT_EQ(px[3], 85);
    EXPECT_EQ(px[12 + 1], 255);
    std::filesystem::remove_all(dir);
}

TEST(ImageOutput, UnwritableFolderIsAnError) {
    OutputOptions o;
    EXPECT_THROW(write_image(gradient_image(), legacy(), o, "/nonexistent-folder/x.png"),
                 lumen::LumenError);
}

// A 37x23 image with 8-pixel blocks: ragged last blocks, values across the whole range.
Image noise_image() {
    Image img;
    img.width = 37;
    img.height = 23;
    img.pixels.resize(size_t(37) * 23 * 5);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-0.2f, 1.3f);
    for (float& v : img.pixels) v = u(rng);
    return img;
}

TEST(ImageOutput, StreamedPngEncodedBlockByBlockEqualsTheWholeImageFile) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_stream";
    std::filesystem::create_directories(dir);
    const Image img = noise_image();
    for (int bits : {8, 16}) {
        OutputOptions o;
        o.bits = bits;
        o.alpha = bits == 16;
        write_image(img, v37(), o, (dir / "whole.png").string());
        // Blocks in a shuffled order from two threads, as the render's workers hand them over.
        std::vector<std::array<int, 4>> blocks;
        for (int y = 0; y < img.height; y += 8)
            for (int x = 0; x < img.width; x += 8)
                blocks.push_back({x, y, std::min(x + 7, img.width - 1), std::min(y + 7, img.height - 1)});
        std::shuffle(blocks.begin(), blocks.end(), std::mt19937(bits));
        ImageEncoder encoder(v37(), o, img.width, img.height);
        encoder.stream_to((dir / "streamed.png").string());
        auto half = [&](size_t from) {
            for (size_t i = from; i < blocks.size(); i += 2)
                encoder.encode(img, blocks[i][0], blocks[i][1], blocks[i][2], blocks[i][3]);
        };
        std::thread other(half, 1);
        half(0);
        other.join();
        encoder.write((dir / "streamed.png").string());
        EXPECT_EQ(file_bytes(dir / "streamed.png"), file_bytes(dir / "whole.png")) << bits;
    }
    std::filesystem::remove_all(dir);
}

TEST(ImageOutput, AbandonedStreamLeavesNoFile) {
    const auto dir = std::filesystem::temp_directory_path() / "lumen_image_output_abandon";
    std::filesystem::create_directories(dir);
    const Image img = noise_image();
    {
        ImageEncoder encoder(v37(), {}, img.width, img.height);
        encoder.stream_to((dir / "x.png").string());
        encoder.encode(img, 0, 0, img.width - 1, 10);  // the render failed after this
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    // A stream to a folder that does not exist fails when it is finished.
    ImageEncoder encoder(v37(), {}, img.width, img.height);
    encoder.stream_to("/nonexistent-folder/x.png");
    encoder.encode(img, 0, 0, img.width - 1, img.height - 1);
    EXPECT_THROW(encoder.write("/nonexistent-folder/x.png"), lumen::LumenError);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lumen::render

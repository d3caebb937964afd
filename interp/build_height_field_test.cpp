// height_field through the interpreter: POV-Ray's heights per image format (measured with
// min_extent/max_extent on 2 x 2 images), the grid orientation, options and errors.
#include <filesystem>
#include <fstream>

#include "image/image_file.hpp"
#include "interp/build_test_support.hpp"

namespace lumen::interp::testing {
namespace {

namespace fs = std::filesystem;

std::string temp_image(const std::string& name, const std::string& bytes) {
    fs::path dir = fs::temp_directory_path() / "lumen_height_field_tests";
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return (dir / name).string();
}

std::string probe_image(const std::string& name) {
    return std::string(LUMEN_SOURCE_DIR) + "/tests/data/images/" + name;
}

using BuildHeightField = BuildTest;

TEST_F(BuildHeightField, HeightsPerFormat) {
    // 2 x 2 images of one level: PGM and TGA grey k -> k * 257; PPM (8-bit RGB) -> red * 256
    // + green.
    const std::string pgm = temp_image("g3.pgm", std::string("P5\n2 2\n255\n") + std::string(4, '\3'));
    auto g = shape_of<scene::HeightField>("height_field { pgm \"" + pgm + "\" }");
    EXPECT_EQ(g.columns, 2);
    EXPECT_EQ(g.rows, 2);
    EXPECT_EQ(g.at(0, 0), 771);
    std::string rgb = "P6\n2 2\n255\n";
    for (int i = 0; i < 4; ++i) rgb += "\310\7\11";  // 200, 7, 9
    const std::string ppm = temp_image("c200.ppm", rgb);
    EXPECT_EQ(shape_of<scene::HeightField>("height_field { \"" + ppm + "\" }").at(1, 1), 51207);
    // With a gamma the decoded float: (200/255)^2 * 65535 = 40313.6.
    const std::string pgm200 = temp_image("g200.pgm", std::string("P5\n2 2\n255\n") + std::string(4, '\310'));
    EXPECT_EQ(shape_of<scene::HeightField>("height_field { pgm \"" + pgm200 + "\" gamma 2 }").at(0, 1),
              40313);
    // PNG grey 8-bit is requantised: the probe image's heights are multiples of 257.
    auto png = shape_of<scene::HeightField>("height_field { png \"" + probe_image("hf_grey8.png") + "\" }");
    EXPECT_EQ(png.columns, 24);
    EXPECT_EQ(png.rows, 18);
    for (uint16_t h : *png.heights) EXPECT_EQ(h % 257, 0);
    // The palette image gives index * 256.
    auto pal = shape_of<scene::HeightField>("height_field { png \"" + probe_image("hf_palette.png") + "\" }");
    for (uint16_t h : *pal.heights) EXPECT_EQ(h % 256, 0);
}

TEST_F(BuildHeightField, BottomImageRowIsZZero) {
    // 2 columns x 3 rows, rows top to bottom 10, 20, 30 (ASCII PGM, maxval 255).
    const std::string pgm = temp_image("rows.pgm", "P2\n2 3\n255\n10 11\n20 21\n30 31\n");
    auto h = shape_of<scene::HeightField>("height_field { pgm \"" + pgm + "\" }");
    EXPECT_EQ(h.at(0, 0), 30 * 257);
    EXPECT_EQ(h.at(1, 0), 31 * 257);
    EXPECT_EQ(h.at(0, 2), 10 * 257);
}

TEST_F(BuildHeightField, OptionsAndTheSameFileInEveryFormatGivesTheSameHeights) {
    auto a = shape_of<scene::HeightField>("height_field { \"" + probe_image("hf_rgb8.png") +
                                          "\" water_level 0.25 smooth hierarchy off translate 1 }");
    EXPECT_DOUBLE_EQ(a.water_level, 0.25);
    EXPECT_TRUE(a.smooth);
    EXPECT_FALSE(a.hierarchy);
    auto b = shape_of<scene::HeightField>("height_field { ppm \"" + probe_image("hf_rgb.ppm") + "\" }");
    auto c = shape_of<scene::HeightField>("height_field { \"" + probe_image("hf_rgb_rle.tga") + "\" }");
    EXPECT_EQ(*a.heights, *b.heights);
    EXPECT_EQ(*a.heights, *c.heights);
    EXPECT_EQ(a.heights_hash, b.heights_hash);
    auto g = shape_of<scene::HeightField>("height_field { tga \"" + probe_image("hf_grey.tga") + "\" }");
    auto p = shape_of<scene::HeightField>("height_field { pgm \"" + probe_image("hf_grey.pgm") + "\" }");
    EXPECT_EQ(*g.heights, *p.heights);
    EXPECT_NE(g.heights_hash, a.heights_hash);
}

TEST_F(BuildHeightField, FunctionImagesGiveHeightXZFromFunctionX1MinusZ) {
    auto h = shape_of<scene::HeightField>(
        "#declare F = function { x * 0.5 + y * 0.25 }\n"
        "height_field { function 5, 3 { F(x, y, 0) } water_level 0.1 }");
    EXPECT_EQ(h.columns, 5);
    EXPECT_EQ(h.rows, 3);
    EXPECT_DOUBLE_EQ(h.water_level, 0.1);
    // Grid z = 0 is the image's bottom row, function y = 1: trunc((0 + 0.25) * 65535).
    EXPECT_EQ(h.at(0, 0), 16383);
    EXPECT_EQ(h.at(4, 2), 32767);  // x = 1, y = 0
    EXPECT_EQ(h.at(2, 1), uint16_t((0.25 + 0.125) * 65535));
    // Values beyond [0, 1] are clamped; pigment functions are not supported.
    EXPECT_EQ(shape_of<scene::HeightField>("height_field { function 2, 2 { 3 } }").at(1, 1), 65535);
    auto o = first_object("height_field { function 10, 10 { pigment { rgb 1 } } }");
    EXPECT_TRUE(std::holds_alternative<scene::UnsupportedShape>(o->shape));
    EXPECT_EQ(error_of("height_field { function 1, 10 { x } }"),
              "t.pov:1:25: error: a function image needs 2 to 65536 pixels a side");
}

TEST_F(BuildHeightField, ErrorsAreLocated) {
    EXPECT_EQ(error_of("height_field { png \"no_such_file.png\" }"),
              "t.pov:1:20: error: cannot find image file 'no_such_file.png'");
    EXPECT_EQ(error_of("height_field { \"a.xyz\" }"),
              "t.pov:1:16: error: cannot tell the image type of 'a.xyz' from its extension");
    const std::string bad = temp_image("bad.png", "\x89PNG\r\n\x1a\nnot really");
    EXPECT_NE(error_of("height_field { png \"" + bad + "\" }").find("t.pov:1:20: error: cannot read image"),
              std::string::npos);
    const std::string one = temp_image("one.pgm", "P2\n1 1\n255\n7\n");
    EXPECT_EQ(error_of("height_field { pgm \"" + one + "\" }"),
              "t.pov:1:20: error: a height_field image needs at least 2 x 2 pixels");
}

// GIF heights are palette indices times 256; POT (Fractint's mtmand.pot, a GIF twice as wide)
// joins each row's left-half index (high byte) and right-half index (low byte). The heights
// agree with POV-Ray's: trace() down onto the POT field at six points gave its heights to 8
// digits.
TEST_F(BuildHeightField, GifIndicesAndPotHeights) {
    const std::string pot = "/usr/share/povray-3.7/include/mtmand.pot";
    if (!fs::exists(pot)) GTEST_SKIP() << "povray-includes is not installed";
    const lumen::image::ImageFile file = lumen::image::read_gif(pot);
    auto index = [&](int x, int z) { return unsigned(file.indices[size_t((119 - z) * 320 + x)]); };
    auto gif = shape_of<scene::HeightField>("height_field { gif \"" + pot + "\" }");
    ASSERT_EQ(gif.columns, 320);
    ASSERT_EQ(gif.rows, 120);
    auto field = shape_of<scene::HeightField>("height_field { pot \"" + pot + "\" }");
    ASSERT_EQ(field.columns, 160);
    ASSERT_EQ(field.rows, 120);
    for (int z = 0; z < 120; z += 7)
        for (int x = 0; x < 160; x += 3) {
            EXPECT_EQ(gif.at(x, z), index(x, z) * 256);
            ASSERT_EQ(field.at(x, z), index(x, z) * 256 + index(x + 160, z)) << x << ", " << z;
        }
}

}  // namespace
}  // namespace lumen::interp::testing

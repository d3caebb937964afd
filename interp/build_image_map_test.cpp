// image_map, bump_map, material_map and image_pattern through the interpreter: where each may
// stand, its modifiers, POV-Ray's gamma rules per #version, and located errors.
#include <cmath>

#include "interp/build_test_support.hpp"
#include "scene/image_map.hpp"

namespace lumen::interp::testing {
namespace {

namespace pattern = scene::pattern;

std::string probe(const std::string& name) {
    return "\"" + std::string(LUMEN_SOURCE_DIR) + "/tests/data/images/" + name + "\"";
}

using BuildImageMap = BuildTest;

TEST_F(BuildImageMap, ImageMapReadsTheFileAndItsModifiers) {
    const scene::Texture t = texture_of("#version 3.7;\nplane { z, 0 pigment { image_map { png " +
                                        probe("map_rgb.png") +
                                        " map_type 1 interpolate 2 once } scale 2 } }");
    const auto* k = std::get_if<pattern::ImageMap>(&t.pigment->pattern.kind);
    ASSERT_NE(k, nullptr);
    ASSERT_NE(k->data, nullptr);
    EXPECT_EQ(k->data->image.width, 20);
    EXPECT_EQ(k->data->image.height, 14);
    EXPECT_EQ(k->map_type, 1);
    EXPECT_EQ(k->interpolate, 2);
    EXPECT_TRUE(k->once);
    EXPECT_TRUE(k->data->may_pass_light);  // clear off the map
    EXPECT_EQ(t.pigment->pattern.frequency, 0);
}

// Only image_map decodes: a chunk-less PNG as sRGB in a 3.7 scene, raw before 3.7 without an
// assumed_gamma, raw in a 3.6 scene whose working gamma is the file's; the other uses raw.
TEST_F(BuildImageMap, GammaRulesFollowTheVersion) {
    auto top_left = [&](const std::string& scene) {
        const scene::Texture t = texture_of(scene);
        const scene::Pigment& p = *t.pigment;
        if (const auto* k = std::get_if<pattern::ImageMap>(&p.pattern.kind)) return k->data->image.colours[0][0];
        return std::get_if<pattern::ImagePattern>(&p.pattern.kind)->data->image.colours[0][0];
    };
    // The top-left pixel of map_rgb.png is white (1.0) and its neighbour (1, 1) has red 13.
    auto second_row = [&](const std::string& scene) {
        const scene::Texture t = texture_of(scene);
        const auto& img = std::get_if<pattern::ImageMap>(&t.pigment->pattern.kind)->data->image;
        return img.colours[size_t(img.width) * 2 + 1][0];  // column 1, row 2: red 13/255
    };
    const std::string file = probe("map_rgb.png");
    const float raw = 13.0f / 255;
    const double srgb = std::pow((raw + 0.055) / 1.055, 2.4);  // the sRGB curve above 0.04045
    EXPECT_FLOAT_EQ(top_left("#version 3.7;\nplane { z, 0 pigment { image_map { png " + file + " } } }"), 1.0f);
    EXPECT_NEAR(second_row("#version 3.7;\nplane { z, 0 pigment { image_map { png " + file + " } } }"),
                srgb, 1e-6);
    EXPECT_FLOAT_EQ(second_row("#version 3.6;\nplane { z, 0 pigment { image_map { png " + file + " } } }"), raw);
    EXPECT_FLOAT_EQ(second_row("#version 3.6; global_settings { assumed_gamma 2.2 }\n"
                               "plane { z, 0 pigment { image_map { png " + file + " } } }"),
                    raw);
    EXPECT_NEAR(second_row("#version 3.7;\nplane { z, 0 pigment { image_map { png " + file + " gamma 2 } } }"),
                raw * raw, 1e-7);
    // 3.7 with a working gamma of 2: sRGB-decoded, then encoded for it.
    EXPECT_NEAR(second_row("#version 3.7; global_settings { assumed_gamma 2 }\n"
                           "plane { z, 0 pigment { image_map { png " + file + " } } }"),
                std::sqrt(srgb), 1e-6);
    EXPECT_FLOAT_EQ(top_left("#version 3.7;\nplane { z, 0 pigment { image_pattern { png " + file + " } } }"), 1.0f);
}

TEST_F(BuildImageMap, PaletteFilterAndTransmit) {
    const scene::Texture t = texture_of("plane { z, 0 pigment { image_map { png " + probe("map_palette.png") +
                                        " filter all 0.25 transmit 2, 0.5 } } }");
    const auto& k = std::get<pattern::ImageMap>(t.pigment->pattern.kind);
    const auto& ft = k.data->entry_filter_transmit;
    ASSERT_EQ(ft.size(), 6u);
    EXPECT_FLOAT_EQ(ft[0][0], 0.25f);
    EXPECT_FLOAT_EQ(ft[2][1], 0.5f);
    EXPECT_NEAR(ft[4][1], 1 - 128 / 255.0, 1e-6);  // the file's tRNS
    EXPECT_FLOAT_EQ(ft[3][1], 0.0f);
    EXPECT_EQ(k.entry_changes, (std::vector<double>{1, 2, 0.5}));
    // A true-colour image adds `filter all` and `transmit all` to every pixel.
    const scene::Texture rgb = texture_of("plane { z, 0 pigment { image_map { png " + probe("map_rgb.png") +
                                          " transmit all 0.3 } } }");
    EXPECT_DOUBLE_EQ(std::get<pattern::ImageMap>(rgb.pigment->pattern.kind).transmit, double(0.3f));
}

TEST_F(BuildImageMap, BumpMapSetsTheAmount) {
    const scene::Texture t = texture_of("plane { z, 0 normal { bump_map { png " + probe("map_grey8.png") +
                                        " bump_size 3 use_index } } }");
    ASSERT_NE(std::get_if<pattern::BumpMap>(&t.normal->pattern.kind), nullptr);
    EXPECT_DOUBLE_EQ(t.normal->amount, 3);
    EXPECT_TRUE(std::get<pattern::BumpMap>(t.normal->pattern.kind).use_index);
    const scene::Texture after = texture_of("plane { z, 0 normal { bump_map { png " + probe("map_grey8.png") +
                                            " } 0.25 } }");
    EXPECT_DOUBLE_EQ(after.normal->amount, 0.25);
}

TEST_F(BuildImageMap, MaterialMapTexturesAreItsEntries) {
    const scene::Texture t = texture_of("plane { z, 0 texture { material_map { png " + probe("map_palette.png") +
                                        " texture { pigment { rgb 1 } } texture { pigment { rgb x } }"
                                        " texture { pigment { rgb y } } } } }");
    const auto* k = std::get_if<pattern::MaterialMap>(&t.pattern.kind);
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->textures, 3);
    ASSERT_EQ(t.texture_map.size(), 3u);
    EXPECT_DOUBLE_EQ(t.texture_map[2].value, 2);
    EXPECT_TRUE(t.list_form);
}

TEST_F(BuildImageMap, BlocksStandOnlyWhereTheyBelong) {
    const std::string f = probe("map_rgb.png");
    EXPECT_EQ(error_of("plane { z, 0 normal { image_map { png " + f + " } } }"),
              "t.pov:1:23: error: an image_map belongs in a pigment, not a normal");
    EXPECT_NE(error_of("plane { z, 0 pigment { bump_map { png " + f + " } } }").find("a bump_map belongs in a normal"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { material_map { png " + f + " texture { } } } }")
                  .find("a material_map belongs in a texture"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 texture { material_map { png " + f + " } } }")
                  .find("needs at least one texture"),
              std::string::npos);
}

TEST_F(BuildImageMap, LocatedErrors) {
    const std::string f = probe("map_rgb.png");
    EXPECT_EQ(error_of("plane { z, 0 pigment { image_map { png \"no_such.png\" } } }"),
              "t.pov:1:40: error: cannot find image file 'no_such.png'");
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png " + f + " map_type 3 } } }")
                  .find("an image_map's map_type must be one of 0, 1, 2, 5"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png " + f + " interpolate 1 } } }")
                  .find("an image_map's interpolate must be one of 2, 3, 4"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png " + f + " filter 2, 0.5 } } }")
                  .find("sets a palette entry, and this image has no palette"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png " + probe("map_palette.png") + " filter 6, 0.5 } } }")
                  .find("palette entry 6 is not in the image's 6 entries"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { png " + probe("map_palette.png") + " transmit 1e30, 0.5 } } }")
                  .find("is not in the image's 6 entries"),
              std::string::npos);
    EXPECT_NE(error_of("plane { z, 0 pigment { image_map { sys \"x.sys\" } } }").find("sys images cannot"),
              std::string::npos);
    // Other image blocks take any map_type and interpolate, as POV-Ray does.
    EXPECT_EQ(std::get<pattern::BumpMap>(texture_of("plane { z, 0 normal { bump_map { png " + f +
                                                    " map_type 3 interpolate 1 } } }")
                                             .normal->pattern.kind)
                  .map_type,
              3);
}

}  // namespace
}  // namespace lumen::interp::testing

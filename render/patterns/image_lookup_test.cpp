// Image patterns at single points, on a hand-made 4 x 2 image: where each map type puts a
// point, tiling and `once`, the interpolations, the bump_map heights and material_map's index
// rule. Whole renders are compared with POV-Ray's in tests/patterns/image_map.pov.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/patterns/image_lookup.hpp"
#include "scene/image_map.hpp"

namespace lumen::render::test {
namespace {

namespace pattern = scene::pattern;

// 4 columns x 2 rows; pixel (c, r) has red c / 4 and green r, blue 0.5; alpha 1 except the
// bottom-right pixel (alpha 0.5).
std::shared_ptr<scene::ImageData> small_image() {
    auto d = std::make_shared<scene::ImageData>();
    d->image.width = 4;
    d->image.height = 2;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 4; ++c)
            d->image.colours.push_back({c / 4.0f, float(r), 0.5f, r == 1 && c == 3 ? 0.5f : 1.0f});
    d->image.alpha = true;
    return d;
}

template <class K> K kind() {
    K k;
    k.data = small_image();
    return k;
}

TEST(ImageLookup, PlanarPutsTheBottomLeftCornerAtTheOrigin) {
    const auto k = kind<pattern::ImageMap>();
    const auto at = image_position(k, {0.1, 0.1, 7});
    ASSERT_TRUE(at);
    EXPECT_EQ(int(at->x), 0);
    EXPECT_EQ(int(at->y), 1);  // the bottom row
    EXPECT_EQ(int(image_position(k, {0.9, 0.9, 0})->y), 0);
    // Tiled: one unit on in x or y is the same pixel, and so is a negative coordinate's wrap.
    EXPECT_EQ(int(image_position(k, {1.3, 0.2, 0})->x), 1);
    EXPECT_EQ(int(image_position(k, {-0.3, 0.2, 0})->x), 2);
    pattern::ImageMap once = k;
    once.once = true;
    EXPECT_FALSE(image_position(once, {1.3, 0.2, 0}));
    EXPECT_FALSE(image_position(once, {0.3, -0.2, 0}));
    EXPECT_TRUE(image_position(once, {0.3, 0.2, 0}));
    // Off the map an image_map is clear, so the ray goes on.
    const scene::Colour clear = image_map_colour(once, {2, 2, 0});
    EXPECT_EQ(clear.t, 1);
    EXPECT_EQ(clear.f, 0);
}

TEST(ImageLookup, SphericalCylindricalAndTorusAngles) {
    auto k = kind<pattern::ImagePattern>();
    k.map_type = 1;
    // +x is longitude 0, +z a quarter turn on; the equator is half way up.
    EXPECT_NEAR(image_position(k, {1, 0, 0})->x, 0, 1e-9);
    EXPECT_NEAR(image_position(k, {0, 0, 1})->x, 1, 1e-9);
    EXPECT_NEAR(image_position(k, {0, 0, -1})->x, 3, 1e-9);
    EXPECT_NEAR(image_position(k, {1, 0, 0})->y, 1, 1e-9);
    EXPECT_FALSE(image_position(k, {0, 0, 0}));
    k.map_type = 2;
    k.once = true;
    EXPECT_FALSE(image_position(k, {1, 1.5, 0}));
    EXPECT_NEAR(image_position(k, {-1, 0.25, 0})->x, 2, 1e-9);
    k.map_type = 5;
    k.once = false;
    // On the ring's outer equator the angle around the tube is pi: half way up.
    EXPECT_NEAR(image_position(k, {1.5, 0, 0})->y, 1, 1e-9);
}

TEST(ImageLookup, InterpolationIsExactAtPixelCentres) {
    auto k = kind<pattern::ImageMap>();
    for (int mode : {0, 2, 3, 4}) {
        k.interpolate = mode;
        // The centre of column 2 of the top row.
        const scene::Colour c = image_colour(k, {2.5, 0.5});
        EXPECT_FLOAT_EQ(float(c.r), 0.5f) << mode;
        EXPECT_FLOAT_EQ(float(c.g), 0.0f) << mode;
    }
    k.interpolate = 2;
    // Half way between columns 1 and 2 of the top row, bilinear: the mean of their reds.
    EXPECT_FLOAT_EQ(float(image_colour(k, {2.0, 0.5}).r), 0.375f);
    // Between the rows (wrapping from the top row to the bottom one above it): the mean green.
    EXPECT_FLOAT_EQ(float(image_colour(k, {1.5, 0.0}).g), 0.5f);
    // Alpha becomes transmit, before interpolation.
    k.interpolate = 0;
    EXPECT_FLOAT_EQ(float(image_colour(k, {3.5, 1.5}).t), 0.5f);
}

TEST(ImageLookup, ImagePatternGreyAndAlpha) {
    auto k = kind<pattern::ImagePattern>();
    // Pixel (2, top row): grey of (0.5, 0, 0.5) in POV's weights.
    EXPECT_NEAR(evaluate(k, {0.6, 0.9, 0}), 0.297 * 0.5 + 0.114 * 0.5, 1e-6);
    k.use_alpha = true;
    EXPECT_FLOAT_EQ(float(evaluate(k, {0.9, 0.1, 0})), 0.5f);  // transmit of the clear pixel
    EXPECT_FLOAT_EQ(float(evaluate(k, {0.6, 0.1, 0})), 0.0f);
}

TEST(ImageLookup, MaterialIndexWrapsPastTheTextures) {
    auto k = kind<pattern::MaterialMap>();
    k.data = std::make_shared<scene::ImageData>(*k.data);
    auto& img = const_cast<scene::ImageData&>(*k.data).image;
    img.palette = true;
    img.colours.assign(12, {0, 0, 0, 1});
    img.indices = {0, 3, 7, 11, 2, 4, 5, 6};
    k.textures = 4;
    // Top row: index 0, 3, 7 (7 mod 4 = 3), 11 (mod 4 = 3); bottom row: 2, 4 (= n: the last), 5
    // (mod 4 = 1).
    EXPECT_EQ(evaluate(k, {0.1, 0.9, 0}), 0);
    EXPECT_EQ(evaluate(k, {0.3, 0.9, 0}), 3);
    EXPECT_EQ(evaluate(k, {0.6, 0.9, 0}), 3);
    EXPECT_EQ(evaluate(k, {0.9, 0.9, 0}), 3);
    EXPECT_EQ(evaluate(k, {0.3, 0.1, 0}), 4);
    EXPECT_EQ(evaluate(k, {0.6, 0.1, 0}), 1);
}

TEST(ImageLookup, BumpHeightsAreGreyOrPaletteIndex) {
    auto k = kind<pattern::BumpMap>();
    EXPECT_NEAR(bump_height(k, {0.5, 1.5}), 0.589 + 0.114 * 0.5, 1e-6);  // (0, 1, 0.5)
    k.data = std::make_shared<scene::ImageData>(*k.data);
    auto& img = const_cast<scene::ImageData&>(*k.data).image;
    img.palette = true;
    img.colours.assign(200, {0, 0, 0, 1});
    img.indices = {0, 1, 2, 3, 100, 150, 199, 3};
    k.use_index = true;
    EXPECT_EQ(bump_height(k, {1.5, 1.5}), 150);  // the raw index, not over 255
}

}  // namespace
}  // namespace lumen::render::test

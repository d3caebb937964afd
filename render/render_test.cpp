// render(): blocks on threads, partial renders, stats and errors, with the real Geometry.
#include <gtest/gtest.h>

#include "base/diagnostics.hpp"
#include "render/render.hpp"
#include "render/shade_test_support.hpp"

namespace lumen::render::test {
namespace {

scene::Scene lit_sphere() {
    scene::Scene s = scene_37();
    s.camera.location = {0, 0, -5};
    s.lights.push_back(point_light({-3, 4, -6}, {1, 1, 1}));
    Material m{rgb(0.8, 0.3, 0.2)};
    m.finish.phong = 0.5;
    s.objects.push_back(sphere({0, 0, 0}, 1, m));
    s.objects.push_back(plane({0, 1, 0}, -1, {rgb(0.5, 0.5, 0.5)}));
    return s;
}

TEST(Render, ThreadCountAndBlockOrderDoNotChangeTheImage) {
    const scene::Scene s = lit_sphere();
    RenderOptions o;
    o.width = 50;
    o.height = 40;
    o.block_size = 8;
    o.antialias = true;
    o.threads = 1;
    const Image one = render(s, o);
    o.threads = 4;
    RenderStats stats;
    const Image four = render(s, o, &stats);
    EXPECT_EQ(one.pixels, four.pixels);
    EXPECT_GE(stats.primary_rays, 50u * 40u);
    EXPECT_GT(stats.shadow_rays, 0u);
}

TEST(Render, MatchesTheTracerWithTheTestIntersector) {
    const scene::Scene s = lit_sphere();
    RenderOptions o;
    o.width = 32;
    o.height = 24;
    const Image img = render(s, o);
    const Image8 ref = render8(s, 32, 24);
    int worst = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
            worst = std::max(worst, std::abs(encode_8bit(img.at(x, y)[0], s, {}) - ref.at(x, y, 0)));
    EXPECT_LE(worst, 1);
}

TEST(Render, PartialRenderLeavesOtherPixelsBlack) {
    const scene::Scene s = lit_sphere();
    RenderOptions o;
    o.width = 32;
    o.height = 24;
    o.start_row = 9;
    o.end_row = 19;
    o.start_col = 4;
    o.end_col = 15;
    double last_progress = 0;
    const Image img = render(s, o, nullptr, [&](double p) { last_progress = p; });
    EXPECT_DOUBLE_EQ(last_progress, 1.0);
    EXPECT_EQ(img.at(0, 0)[0], 0.0f);
    EXPECT_EQ(img.at(20, 12)[0], 0.0f);
    EXPECT_GT(img.at(10, 12)[0] + img.at(10, 12)[1], 0.0f);  // inside the rendered window
}

TEST(Render, UnsupportedFeatureThrowsWithItsName) {
    scene::Scene s = lit_sphere();
    s.unsupported.push_back({"media", {}});
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    try {
        render(s, o);
        FAIL() << "expected LumenError";
    } catch (const lumen::LumenError& e) {
        EXPECT_NE(std::string(e.what()).find("media"), std::string::npos);
    }
}

}  // namespace
}  // namespace lumen::render::test

// Patterns and colour maps against POV-Ray 3.7 renders of a plane seen from above
// (render/testdata/p_*.pov: ambient 1, diffuse 0, no #version, so bytes = pigment values).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render/pattern.hpp"
#include "render/pigment.hpp"
#include "render/shade_test_support.hpp"

namespace lumen::render::test {
namespace {

scene::Pigment pigment_of(scene::PatternType type) {
    scene::Pigment p;
    p.pattern.kind = scene::make_pattern_kind(type);
    return p;
}

// Max channel difference between the pigment on plane y = height and the reference image
// (orthographic camera looking down -y, `size` units across, image top = +z).
int max_difference(const scene::Pigment& pigment, const std::string& reference, double size,
                   double height) {
    const Image8 ref = read_reference(reference);
    EXPECT_GT(ref.width, 0) << reference;
    int worst = 0;
    for (int j = 0; j < ref.height; ++j) {
        for (int i = 0; i < ref.width; ++i) {
            const double x = ((i + 0.5) / ref.width - 0.5) * size;
            const double z = (0.5 - (j + 0.5) / ref.height) * size;
            const scene::Colour c = evaluate_pigment(&pigment, {x, height, z});
            const double v[3] = {c.r, c.g, c.b};
            for (int k = 0; k < 3; ++k) {
                const int ours = int(std::floor(std::clamp(v[k], 0.0, 1.0) * 255 + 0.5));
                worst = std::max(worst, std::abs(ours - ref.at(i, j, k)));
            }
        }
    }
    return worst;
}

TEST(Pattern, BrickLayoutAndDefaultColours) {
    const scene::Pigment brick = pigment_of(scene::PatternType::Brick);
    EXPECT_EQ(max_difference(brick, "p_brick.ppm", 24, 0.3), 0);
    EXPECT_EQ(max_difference(brick, "p_brick_odd.ppm", 24, 4.1), 0);
}

TEST(Pattern, HexagonSquareAndRadialDefaults) {
    EXPECT_EQ(max_difference(pigment_of(scene::PatternType::Hexagon), "p_hexagon.ppm", 8, 0), 0);
    EXPECT_EQ(max_difference(pigment_of(scene::PatternType::Square), "p_square.ppm", 4, 0), 0);
    EXPECT_EQ(max_difference(pigment_of(scene::PatternType::Radial), "p_radial.ppm", 2, 0), 0);
}

TEST(Pattern, TriangularLayout) {
    EXPECT_EQ(max_difference(pigment_of(scene::PatternType::Triangular), "p_triangular.ppm", 7, 0), 0);
}

TEST(Pattern, CheckerListForm) {
    scene::Pigment p = pigment_of(scene::PatternType::Checker);
    p.colour_map = {{0, rgb(1, 0, 0)}, {1, rgb(0, 0, 1)}};
    p.list_form = true;
    EXPECT_EQ(max_difference(p, "p_checker.ppm", 6, 0), 0);
}

TEST(Pattern, GradientColourMapWithHardEdgeAndTransform) {
    scene::Pigment p = pigment_of(scene::PatternType::Gradient);
    p.pattern.kind = scene::pattern::Gradient{glm::normalize(glm::dvec3(1, 0, 1))};
    p.colour_map = {{0, rgb(1, 0, 0)}, {0.3, rgb(0, 1, 0)}, {0.3, rgb(0, 0, 1)}, {1, rgb(1, 1, 1)}};
    const glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.2, 0, 0.1)) *
                         glm::scale(glm::dmat4(1), glm::dvec3(1.5));
    p.pattern.steps.add_transform({m, glm::inverse(m)});
    EXPECT_LE(max_difference(p, "p_gradient.ppm", 4, 0), 1);
}

TEST(Pattern, OnionFrequencyPhaseAndSineWave) {
    scene::Pigment onion = pigment_of(scene::PatternType::Onion);
    onion.pattern.frequency = 2;
    onion.pattern.phase = 0.1;
    EXPECT_LE(max_difference(onion, "p_onion.ppm", 6, 0), 1);
    scene::Pigment sine = pigment_of(scene::PatternType::Gradient);
    sine.pattern.wave = scene::WaveType::Sine;
    EXPECT_LE(max_difference(sine, "p_sine.ppm", 4, 0), 1);
}

TEST(Pattern, BlendMapLookupRules) {
    const scene::ColourMap map = {{0.2, rgb(1, 0, 0)}, {0.5, rgb(0, 1, 0)}, {0.5, rgb(0, 0, 1)},
                                  {0.8, rgb(1, 1, 1)}};
    EXPECT_EQ(lookup_colour_map(map, 0.0), rgb(1, 0, 0));      // below the first entry
    EXPECT_EQ(lookup_colour_map(map, 0.9), rgb(1, 1, 1));      // above the last
    EXPECT_EQ(lookup_colour_map(map, 0.5), rgb(0, 1, 0));      // exact match: first equal entry
    // Keys and colours are single precision, as in POV.
    EXPECT_NEAR(lookup_colour_map(map, 0.35).r, 0.5, 1e-7);   // linear blend
    EXPECT_NEAR(lookup_colour_map(map, 0.65).b, 1.0, 1e-7);   // after the hard edge
    EXPECT_NEAR(lookup_colour_map(map, 0.65).r, 0.5, 1e-7);
    // POV's blend: the difference and the sum in float, the weight from float keys.
    const scene::ColourMap two = {{0.1, rgb(0.3, 0, 0)}, {0.7, rgb(0.9, 0, 0)}};
    const double w = (0.4 - double(0.1f)) / (double(0.7f) - double(0.1f));
    EXPECT_EQ(lookup_colour_map(two, 0.4).r, double(0.3f + float(w * double(0.9f - 0.3f))));
    EXPECT_EQ(lookup_colour_map(two, 0.7).r, double(0.9f));
}

// A pigment_map entry is evaluated at its parent's pattern point: the parent's scale carries
// over to the entry, which is not transformed itself.
TEST(Pattern, MapEntriesAreEvaluatedAtTheParentsPatternPoint) {
    auto child = std::make_shared<scene::Pigment>();
    child->pattern.kind = scene::pattern::Gradient{{0, 1, 0}};
    scene::Pigment parent;
    parent.pattern.kind = scene::pattern::Checker{};
    parent.pattern.steps.add_transform(
        {glm::scale(glm::dmat4(1.0), glm::dvec3(4.0)), glm::scale(glm::dmat4(1.0), glm::dvec3(0.25))});
    parent.pigment_map = {{0, child}, {1, child}};
    // World y = 2 is the parent's y = 0.5: the child's gradient reads 0.5 there, not 0 (2 mod 1).
    EXPECT_NEAR(evaluate_pigment(&parent, {0.5, 2, 0.5}).r, 0.5, 1e-7);
    EXPECT_EQ(pattern_point(parent.pattern, {0.5, 2, 0.5}), glm::dvec3(0.125, 0.5, 0.125));
    EXPECT_EQ(pattern_value_at(child->pattern, {0, 0.25, 0}), 0.25);
}

TEST(Pattern, DiscretePatternsIgnoreFrequency) {
    scene::Pattern p;
    p.kind = scene::make_pattern_kind(scene::PatternType::Checker);
    p.frequency = 3;
    EXPECT_EQ(pattern_value(p, {0.5, 0.5, 0.5}), 0.0);
    EXPECT_EQ(pattern_value(p, {1.5, 0.5, 0.5}), 1.0);
    EXPECT_TRUE(is_discrete(scene::PatternType::Hexagon));
    EXPECT_FALSE(is_discrete(scene::PatternType::Gradient));
}

}  // namespace
}  // namespace lumen::render::test

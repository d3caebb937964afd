// The pattern table's consumers in the renderer (discrete kinds, default maps, dispatch),
// the ordered steps, and the one blend-map lookup every map kind shares.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render/pattern.hpp"
#include "scene/texture.hpp"

namespace lumen::render::test {
namespace {

TEST(PatternTable, DiscreteKindsHaveADefaultMapEntryPerIndex) {
    for (const scene::PatternInfo& row : scene::kPatternTable) {
        EXPECT_EQ(is_discrete(row.type), row.entries > 0) << row.keyword;
        if (row.entries > 0)
            EXPECT_EQ(int(default_colour_map(row.type).size()), row.entries) << row.keyword;
        else
            EXPECT_FALSE(default_colour_map(row.type).empty()) << row.keyword;
    }
}

TEST(PatternTable, DispatchReachesEachKindsEvaluator) {
    scene::Pattern p;
    p.kind = scene::pattern::Gradient{{0, 1, 0}};
    EXPECT_DOUBLE_EQ(pattern_value(p, {0.9, 0.25, 0.9}), 0.25);
    p.kind = scene::pattern::Brick{};
    EXPECT_DOUBLE_EQ(pattern_value(p, {1, 1, 1}), 1.0);   // inside a brick
    EXPECT_DOUBLE_EQ(pattern_value(p, {1, 2.75, 1}), 0.0);  // in the mortar
    // povray's list form `square A, B, C, D`: A and B alternate along z at even x, D and C at
    // odd x (the values matter to normals, which difference them).
    p.kind = scene::make_pattern_kind(scene::PatternType::Square);
    EXPECT_DOUBLE_EQ(pattern_value(p, {0.5, 0, 0.5}), 0.0);
    EXPECT_DOUBLE_EQ(pattern_value(p, {0.5, 0, 1.5}), 1.0);
    EXPECT_DOUBLE_EQ(pattern_value(p, {1.5, 0, 0.5}), 3.0);
    EXPECT_DOUBLE_EQ(pattern_value(p, {1.5, 0, 1.5}), 2.0);
}

scene::Transform scaled(double s) {
    return {glm::scale(glm::dmat4(1.0), glm::dvec3(s)), glm::scale(glm::dmat4(1.0), glm::dvec3(1 / s))};
}
scene::Transform moved(double x) {
    return {glm::translate(glm::dmat4(1.0), {x, 0, 0}), glm::translate(glm::dmat4(1.0), {-x, 0, 0})};
}

// The steps act on the pattern in order, so a world point goes through them last to first:
// `scale 2 translate x` puts the pattern's x = 0.25 at world x = 1.5.
TEST(PatternTable, WorldPointsGoThroughTheStepsLastToFirst) {
    scene::Pattern p;
    p.kind = scene::pattern::Gradient{};
    p.steps.steps = {scaled(2), scene::warp::ClassicTurbulence{}, moved(1)};
    EXPECT_DOUBLE_EQ(pattern_value(p, {1.5, 0, 0}), 0.25);
    scene::PatternSteps composed;
    composed.add_transform(scaled(2));
    composed.add_transform(moved(1));
    ASSERT_EQ(composed.steps.size(), 1u);
    p.steps = composed;
    EXPECT_DOUBLE_EQ(pattern_value(p, {1.5, 0, 0}), 0.25);
}

// Below the first entry -> the first; above the last -> the last; an exact value -> the first
// entry with it; between -> the two neighbours and the upper one's weight.
template <class Map> void expect_lookups(const Map& map) {
    ASSERT_EQ(map.size(), 3u);
    const scene::BlendWeights below = blend_weights(map, -1.0), above = blend_weights(map, 2.0);
    EXPECT_EQ(below.lower, 0);
    EXPECT_EQ(below.upper_weight, 0);
    EXPECT_EQ(above.lower, 2);
    EXPECT_EQ(blend_weights(map, 0.5).lower, 1);
    EXPECT_EQ(blend_weights(map, 0.5).upper_weight, 0);
    const scene::BlendWeights mid = blend_weights(map, 0.75);
    EXPECT_EQ(mid.lower, 1);
    EXPECT_EQ(mid.upper, 2);
    EXPECT_DOUBLE_EQ(mid.upper_weight, 0.5);
}

TEST(BlendMap, OneLookupForEveryMapKind) {
    const scene::Colour c{};
    expect_lookups(scene::ColourMap{{0, c}, {0.5, c}, {1, c}});
    expect_lookups(scene::DensityMap{{0, c}, {0.5, c}, {1, c}});
    const auto pigment = std::make_shared<const scene::Pigment>();
    expect_lookups(scene::PigmentMap{{0, pigment}, {0.5, pigment}, {1, pigment}});
    const auto normal = std::make_shared<const scene::Normal>();
    expect_lookups(scene::NormalMap{{0, normal}, {0.5, normal}, {1, normal}});
    expect_lookups(scene::TextureMap{{0, {}}, {0.5, {}}, {1, {}}});
    expect_lookups(scene::SlopeMap{{0, {0, 1}}, {0.5, {1, 0}}, {1, {0, -1}}});
}

TEST(BlendMap, ListFormsAreMapsValuedByIndex) {
    const scene::Colour a{1, 0, 0, 0, 0}, b{0, 1, 0, 0, 0}, c{0, 0, 1, 0, 0};
    const scene::ColourMap hexagon{{0, a}, {1, b}, {2, c}};
    for (int i = 0; i < 3; ++i) EXPECT_EQ(blend_weights(hexagon, double(i)).lower, i);
    EXPECT_EQ(lookup_colour_map(hexagon, 1.0), b);
}

}  // namespace
}  // namespace lumen::render::test
